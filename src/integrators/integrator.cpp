#include "integrators/integrator.h"

#include <cmath>

#include "integrators/registry.h"

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
    const IntegratorInfo* info = findIntegrator(name);
    return info ? info->make() : nullptr;
}

}  // namespace lightpath
