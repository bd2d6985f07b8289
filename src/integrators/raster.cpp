#include "integrators/raster.h"

#include "integrators/registry.h"
#include <algorithm>
#include <cmath>

#include "geometry/intersect.h"
#include "integrators/raycast.h"

namespace lightpath {

ZBuffer::ZBuffer(const SceneGeometry& geometry, const Camera& camera)
    : geometry_(geometry),
      camera_(camera),
      width_(camera.width()),
      height_(camera.height()),
      fragments_(fragmentCount(width_, height_)) {
    // The lecture's loops, in the rasteriser's order: for each primitive, for each pixel it covers.
    for (std::uint32_t i = 0; i < geometry.shapes().size(); ++i) {
        if (geometry.shapes()[i].ops->bounded) rasteriseShape(i);
        else rasteriseUnbounded(i);
    }
    for (std::uint32_t i = 0; i < geometry.triangles().size(); ++i) rasteriseTriangle(i);
}

Vec3 ZBuffer::pixelDirection(int x, int y) const {
    return camera_.filmDirection(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
}

void ZBuffer::test(int x, int y, float t, std::uint32_t primitive, const Vec3& barycentrics) {
    RasterFragment& kept = fragments_[index(x, y)];
    if (!(t < kept.t)) return;
    // The alpha test: a fragment where the surface is cut out is discarded (geometry/coverage.h).
    if (geometry_.hasCutouts()) {
        const Ray ray = camera_.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        const bool triangle = geometry_.shapeOf(primitive) == nullptr;
        if (!geometry_.covers(ray, t, primitive, triangle ? &barycentrics : nullptr)) return;
    }
    kept = {t, primitive, barycentrics};
}

std::array<int, 4> ZBuffer::pixelBox(const Vec3& a, const Vec3& b, const Vec3& c) const {
    int x0 = 0, y0 = 0, x1 = width_ - 1, y1 = height_ - 1;
    const auto pa = camera_.filmPosition(a), pb = camera_.filmPosition(b), pc = camera_.filmPosition(c);
    if (pa && pb && pc) {
        const auto low = [](float v) { return static_cast<int>(std::floor(v)) - 1; };
        const auto high = [](float v) { return static_cast<int>(std::ceil(v)) + 1; };
        x0 = std::max(x0, low(std::min({pa->x, pb->x, pc->x})));
        y0 = std::max(y0, low(std::min({pa->y, pb->y, pc->y})));
        x1 = std::min(x1, high(std::max({pa->x, pb->x, pc->x})));
        y1 = std::min(y1, high(std::max({pa->y, pb->y, pc->y})));
    }
    if (x1 >= x0 && y1 >= y0) pixelsTested_ += std::uint64_t(x1 - x0 + 1) * std::uint64_t(y1 - y0 + 1);
    return {x0, y0, x1, y1};
}

template <typename Fragment>
void ZBuffer::coverTriangleOrthographic(const Vec3& a, const Vec3& b, const Vec3& c, Fragment fragment) const {
    // Parallel rays along forward: the corners project to the film by dropping their depth, so 2D
    // edge functions of each pixel's ray origin give its barycentrics, and the depth (the unit
    // ray's t) interpolates linearly. In double, inclusive on every edge, as coverTriangle.
    const glm::dvec3 right(camera_.right()), up(camera_.up()), forward(camera_.forward());
    const glm::dvec3 corners[3] = {glm::dvec3(a), glm::dvec3(b), glm::dvec3(c)};
    glm::dvec2 film[3];
    double depth[3];
    for (int k = 0; k < 3; ++k) {
        film[k] = {glm::dot(corners[k], right), glm::dot(corners[k], up)};
        depth[k] = glm::dot(corners[k], forward);
    }
    const auto edge = [](const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& x) {
        return (q.x - p.x) * (x.y - p.y) - (q.y - p.y) * (x.x - p.x);
    };
    const double area = edge(film[0], film[1], film[2]);
    if (!(std::fabs(area) > 0.0) || !std::isfinite(area)) return;  // edge-on: no area on the film
    const double orientation = area > 0.0 ? 1.0 : -1.0;
    const double film0 = glm::dot(glm::dvec3(camera_.eye()), forward);  // the film's depth
    if (depth[0] <= film0 && depth[1] <= film0 && depth[2] <= film0) return;  // wholly behind the film
    const auto [x0, y0, x1, y1] = pixelBox(a, b, c);
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec3 origin(camera_.filmOrigin(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
            const glm::dvec2 o{glm::dot(origin, right), glm::dot(origin, up)};
            const double ea = orientation * edge(film[1], film[2], o), eb = orientation * edge(film[2], film[0], o),
                         ec = orientation * edge(film[0], film[1], o);
            if (ea < 0.0 || eb < 0.0 || ec < 0.0) continue;
            const double sum = ea + eb + ec;
            if (!(sum > 0.0)) continue;
            const glm::dvec3 barycentrics = glm::dvec3{ea, eb, ec} / sum;
            const double t = barycentrics.x * depth[0] + barycentrics.y * depth[1] + barycentrics.z * depth[2] -
                             glm::dot(origin, forward);
            if (!(t > 0.0)) continue;  // behind the film, where the rays start
            fragment(x, y, static_cast<float>(t), Vec3(barycentrics));
        }
    }
}

template <typename Fragment>
void ZBuffer::coverTriangle(const Vec3& a, const Vec3& b, const Vec3& c, Fragment fragment) const {
    if (camera_.orthographic()) {
        coverTriangleOrthographic(a, b, c, fragment);
        return;
    }
    // In double: for a small triangle far away, vb x vc is the difference of nearly equal
    // products, and in float its rounding moves depths by 1e-3 relative, enough to change which
    // of two nearby surfaces is nearer.
    const glm::dvec3 eye(camera_.eye());
    const glm::dvec3 va = glm::dvec3(a) - eye, vb = glm::dvec3(b) - eye, vc = glm::dvec3(c) - eye;
    // Edge function of the edge opposite a: (vb x vc).D, zero on the plane through the eye and
    // that edge. For D = s^-1 X, X = sum_i beta_i v_i on the triangle, e_i(D) = beta_i det / s.
    const glm::dvec3 na = glm::cross(vb, vc), nb = glm::cross(vc, va), nc = glm::cross(va, vb);
    const double det = glm::dot(va, na);  // 6 x the signed volume of the tetrahedron (eye, a, b, c)
    if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return;  // edge-on: no area on the film
    const double orientation = det > 0.0 ? 1.0 : -1.0;
    const double volume = std::fabs(det);
    // Wholly behind the eye's plane: no film direction reaches it (the edge functions would refuse
    // every pixel). Refused here, because such a triangle has no projected bounding box, and
    // testing the whole film for each facet of a sphere behind the camera took minutes.
    const glm::dvec3 forward(camera_.forward());
    if (glm::dot(va, forward) <= 0.0 && glm::dot(vb, forward) <= 0.0 && glm::dot(vc, forward) <= 0.0) return;

    // The pixels to test: the projected triangle's bounding box (one pixel of slack for the
    // projection's rounding), or the whole film when a corner is not in front of the eye.
    const auto [x0, y0, x1, y1] = pixelBox(a, b, c);
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec3 d(pixelDirection(x, y));
            // Inclusive on every edge: a pixel centre on an edge two triangles share is covered by
            // both (the edge functions are exact negatives), never by neither.
            const double ea = orientation * glm::dot(na, d), eb = orientation * glm::dot(nb, d),
                         ec = orientation * glm::dot(nc, d);
            if (ea < 0.0 || eb < 0.0 || ec < 0.0) continue;
            const double sum = ea + eb + ec;
            if (!(sum > 0.0)) continue;
            // Perspective-correct: the film direction meets the triangle at s d, s = det / sum.
            const auto t = static_cast<float>(volume / sum * glm::length(d));
            fragment(x, y, t, Vec3(glm::dvec3{ea, eb, ec} / sum));
        }
    }
}

