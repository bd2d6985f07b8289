#pragma once
// Which of many coplanar triangles may hold a point: a bounding-volume hierarchy over their 2D
// bounds in the plane they share (radiosity's mesh of an infinite plane: its cut rectangle's pieces
// and its rings, hundreds of triangles from a patch's size to 64 times the scene's). A point is
// projected into the plane, so one off it by roundoff finds the triangles its projection lies in.
// Each triangle's bounds are grown by a margin, so every triangle whose barycentric test accepts
// the point within a small slack is a candidate: the index narrows a scan, it never decides it.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "math/types.h"

namespace lightpath {

class CoplanarTriangleIndex {
public:
    using Corners = std::array<Vec3, 3>;

    // The index of `triangles` (at least one), or nullopt when they do not share a plane (within
    // `kPlaneTolerance` of their extent) or one is degenerate. `margin`: how far outside a triangle,
    // in units of its longest edge, a point still counts as near it.
    static std::optional<CoplanarTriangleIndex> build(std::span<const Corners> triangles, float margin);

    // Calls visit(i) for each triangle i whose grown bounds hold `point`'s projection, in no
    // particular order.
    template <class Visit>
    void forEachCandidate(const Vec3& point, Visit&& visit) const {
        const Vec2 p = project(point);
        std::uint32_t stack[kMaxDepth];
        std::uint32_t top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (p.x < node.lo.x || p.y < node.lo.y || p.x > node.hi.x || p.y > node.hi.y) continue;
            if (node.count > 0) {
                for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
                    if (holds(bounds_[order_[k]], p)) visit(order_[k]);
            } else {
                stack[top++] = node.first;
                stack[top++] = node.first + 1;
            }
        }
    }

    static constexpr float kPlaneTolerance = 1e-4f;

private:
    struct Box {
        Vec2 lo{0.0f}, hi{0.0f};
    };
    // A leaf: triangles order_[first .. first + count); an inner node (count 0): children first, first + 1.
    struct Node {
        Vec2 lo{0.0f}, hi{0.0f};
        std::uint32_t first = 0, count = 0;
    };
    static constexpr std::uint32_t kLeafSize = 4;
    static constexpr std::uint32_t kMaxDepth = 64;  // median splits: depth log2(n / kLeafSize) + 1

    static bool holds(const Box& b, Vec2 p) { return p.x >= b.lo.x && p.y >= b.lo.y && p.x <= b.hi.x && p.y <= b.hi.y; }
    Vec2 project(const Vec3& point) const {
        const Vec3 d = point - origin_;
        return {glm::dot(d, axisU_), glm::dot(d, axisV_)};
    }
    // Fills node `id` with triangles order_[first .. first + count), its children appended.
    void buildNode(std::uint32_t id, std::uint32_t first, std::uint32_t count, std::uint32_t depth);

    Vec3 origin_{0.0f}, axisU_{0.0f}, axisV_{0.0f};
    std::vector<Box> bounds_;           // per triangle, grown by its margin
    std::vector<std::uint32_t> order_;  // triangle ids, leaf by leaf
    std::vector<Node> nodes_;           // node 0 the root
};

}  // namespace lightpath
