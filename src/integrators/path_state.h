#pragma once
// The one type through which integrators meet the LPE automaton (docs/design.md). It owns the
// events of the path being traced and the automaton state after each, so "step, check dead,
// record, emit" is one call: push() refuses an event after which no requested output can accept,
// emit() classifies a finished path and hands it to the sink. It also carries what a worker needs
// per path: its counters and its current sample's random numbers.
#include <array>
#include <cmath>
#include <span>
#include <string>

#include "integrators/contribution_sink.h"
#include "integrators/event_symbols.h"
#include "integrators/lobe_step_table.h"
#include "integrators/path_record.h"
#include "integrators/ray_counters.h"
#include "lpe/automaton.h"
#include "math/types.h"
#include "sampling/sampler.h"

namespace lightpath {

struct RenderContext;

class PathState {
public:
    PathState(const RenderContext& context, ContributionSink& sink, RayCounters& counters);

    // Appends `event` and advances the automaton; false, and nothing appended, when no requested
    // output can accept any path that continues from here (a dead state: the branch stops), or
    // when the event stack is full (counted in RayCounters::eventOverflow; no shipped integrator
    // gets there, since maxDepth <= kMaxDepth).
    bool push(const PathEvent& event);
    void pop();
    std::size_t size() const { return events_.size(); }
    const PathRecord& events() const { return events_; }
    lpe::Automaton::State state() const { return states_[events_.size()]; }
    // Names the vertex this path has reached, for per-vertex random numbers.
    std::uint64_t key() const { return events_.key(); }

    // Would a path ending now in `light` (after `surface`) reach a requested output?
    bool wants(const PathEvent& light) const { return wanted(acceptsAfter(state(), light)); }
    bool wants(const PathEvent& surface, const PathEvent& light) const {
        return wanted(acceptsAfter(step(state(), surface), light));
    }
    // The same in two steps (a medium point's light samples): the state after `surface`, then the
    // outputs accepting a path that ends from there in `light`. A surface's smooth lobes read
    // theirs from the per-render table instead (acceptsThrough, below).
    lpe::Automaton::State stateAfter(const PathEvent& surface) const { return step(state(), surface); }
    lpe::OutputMask acceptsAfter(lpe::Automaton::State state, const PathEvent& light) const {
        return automaton_.accepts(step(state, light));
    }
    bool wanted(lpe::OutputMask accepted) const { return keepAllPaths_ || (accepted & requested_) != 0; }