void ZBuffer::rasteriseTriangle(std::uint32_t index) {
    const Triangle& triangle = geometry_.triangles()[index];
    const std::uint32_t id = geometry_.triangleId(index);
    coverTriangle(triangle.a, triangle.b, triangle.c,
                  [&](int x, int y, float t, const Vec3& barycentrics) { test(x, y, t, id, barycentrics); });
}

float ZBuffer::depthUnder(const ShapeRecord& shape, std::uint32_t id, int x, int y) const {
    if (shape.ops->depthAlong && !camera_.orthographic()) {
        const Vec3 d = pixelDirection(x, y);
        const float s = shape.ops->depthAlong(shape, camera_.eye(), d);
        return s > 0.0f && std::isfinite(s) ? s * glm::length(d) : kNoHit;
    }
    const Ray ray = camera_.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    return geometry_.intersectPrimitive(ray, id);
}

void ZBuffer::rasteriseUnbounded(std::uint32_t index) {
    // No box holds it: every pixel centre is tested (a plane's image is the film on one side of
    // its horizon).
    const ShapeRecord& shape = geometry_.shapes()[index];
    const std::uint32_t id = geometry_.shapeId(index);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const float t = depthUnder(shape, id, x, y);
            if (t != kNoHit) test(x, y, t, id, Vec3{0.0f});
        }
    }
}

