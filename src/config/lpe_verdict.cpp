#include "config/lpe_verdict.h"

#include <algorithm>
#include <utility>

#include "config/lpe_feasibility.h"
#include "config/scene_events.h"
#include "film/aov_presets.h"
#include "integrators/event_symbols.h"
#include "lpe/analysis.h"
#include "scene/spelling.h"

namespace lightpath {
namespace {

// The languages an expression must share a path with: what lightpath renders (with `volumes`, as
// it would with media) and, when one is named, what the integrator follows.
std::vector<std::string> languages(const std::string& expression, const IntegratorInfo* integrator, bool volumes) {
    std::vector<std::string> all = {expression, volumes ? kPathsWithVolumes : kRenderedPaths};
    if (integrator) all.emplace_back(integrator->pathLanguage);
    return all;
}

// The scene's label placement with each label of `aov` the scene lacks placed on no event, and the
// message naming the first of those ("" when the scene knows them all).
std::pair<lpe::LabelPlacement, std::string> placeLabels(const lpe::NamedExpression& aov, const Scene& scene) {
    const std::vector<std::string> known = sceneLabels(scene);
    lpe::LabelPlacement placement = labelPlacement(scene);
    std::string unknown;
    const lpe::Automaton automaton = lpe::Automaton::compile({{aov.name, aov.expression}});
    for (const std::string& label : automaton.labels()) {
        if (std::binary_search(known.begin(), known.end(), label)) continue;
        placement[label] = {};
        if (unknown.empty()) unknown = unknownNameMessage("label", label, known, ListKnown::withoutSuggestion);
    }
    return {placement, unknown};
}

}  // namespace

bool isPresetMember(const lpe::NamedExpression& aov, const Scene* scene) {
    for (const AovPreset* preset : aovPresets())
        for (const auto& member : preset->expressions(scene))
            if (member.name == aov.name && member.expression == aov.expression) return true;
    return false;
}

Judgement judgeExpression(const lpe::NamedExpression& aov, const IntegratorInfo* integrator, const Scene* scene) {
    const std::string& expression = aov.expression;
    // Never, in any scene: no path of the integrator, volumes let in where it renders media, has it.
    if (!lpe::haveCommonPath(languages(expression, integrator, !integrator || integrator->rendersMedia))) {
        if (!lpe::haveCommonPath(languages(expression, nullptr, true))) return {Verdict::Refused, whyNeverRendered(expression)};
        const std::string why = *whyNeverFilled(expression, *integrator);
        const bool member = isPresetMember(aov, scene);
        return {member ? Verdict::PresetBlack : Verdict::Refused, member ? std::string(integrator->limitation) : why};
    }
    if (!lpe::haveCommonPath(languages(expression, integrator, false))) {
        // Volume events occur only where a scene has media and the integrator renders them (its
        // refusal of the others is RenderConfig::judge's); there the labels decide.
        const bool scattering = scene && std::any_of(scene->media.begin(), scene->media.end(),
                                                     [](const MediumSlot& m) { return m->scatters(); });
        const bool volumesHere = scene && integrator && integrator->rendersMedia && scattering;
        if (!volumesHere) {
            const std::string why = "it needs a volume event (V): only a scene with [media] fills it, under an "
                                    "integrator that renders media (" + mediaRenderers() + ")";
            // Media that only absorb (a tinted glass's inside) make no V event either.
            const bool absorbing = scene && !scene->media.empty() && !scattering;
            const std::string lack = absorbing ? "no medium that scatters (its media only absorb)" : "no medium ([media])";
            if (!isPresetMember(aov, scene)) return {Verdict::BlackHere, absorbing ? "in this scene " + lack : why};
            // A preset's volume AOV (classes') is written black without a word, as its other AOVs are.
            const bool sceneLacks = scene && !scattering;
            return {Verdict::PresetBlack, sceneLacks ? "in this scene " + lack : why, sceneLacks ? lack : ""};
        }
        // A label that labels nothing here (a misspelt medium) is on no event, as for surfaces below.
        auto [placement, unknown] = placeLabels(aov, *scene);
        if (lpe::haveCommonPath(languages(expression, integrator, true), placement))
            return {Verdict::Fillable, unknown.empty() ? "" : unknown + ": it labels nothing in this scene"};
        if (!unknown.empty()) return {Verdict::BlackHere, "this scene has no " + unknown.substr(std::string("unknown ").size())};
        return {Verdict::BlackHere, "no path of " + std::string(integrator->name) +
                                        " in this scene carries these labels where the expression needs them"};
    }
    if (!scene) return {};

    // In this scene: what its materials scatter by and its lights and surfaces emit. Black here with
    // the cause and a fix, as a label the scene lacks is: another scene fills it.
    const auto blackForWantOf = [&](const std::string& lack) {
        return Judgement{isPresetMember(aov, scene) ? Verdict::PresetBlack : Verdict::BlackHere, "in this scene " + lack, lack};
    };
    if (auto lack = whyNotInScene(expression, languages(expression, integrator, false), *scene)) return blackForWantOf(*lack);

    // In this scene: a label it names that labels nothing here is on no event at all.
    auto [placement, unknown] = placeLabels(aov, *scene);
    const bool fillable = lpe::haveCommonPath(languages(expression, integrator, false), placement);
    if (fillable) {
        // On the events each labelled object and light produces (a mirror named by a floor's label).
        if (auto lack = whyNotOnItsLabels(expression, languages(expression, integrator, false), *scene))
            return blackForWantOf(*lack);
        return {Verdict::Fillable, unknown.empty() ? "" : unknown + ": it labels nothing in this scene"};
    }
    if (!unknown.empty()) return {Verdict::BlackHere, "this scene has no " + unknown.substr(std::string("unknown ").size())};
    const IntegratorInfo& language = integrator ? *integrator : *findIntegrator("path");
    return {Verdict::BlackHere, whyNeverFilled(expression, language, scene).value_or("no path of this scene carries its labels")};
}

const Judgement& Judge::operator()(const lpe::NamedExpression& aov) const {
    const auto key = std::make_pair(aov.name, aov.expression);
    const auto found = judged_.find(key);
    if (found != judged_.end()) return found->second;
    return judged_.emplace(key, judgeExpression(aov, integrator_, scene_)).first->second;
}

std::string refusalMessage(const lpe::NamedExpression& aov, const IntegratorInfo* integrator, const std::string& reason) {
    const std::string under = integrator ? "under --integrator " + std::string(integrator->name) : "under any integrator";
    return "'" + aov.expression + "' can never match " + under + ": " + reason;
}

std::string warningMessage(const lpe::NamedExpression& aov, const Judgement& judgement) {
    if (judgement.verdict == Verdict::Fillable) return "--lpe " + aov.name + ": " + judgement.reason;
    return "AOV " + aov.name + " (" + aov.expression + ") stays black: " + judgement.reason;
}

std::vector<BlackAov> blackPresetAovs(const std::vector<lpe::NamedExpression>& set, const Judge& judge) {
    std::vector<BlackAov> black;
    for (const auto& aov : set) {
        const Judgement& judgement = judge(aov);
        if (judgement.verdict != Verdict::PresetBlack) continue;
        // Black for want of something in the scene, or whatever the scene, under this integrator.
        const bool inThisScene = !judgement.sceneLacks.empty();
        black.push_back({aov.name, inThisScene ? judgement.sceneLacks : judgement.reason, inThisScene});
    }
    return black;
}

}  // namespace lightpath