    // A shading point's smooth lobes seen from the current state: the lobes of a hit on `object`
    // and where the path stands before scattering there. Its ambient term and light samples ask
    // acceptsThrough() for the outputs each lobe's term reaches.
    struct SurfaceLobes {
        const SmoothLobes& lobes;
        lpe::Automaton::State state;
        std::uint32_t shadingClass;
    };
    SurfaceLobes surfaceLobes(std::uint32_t object) const {
        const std::uint32_t shadingClass = lobeSteps_.classOf(object);
        return {lobeSteps_.lobes(shadingClass), state(), shadingClass};
    }
    LightColumn lightColumn(const PathEvent& light) const { return lobeSteps_.columnOf(light); }
    LightColumn ambientColumn() const { return lobeSteps_.ambient(); }
    // accepted[slot]: the outputs accepting a path that scatters through each smooth lobe of `at`
    // and ends in `light`. Read from the per-render table (lobe_step_table.h), or, where it has no
    // entry, stepped into `scratch` as the table was made: the same answer either way.
    const lpe::OutputMask* acceptsThrough(const SurfaceLobes& at, LightColumn light,
                                          lpe::OutputMask (&scratch)[kMaxLobes]) const {
        if (light.column >= 0) [[likely]]
            return lobeSteps_.accepts(at.state, light.column, at.shadingClass);
        for (int slot = 0; slot < at.lobes.count; ++slot)
            scratch[slot] = automaton_.accepts(automaton_.step(automaton_.step(at.state, at.lobes.symbol[slot]), light.symbol));
        return scratch;
    }
    // Bit l set: accepted[l] reaches a requested output, for the `count` lobes of a term. All of
    // them when every path is kept (the beauty or `rest` is written): no lookup then.
    unsigned wantedLobes(const lpe::OutputMask* accepted, int count) const {
        static_assert(kMaxLobes <= 32);
        if (keepAllPaths_) return (1u << count) - 1u;
        unsigned wanted = 0;
        for (int l = 0; l < count; ++l) wanted |= unsigned{(accepted[l] & requested_) != 0} << l;
        return wanted;
    }
    // Ends the path in `light` (after `surface`) with radiance `value`. Non-finite values are
    // counted and dropped, never stored.
    void emit(const PathEvent& light, const Rgb& value, std::span<const TermFactor> factors = {});
    void emit(const PathEvent& surface, const PathEvent& light, const Rgb& value,
              std::span<const TermFactor> factors = {});
    // With `accepted` = acceptsAfter(stateAfter(surface), light), already known to the caller.
    // Inline up to the sink: every light sample's and ambient term's contribution comes here
    // (with the light's symbol looked up once, -2.3% of a Whitted render's non-traversal
    // instructions; docs/performance.md, Shading). `explain` takes the call below.
    void emitAccepted(const PathEvent& surface, const PathEvent& light, const Rgb& value, lpe::OutputMask accepted,
                      std::span<const TermFactor> factors = {}) {
        // Only `explain`'s log reads the finished path: the events are recorded for it alone.
        if (!sink_.explaining()) [[likely]] {
            addAccepted(value, accepted);
            return;
        }
        if (finite(value)) emitExplained(surface, light, value, accepted, factors);
    }
    // emitAccepted() where the caller knows `explain` is not logging: the surface and light
    // events are not needed, so not even built (about 15 instructions a term; docs/performance.md,
    // Shading share, fourth pass).
    void addAccepted(const Rgb& value, lpe::OutputMask accepted) {
        if (finite(value)) sink_.add(value, accepted, events_);
    }
    // `explain` only: the term through `surface` from `light` added nothing, for `reason`.
    bool explaining() const { return sink_.explaining(); }
    void reject(const PathEvent& surface, const PathEvent& light, std::string reason);
    // The same for light tracing: the finished path's value goes to pixel (x, y) of the image.
    void splat(int x, int y, const PathEvent& light, const Rgb& value);
    // Bidirectional path tracing names the strategy (s, t) of what it emits next, for `explain`.
    void setStrategy(int s, int t) { sink_.setStrategy(s, t); }

    const RenderContext& context;
    RayCounters& counters;
    Sampler* sampler = nullptr;  // the current pixel sample's random numbers
    int sampleIndex = 0;         // which of its pixel's samples this is (sppm's pass)

private:
    // Inline, as the two lookups they are: every light sample of every shading point asks them.
    lpe::Automaton::State step(lpe::Automaton::State state, const PathEvent& event) const {
        return automaton_.step(state, symbols_(event));
    }
    bool finite(const Rgb& value) {
        if (std::isfinite(value.r) && std::isfinite(value.g) && std::isfinite(value.b)) [[likely]]
            return true;
        ++counters.nonFinite;
        return false;
    }
    void emitExplained(const PathEvent& surface, const PathEvent& light, const Rgb& value, lpe::OutputMask accepted,
                       std::span<const TermFactor> factors);

    // The context's automaton and requested outputs, kept here so the lookups above need no
    // RenderContext (integrator.h includes this header).
    const lpe::Automaton& automaton_;
    const EventSymbols& symbols_;
    const LobeStepTable& lobeSteps_;
    lpe::OutputMask requested_;
    bool keepAllPaths_;
    ContributionSink& sink_;
    PathRecord events_;
    std::array<lpe::Automaton::State, kMaxPathEvents + 1> states_{};
};

}  // namespace lightpath