void ZBuffer::rasteriseShape(std::uint32_t index) {
    // Its bounding box's 12 triangles cover every pixel it can cover, and each such pixel takes the
    // shape's own depth under its centre, once (a ray-cast impostor, Sigg et al. 2006): exactly ray
    // casting's first hits, with no facets to approximate a curved outline.
    const ShapeRecord& shape = geometry_.shapes()[index];
    const std::uint32_t id = geometry_.shapeId(index);
    const Bounds box = shape.ops->bounds(shape);
    const auto corner = [&](int i) {
        return Vec3{i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z};
    };
    const auto fragment = [&](int x, int y, float, const Vec3&) {
        if (fragments_[this->index(x, y)].primitive == id) return;
        const float t = depthUnder(shape, id, x, y);
        if (t != kNoHit) test(x, y, t, id, Vec3{0.0f});
    };
    // Each face of the box as two triangles: the faces x, y, z = lo and = hi.
    constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto& face : kFaces) {
        coverTriangle(corner(face[0]), corner(face[1]), corner(face[2]), fragment);
        coverTriangle(corner(face[0]), corner(face[2]), corner(face[3]), fragment);
    }
}

std::optional<SurfaceHit> ZBuffer::surfaceAt(int x, int y) const {
    const RasterFragment& kept = at(x, y);
    if (kept.primitive == kNoPrimitive) return std::nullopt;
    const Ray ray = camera_.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    const bool triangle = geometry_.shapeOf(kept.primitive) == nullptr;
    return geometry_.describeHit(ray, kept.t, kept.primitive, triangle ? &kept.barycentrics : nullptr);
}

void RasterIntegrator::preprocess(const RenderContext& context) { zBuffer_.emplace(context.geometry, context.camera); }

void RasterIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    // The renderer samples each pixel once, at its centre (samplesPixelCentres): the ray names its pixel.
    const std::optional<Vec2> film = path.context.camera.filmPosition(ray.origin + ray.direction);
    if (!film) return;
    const int x = std::clamp(static_cast<int>(std::floor(film->x)), 0, zBuffer_->width() - 1);
    const int y = std::clamp(static_cast<int>(std::floor(film->y)), 0, zBuffer_->height() - 1);
    shadeFirstHit(zBuffer_->surfaceAt(x, y), ray, path);
}

}  // namespace lightpath

// It finds ray casting's first hits with a z-buffer and shades them with raycast.cpp: ray casting's language.
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::integratorRow(
    "raster", "z-buffer rasterisation: ray casting's first hits with the loops swapped, one sample per pixel, no shadows",
    "E(D|G)L|EL", "rasterisation shades the first visible surface only, like ray casting",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::RasterIntegrator>()); },
    lightpath::ShadowRays::Never, 1))
