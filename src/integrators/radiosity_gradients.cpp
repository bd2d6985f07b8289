#include "integrators/radiosity_gradients.h"

#include <algorithm>
#include <cmath>

#include "sampling/warp.h"

namespace lightpath {
namespace {

// The least-squares system is taken as undetermined when its matrix's determinant is below this
// fraction of its trace squared (its neighbours' offsets nearly on one line: a gradient across
// that line would be noise).
constexpr float kWellPosed = 1e-3f;

}  // namespace

PatchGradients::PatchGradients(const RadiosityMesh& mesh) {
    const auto& patches = mesh.patches();
    const auto& clusters = mesh.clusters();
    patchCount_ = patches.size();
    const auto [aroundStart, around] = mesh.patchesAroundVertices();
    const auto centroid = [&](const RadiosityPatch& p) { return (p.a + p.b + p.c) / 3.0f; };
    std::vector<std::uint32_t> found;
    for (std::uint32_t p = 0; p < patches.size(); ++p) {
        const RadiosityPatch& patch = patches[p];
        if (patch.vertexCount != 3 || clusters[patch.cluster].memberCount != 1) continue;
        found.clear();
        for (int v = 0; v < 3; ++v)
            for (std::uint32_t i = aroundStart[patch.vertices[v]]; i < aroundStart[patch.vertices[v] + 1]; ++i)
                if (around[i] != p && patches[around[i]].vertexCount == 3) found.push_back(around[i]);
        std::sort(found.begin(), found.end());
        found.erase(std::unique(found.begin(), found.end()), found.end());
        if (found.size() < 2) continue;
        const Frame frame(patch.normal);
        const Vec3 centre = centroid(patch);
        const auto inPlane = [&](const Vec3& x) {
            const Vec3 d = x - centre;
            return Vec2{glm::dot(d, frame.s), glm::dot(d, frame.t)};
        };
        patches_.push_back({p, patch.cluster, {inPlane(patch.a), inPlane(patch.b), inPlane(patch.c)}});
        for (std::uint32_t q : found) neighbours_.push_back({patches[q].cluster, inPlane(centroid(patches[q]))});
        patchStart_.push_back(static_cast<std::uint32_t>(neighbours_.size()));
    }
}

void PatchGradients::fit(std::span<const Rgb> values, std::vector<std::array<Rgb, 3>>& corners,
                         std::vector<std::uint8_t>& fitted) const {
    corners.assign(2 * patchCount_, std::array<Rgb, 3>{});
    fitted.assign(2 * patchCount_, 0);
    for (std::size_t i = 0; i < patches_.size(); ++i) {
        const Fittable& patch = patches_[i];
        for (std::uint32_t side = 0; side < 2; ++side) {
            const Rgb b = values[2 * patch.cluster + side];
            const std::size_t at = 2 * std::size_t(patch.patch) + side;
            if (isBlack(b)) {
                fitted[at] = 1;  // no light here: the gather reads 0, as the scaled plane would
                continue;
            }
            // Minimise sum_j w_j (B_j - B - g . d_j)^2, w_j = 1 / |d_j|^2: the normal equations
            // M g = r with M = sum w d d^T, r = sum w d (B_j - B), per channel.
            float mxx = 0.0f, mxy = 0.0f, myy = 0.0f;
            Rgb rx{0.0f}, ry{0.0f};
            for (std::uint32_t n = patchStart_[i]; n < patchStart_[i + 1]; ++n) {
                const Neighbour& q = neighbours_[n];
                const Rgb bq = values[2 * q.cluster + side];
                if (isBlack(bq)) continue;
                const float w = 1.0f / glm::dot(q.offset, q.offset);
                mxx += w * q.offset.x * q.offset.x;
                mxy += w * q.offset.x * q.offset.y;
                myy += w * q.offset.y * q.offset.y;
                rx += (w * q.offset.x) * (bq - b);
                ry += (w * q.offset.y) * (bq - b);
            }
            const float det = mxx * myy - mxy * mxy;
            const float trace = mxx + myy;
            if (!(det > kWellPosed * trace * trace)) continue;
            const Rgb gx = (myy * rx - mxy * ry) / det, gy = (mxx * ry - mxy * rx) / det;
            std::array<Rgb, 3>& out = corners[at];
            for (int c = 0; c < 3; ++c) {
                // The corners' departures from B; scaled down (the same factor at every corner, so
                // the centroid's value and the mean stay B) until the lowest corner is 0.
                std::array<float, 3> step{};
                float lowest = 0.0f;
                for (int v = 0; v < 3; ++v) {
                    step[v] = gx[c] * patch.corners[v].x + gy[c] * patch.corners[v].y;
                    lowest = std::min(lowest, step[v]);
                }
                const float limit = b[c] + lowest < 0.0f ? b[c] / -lowest : 1.0f;
                for (int v = 0; v < 3; ++v) out[v][c] = b[c] + limit * step[v];
            }
            fitted[at] = 1;
        }
    }
}

}  // namespace lightpath
