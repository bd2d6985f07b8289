#include "integrators/integrator.h"

#include <cmath>

#include "integrators/path.h"
#include "integrators/raycast.h"
#include "integrators/whitted.h"

namespace lightpath {
namespace {

bool isFinite(const Rgb& v) { return std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b); }

}  // namespace

void Tracer::emit(lpe::Automaton::State state, const PathEvent& surface,
                  lpe::Automaton::Symbol surfaceSymbol, const PathEvent& light,
                  lpe::Automaton::Symbol lightSymbol, const Rgb& value) {
    path.push(surface);
    emit(context.automaton.step(state, surfaceSymbol), light, lightSymbol, value);
    path.pop();
}

void Tracer::emit(lpe::Automaton::State state, const PathEvent& light,
                  lpe::Automaton::Symbol lightSymbol, const Rgb& value) {
    if (!isFinite(value)) {
        ++counters.nonFinite;
        return;
    }
    path.push(light);
    sink_.add(value, context.automaton.accepts(context.automaton.step(state, lightSymbol)), path);
    path.pop();
}

std::unique_ptr<Integrator> makeIntegrator(std::string_view name) {
    if (name == "raycast") return std::make_unique<RaycastIntegrator>();
    if (name == "whitted") return std::make_unique<WhittedIntegrator>();
    if (name == "path") return std::make_unique<PathIntegrator>();
    return nullptr;
}

}  // namespace lightpath
