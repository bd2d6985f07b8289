#pragma once
// Photons and the maps that hold them (Jensen 2001, "Realistic Image Synthesis Using Photon
// Mapping", ch. 5): photons are shot from the lights with Light::sampleEmission, each carrying its
// flux and the events of its path from the light, and stored at diffuse and glossy hits in a hash
// grid whose cells are a search diameter wide, so a lookup within the radius visits at most eight
// cells and allocates nothing.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/types.h"
#include "transport/path_event.h"

namespace lightpath {

struct RenderContext;

struct Photon {
    Vec3 position{0.0f};
    Vec3 wi{0.0f};      // unit, back towards where the photon came from
    Vec3 normal{0.0f};  // the surface's shading normal, turned to the side the photon arrived on
    Rgb power{0.0f};    // flux, already divided by the number of photons shot
    // Its path from the light: PhotonMap::events()[history] is the light's event, the next
    // `bounces` are its scattering events in the order they happened (the hit it is stored at,
    // whose event the eye's side names, is not among them).
    std::uint32_t history = 0;
    std::uint8_t bounces = 0;
};

class PhotonMap {
public:
    // Takes the photons and their histories and sorts them into cells of width 2 `radius`, hashed
    // into 2 `shot` buckets (at least two per photon): the photons shot, not those kept, so a map
    // that keeps fewer (the requested outputs filter them) visits the rest in the same order.
    PhotonMap(std::vector<Photon> photons, std::vector<PathEvent> events, float radius, std::uint64_t shot);
    PhotonMap() = default;

    float radius() const { return radius_; }
    std::size_t size() const { return photons_.size(); }
    std::span<const Photon> photons() const { return photons_; }
    std::span<const PathEvent> events() const { return events_; }
    std::size_t bytes() const;

    // Calls visit(photon, index, distance2) for every photon closer to `point` than radius().
    template <class Visit>
    void forEachWithin(const Vec3& point, const Visit& visit) const {
        if (photons_.empty()) return;
        const float r2 = radius_ * radius_;
        std::array<std::uint32_t, 8> buckets{};
        int count = 0;
        const glm::ivec3 lo = cellOf(point - Vec3(radius_)), hi = cellOf(point + Vec3(radius_));
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    // Two cells may share a bucket: each bucket is visited once.
                    const std::uint32_t b = bucketOf({x, y, z});
                    bool seen = false;
                    for (int i = 0; i < count; ++i) seen = seen || buckets[i] == b;
                    if (!seen) buckets[count++] = b;
                }
        for (int i = 0; i < count; ++i) {
            for (std::uint32_t p = bucketStart_[buckets[i]]; p < bucketStart_[buckets[i] + 1]; ++p) {
                const Vec3 d = photons_[p].position - point;
                const float distance2 = glm::dot(d, d);
                if (distance2 < r2) visit(photons_[p], p, distance2);
            }
        }
    }

private:
    glm::ivec3 cellOf(const Vec3& p) const { return glm::ivec3(glm::floor(p / cellSize_)); }
    std::uint32_t bucketOf(const glm::ivec3& c) const {
        // Teschner et al. 2003's spatial hash.
        const auto h = (std::uint32_t(c.x) * 73856093u) ^ (std::uint32_t(c.y) * 19349663u) ^ (std::uint32_t(c.z) * 83492791u);
        return h & (bucketCount_ - 1);
    }

    std::vector<Photon> photons_;  // sorted by bucket
    std::vector<PathEvent> events_;
    std::vector<std::uint32_t> bucketStart_;  // bucketCount_ + 1 offsets into photons_
    std::uint32_t bucketCount_ = 1;
    float radius_ = 0.0f, cellSize_ = 1.0f;
};

// What one photon pass shot and kept.
struct PhotonPassCounts {
    std::uint64_t shot = 0;
    std::uint64_t caustic = 0;  // stored after L S+
    std::uint64_t global = 0;   // stored after any other path of at least one scattering event
};

// The photons of `count` paths from the lights, the light chosen by power (LightSet::chooseEmitter),
// path i seeded by `seed` and i alone, so the result is the same on any number of threads. A photon
// is kept at every hit with a smooth lobe after at least one scattering event (direct light is next-
// event estimation's), while 1 + its events <= maxDepth, and only when `keep`(its light-side events
// as PathEvents from the light, and the merge's candidate events) says some requested output may accept
// a path ending in them.
struct PhotonSet {
    std::vector<Photon> caustic, global;
    std::vector<PathEvent> causticEvents, globalEvents;
    PhotonPassCounts counts;
};
// Whether a photon's light-side events (the light first) may still end an accepted path whose
// merge vertex is one of `merges` (the events of the smooth lobes where it is stored: the eye's
// side reads it through one of them).
using PhotonFilter = bool (*)(const void* state, std::span<const PathEvent> lightSide, std::span<const PathEvent> merges);
PhotonSet shootPhotons(const RenderContext& context, std::uint64_t count, std::uint64_t seed,
                       PhotonFilter keep = nullptr, const void* keepState = nullptr);

}  // namespace lightpath
