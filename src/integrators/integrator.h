#pragma once
// What every integrator shares: the read-only render context, and the per-thread tracer state
// through which contributions reach the sink with their automaton state.
#include <memory>
#include <string_view>

#include "geometry/scene_geometry.h"
#include "integrators/contribution_sink.h"
#include "integrators/event_symbols.h"
#include "integrators/path_record.h"
#include "integrators/ray_counters.h"
#include "lights/emitters.h"
#include "lpe/automaton.h"
#include "math/ray.h"
#include "scene/scene.h"
#include "sampling/sampler.h"
#include "scene/scene_analysis.h"

namespace lightpath {

struct RenderContext {
    const Scene& scene;
    const SceneGeometry& geometry;
    const lpe::Automaton& automaton;
    const EventSymbols& symbols;
    const SceneAnalysis& analysis;
    const EmitterSet& emitters;
    int maxDepth = 5;  // Whitted: specular bounces after the first hit; path: scattering events
    // The outputs the user asked for. When every contribution is wanted (the beauty or `rest` is
    // written, or skipping is off) nothing may be skipped on their account.
    lpe::OutputMask requested = 0;
    bool keepAllPaths = true;
    // Off (`--no-skip`): evaluate every term and trace every ray, even those that cannot add
    // anything, so tests and lectures can compare against the work skipping saves.
    bool skipEnabled = true;
};

// One worker's view of a render: the shared context plus its own sink, counters and path stack.
class Tracer {
public:
    Tracer(const RenderContext& context, ContributionSink& sink, RayCounters& counters)
        : context(context), counters(counters), sink_(sink) {}

    // Records `surface` then `light` after `state`, and hands `value` to the sink with the outputs
    // that accept the resulting path. Non-finite values are counted and dropped, never stored.
    void emit(lpe::Automaton::State state, const PathEvent& surface, lpe::Automaton::Symbol surfaceSymbol,
              const PathEvent& light, lpe::Automaton::Symbol lightSymbol, const Rgb& value);
    // The same for a path that ends without a surface event (background, emitter hit directly).
    void emit(lpe::Automaton::State state, const PathEvent& light, lpe::Automaton::Symbol lightSymbol,
              const Rgb& value);

    // Would a contribution accepted by `accepted` reach a requested output?
    bool wants(lpe::OutputMask accepted) const {
        return context.keepAllPaths || (accepted & context.requested) != 0;
    }
    // Can a branch in `state` still reach a requested output (DESIGN.md: dead states stop)?
    bool alive(lpe::Automaton::State state) const {
        return context.keepAllPaths || !context.automaton.isDead(state, context.requested);
    }

    const RenderContext& context;
    RayCounters& counters;
    PathRecord path;
    Sampler* sampler = nullptr;  // the current pixel sample's random numbers

private:
    ContributionSink& sink_;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Traces one camera ray; the camera event is already on the tracer's path and `state` is the
    // automaton state after it.
    virtual void traceCameraRay(const Ray& ray, lpe::Automaton::State state, Tracer& tracer) const = 0;
};

// "raycast", "whitted" or "path"; nullptr for an unknown name.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);

}  // namespace lightpath
