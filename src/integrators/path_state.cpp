#include "integrators/path_state.h"

#include <cmath>

#include "integrators/integrator.h"
#include "util/hot_path.h"

namespace lightpath {

namespace {
constexpr std::size_t kEmitEvents = 2;  // emitAccepted() and reject() record a surface and a light
}  // namespace

PathState::PathState(const RenderContext& context, ContributionSink& sink, RayCounters& counters)
    : context(context), counters(counters), automaton_(context.automaton), symbols_(context.symbols), lobeSteps_(context.lobeSteps),
      requested_(context.requested), keepAllPaths_(context.keepAllPaths), sink_(sink) {
    states_[0] = context.automaton.start();
}

LIGHTPATH_HOT_PATH
bool PathState::push(const PathEvent& event) {
    // Room is kept for the surface and light that emit() records after the last push. Checked in
    // Release too: one compare, against writing past the end of a std::array.
    if (events_.size() + 1 + kEmitEvents > kMaxPathEvents) [[unlikely]] {
        ++counters.eventOverflow;
        return false;
    }
    const lpe::Automaton::State next = step(state(), event);
    if (!keepAllPaths_ && automaton_.isDead(next, requested_)) return false;
    events_.push(event);
    states_[events_.size()] = next;
    return true;
}

LIGHTPATH_HOT_PATH
void PathState::pop() { events_.pop(); }

void PathState::emit(const PathEvent& light, const Rgb& value, std::span<const TermFactor> factors) {
    if (!finite(value)) return;
    const lpe::OutputMask accepted = acceptsAfter(state(), light);
    if (!sink_.explaining()) {  // only `explain`'s log reads the finished path
        sink_.add(value, accepted, events_);
        return;
    }
    events_.push(light);
    sink_.add(value, accepted, events_, factors);
    events_.pop();
}

void PathState::emit(const PathEvent& surface, const PathEvent& light, const Rgb& value,
                     std::span<const TermFactor> factors) {
    emitAccepted(surface, light, value, acceptsAfter(step(state(), surface), light), factors);
}

void PathState::emitExplained(const PathEvent& surface, const PathEvent& light, const Rgb& value,
                              lpe::OutputMask accepted, std::span<const TermFactor> factors) {
    events_.push(surface);
    events_.push(light);
    sink_.add(value, accepted, events_, factors);
    events_.pop();
    events_.pop();
}

void PathState::reject(const PathEvent& surface, const PathEvent& light, std::string reason) {
    events_.push(surface);
    events_.push(light);
    sink_.reject(events_, std::move(reason));
    events_.pop();
    events_.pop();
}

void PathState::splat(int x, int y, const PathEvent& light, const Rgb& value) {
    if (!finite(value)) return;
    const lpe::OutputMask accepted = acceptsAfter(state(), light);
    events_.push(light);
    sink_.splat(x, y, value, accepted, events_);
    events_.pop();
}

}  // namespace lightpath
