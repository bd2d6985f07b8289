#pragma once
#include <cstdint>

namespace lightpath {

// What a render cast and what it skipped, and why (`--stats`). Kept per worker thread and summed.
// Aligned to a cache line: the workers' counters sit side by side in one vector and are bumped
// for every ray, and two threads writing one line would pass it back and forth between cores
// (false sharing: Whitted scaled 1.2-1.3x on two cores with them packed).
struct alignas(64) RayCounters {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflection = 0;
    std::uint64_t refraction = 0;
    std::uint64_t volume = 0;  // rays scattered at a point inside a medium (a V event)

    // Work in participating media (`--stats`; all zero in a scene without media, which does none).
    std::uint64_t mediumSegments = 0;   // ray segments through a medium: a free flight or single scattering along each
    std::uint64_t mediumShadow = 0;     // shadow rays attenuated by a medium's transmittance
    std::uint64_t singleScattering = 0; // ray casting's and Whitted's single-scattering points lit (E S* V L)

    // Skipped rays by reason.
    std::uint64_t cameraDead = 0;          // no requested output accepts any path from here
    std::uint64_t shadowBehind = 0;        // light behind the surface: N.(b - p) <= 0
    std::uint64_t shadowZero = 0;          // the light's attenuated diffuse and highlight terms are 0
    std::uint64_t shadowDead = 0;          // no requested output accepts light from this light here
    std::uint64_t reflectionDead = 0;      // automaton state dead after the mirror event
    std::uint64_t refractionDead = 0;      // automaton state dead after the refraction event
    std::uint64_t volumeDead = 0;          // automaton state dead after a volume scattering

    // Glossy lobes' terms (the highlight's ks (H.N)^n) evaluated, and skipped because the
    // material's glossy lobe scatters nothing (ks = 0).
    std::uint64_t glossyEvaluated = 0;
    std::uint64_t glossyAbsent = 0;

    std::uint64_t nonFinite = 0;  // contributions dropped because they were NaN or infinite
    std::uint64_t eventOverflow = 0;  // events refused because the path's event stack was full

    std::uint64_t total() const { return camera + shadow + reflection + refraction + volume; }

    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        refraction += o.refraction;
        volume += o.volume;
        mediumSegments += o.mediumSegments;
        mediumShadow += o.mediumShadow;
        singleScattering += o.singleScattering;
        cameraDead += o.cameraDead;
        shadowBehind += o.shadowBehind;
        shadowZero += o.shadowZero;
        shadowDead += o.shadowDead;
        reflectionDead += o.reflectionDead;
        refractionDead += o.refractionDead;
        volumeDead += o.volumeDead;
        glossyEvaluated += o.glossyEvaluated;
        glossyAbsent += o.glossyAbsent;
        nonFinite += o.nonFinite;
        eventOverflow += o.eventOverflow;
        return *this;
    }
};

}  // namespace lightpath
