#include "integrators/coplanar_triangle_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace lightpath {

std::optional<CoplanarTriangleIndex> CoplanarTriangleIndex::build(std::span<const Corners> triangles, float margin) {
    if (triangles.empty()) return std::nullopt;
    CoplanarTriangleIndex index;
    const Corners& first = triangles.front();
    const Vec3 normal = glm::cross(first[1] - first[0], first[2] - first[0]);
    if (!(glm::length(normal) > 0.0f)) return std::nullopt;
    const Vec3 n = glm::normalize(normal);
    index.origin_ = first[0];
    index.axisU_ = glm::normalize(first[1] - first[0]);
    index.axisV_ = glm::cross(n, index.axisU_);
    float extent = 0.0f;
    for (const Corners& t : triangles)
        for (const Vec3& corner : t) extent = std::max(extent, glm::length(corner - index.origin_));
    index.bounds_.reserve(triangles.size());
    for (const Corners& t : triangles) {
        const Vec3 tn = glm::cross(t[1] - t[0], t[2] - t[0]);
        if (!(glm::length(tn) > 0.0f)) return std::nullopt;
        // Coplanar: parallel normals, and every corner in the first triangle's plane.
        if (glm::length(glm::cross(glm::normalize(tn), n)) > kPlaneTolerance) return std::nullopt;
        Box box{Vec2(std::numeric_limits<float>::infinity()), Vec2(-std::numeric_limits<float>::infinity())};
        float longest = 0.0f;
        for (int k = 0; k < 3; ++k) {
            if (std::fabs(glm::dot(t[k] - index.origin_, n)) > kPlaneTolerance * std::max(extent, 1.0f)) return std::nullopt;
            const Vec2 p = index.project(t[k]);
            box.lo = glm::min(box.lo, p);
            box.hi = glm::max(box.hi, p);
            longest = std::max(longest, glm::length(t[(k + 1) % 3] - t[k]));
        }
        // The margin, plus the projection's own roundoff at this distance from the origin.
        const float grow = margin * longest + 1e-5f * std::max(extent, 1.0f);
        box.lo -= Vec2(grow);
        box.hi += Vec2(grow);
        index.bounds_.push_back(box);
    }
    index.order_.resize(triangles.size());
    std::iota(index.order_.begin(), index.order_.end(), 0u);
    index.nodes_.reserve(2 * triangles.size() / kLeafSize + 1);
    index.nodes_.emplace_back();
    index.buildNode(0, 0, static_cast<std::uint32_t>(triangles.size()), 0);
    return index;
}

void CoplanarTriangleIndex::buildNode(std::uint32_t id, std::uint32_t first, std::uint32_t count, std::uint32_t depth) {
    Node node;
    node.lo = Vec2(std::numeric_limits<float>::infinity());
    node.hi = Vec2(-std::numeric_limits<float>::infinity());
    Vec2 centreLo = node.lo, centreHi = node.hi;
    for (std::uint32_t k = first; k < first + count; ++k) {
        const Box& b = bounds_[order_[k]];
        node.lo = glm::min(node.lo, b.lo);
        node.hi = glm::max(node.hi, b.hi);
        const Vec2 centre = 0.5f * (b.lo + b.hi);
        centreLo = glm::min(centreLo, centre);
        centreHi = glm::max(centreHi, centre);
    }
    if (count <= kLeafSize || depth + 2 >= kMaxDepth) {
        node.first = first;
        node.count = count;
        nodes_[id] = node;
        return;
    }
    // Median split along the wider axis of the boxes' centres.
    const int axis = (centreHi.x - centreLo.x) >= (centreHi.y - centreLo.y) ? 0 : 1;
    const std::uint32_t half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](std::uint32_t a, std::uint32_t b) {
                         return bounds_[a].lo[axis] + bounds_[a].hi[axis] < bounds_[b].lo[axis] + bounds_[b].hi[axis];
                     });
    // Children are adjacent: the left one's id is node.first, the right one's node.first + 1.
    const auto left = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    node.first = left;
    node.count = 0;
    nodes_[id] = node;
    buildNode(left, first, half, depth + 1);
    buildNode(left + 1, first + half, count - half, depth + 1);
}

}  // namespace lightpath
