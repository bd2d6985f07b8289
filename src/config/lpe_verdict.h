#pragma once
// The one judge of an AOV expression. Every command that takes expressions asks it, so they accept
// and refuse the same ones for the same integrator: render and explain (RenderConfig::buildAovSet),
// serve (serve::applySettings, before a job is prepared), lpe check and lpe match --integrator.
//
//   refused      no path of the integrator matches it in any scene (lpe_feasibility.h says why);
//   black here   it could match, but not in this scene (no material scatters by an event it
//                needs, no emitter of the kind it ends at: config/scene_events.h; a label the
//                scene lacks or places elsewhere) or it needs a volume event in a scene without media:
//                rendered black, with one short warning;
//   preset black an AOV of a preset (`classes`, `taxonomy`, by name and expression; given the
//                scene, `lights` too) that this integrator, or this scene's events, cannot fill: written black so the preset still sums to the beauty, and
//                said in --stats and the EXR header, never as a warning (docs/lpe.md);
//   fillable     otherwise; a label the scene lacks still gets a warning (a typo in [^'kee']).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "integrators/registry.h"
#include "lpe/automaton.h"
#include "scene/scene.h"

namespace lightpath {

enum class Verdict { Fillable, BlackHere, PresetBlack, Refused };

struct Judgement {
    Verdict verdict = Verdict::Fillable;
    // Refused, BlackHere, PresetBlack: why; Fillable: a warning about the scene's labels, or empty.
    std::string reason;
    // BlackHere, PresetBlack for want of something in this scene: that lack alone (`reason` is
    // "in this scene " and it); empty otherwise.
    std::string sceneLacks;
};

// `integrator` null: every integrator (refused only when none can fill it); `scene` null: judged
// without a scene, which can only refuse, never find an AOV black in this scene (volumes aside).
// Throws lpe::SyntaxError.
Judgement judgeExpression(const lpe::NamedExpression& aov, const IntegratorInfo* integrator,
                          const Scene* scene = nullptr);

// Judges the AOVs of one render, each once whoever asks: the refusals and warnings before it, its
// black preset members, the empty-AOV warnings after it (each judgement is tens of automaton
// searches). Not thread-safe; `integrator` and `scene` must outlive it.
class Judge {
public:
    Judge(const IntegratorInfo* integrator, const Scene* scene) : integrator_(integrator), scene_(scene) {}
    const Judgement& operator()(const lpe::NamedExpression& aov) const;
    const IntegratorInfo* integrator() const { return integrator_; }

private:
    const IntegratorInfo* integrator_;
    const Scene* scene_;
    mutable std::map<std::pair<std::string, std::string>, Judgement> judged_;  // by (name, expression)
};

// Is `aov` a member of a preset (same name and expression)? The presets made from a scene
// (`lights`) only when `scene` is given.
bool isPresetMember(const lpe::NamedExpression& aov, const Scene* scene = nullptr);

// "'E.*L'key'' can never match under --integrator whitted: <reason>": the refusal every command
// prints after the expression's name ("--lpe k: ", "lpe check: k: ").
std::string refusalMessage(const lpe::NamedExpression& aov, const IntegratorInfo* integrator, const std::string& reason);
// "AOV k (EXPR) stays black: <reason>" for BlackHere, "--lpe k: <reason>" for a Fillable warning.
std::string warningMessage(const lpe::NamedExpression& aov, const Judgement& judgement);

// The preset AOVs of `set` that `integrator` (in `scene`, if given) cannot fill, each with the
// integrator's limitation or what the scene lacks: for --stats and the EXR header.
struct BlackAov {
    std::string name;
    std::string reason;
    bool inThisScene = false;  // the integrator could fill it, but not with this scene's events
};
std::vector<BlackAov> blackPresetAovs(const std::vector<lpe::NamedExpression>& set, const Judge& judge);

}  // namespace lightpath
