#pragma once
// The vertices of bidirectional path tracing's subpaths and the multiple importance weights of its
// strategies (Veach 1997, ch. 10; Veach and Guibas 1995). A path x0 (on a light) ... x(n-1) (the
// eye) is made by strategy (s, t), s + t = n: s vertices walked from the light, t from the eye,
// joined by one segment. Each vertex keeps its area density as its own walk sampled it (pdfFwd)
// and as the other walk would have (pdfRev), so every strategy's density of the same path is a
// product of these, and the power heuristic compares them.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "integrators/path_record.h"
#include "integrators/shading_point.h"
#include "lights/light.h"
#include "materials/bsdf.h"

namespace lightpath {

struct RenderContext;

// A subpath has at most the eye (or the light) and one vertex per scattering event plus the end.
inline constexpr int kMaxSubpathVertices = kMaxDepth + 2;

// A vertex's shading point, which (holding references) cannot be assigned: replaced whole instead.
class ShadingSlot {
public:
    ShadingSlot() = default;
    ShadingSlot(const ShadingSlot& other) { *this = other; }
    ShadingSlot& operator=(const ShadingSlot& other) {
        if (this == &other) return *this;
        value_.reset();
        if (other.value_) value_.emplace(*other.value_);
        return *this;
    }
    void emplace(const ShadingPoint& point) {
        value_.reset();
        value_.emplace(point);
    }
    const ShadingPoint& operator*() const { return *value_; }
    const ShadingPoint* operator->() const { return &*value_; }
    explicit operator bool() const { return value_.has_value(); }

private:
    std::optional<ShadingPoint> value_;
};

enum class VertexKind : std::uint8_t { Camera, Light, Surface };

struct BdptVertex {
    VertexKind kind = VertexKind::Surface;
    Vec3 point{0.0f};
    Vec3 normal{0.0f};  // geometric, for area densities; zero for a point light and the camera
    // The walk's throughput up to this vertex: for an eye subpath the radiance weight, for a light
    // subpath Le G f ... / densities, excluding this vertex's own scattering (pbrt-v4 "beta").
    Rgb beta{0.0f};
    float pdfFwd = 0.0f;  // area density of this vertex sampled by its own walk
    float pdfRev = 0.0f;  // area density of this vertex sampled from the other side
    // Surface: the lobe the walk left through (the path's event here) and whether it is a delta.
    // Light: delta for a point light. A delta vertex cannot end a subpath that is joined.
    int lobe = 0;  // its index in the material's lobes()
    bool delta = false;
    const Light* light = nullptr;  // the light of x0
    // x0's densities per unit area on its light: as light sampling from x1 picks it (next-event
    // estimation, s = 1), and as sampleEmission does (light walks, s >= 2). They differ where light
    // sampling samples the solid angle a sphere subtends instead of its area.
    float pdfPosition = 0.0f;
    float pdfEmission = 0.0f;
    ShadingSlot surface;
    // Surface: bit l set when lobe l is smooth (not a delta) and the material has it, asked once
    // here rather than per lobe at every join (which also asked the material at each).
    std::uint32_t smoothLobes = 0;

    bool onSurface() const { return kind == VertexKind::Surface; }
    bool scattersSmoothly(int lobe) const { return (smoothLobes >> lobe & 1u) != 0; }
};

// Solid-angle density at `from` converted to area density at `to` (Veach 1997, eq. 8.10). Inline:
// each join converts six densities.
inline float toAreaDensity(float pdfSolidAngle, const BdptVertex& from, const BdptVertex& to) {
    const Vec3 d = to.point - from.point;
    const float distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0f)) return 0.0f;
    // Parallel rays: the density is per unit area across them already (lights/light.h).
    if (from.kind == VertexKind::Light && from.light != nullptr && from.light->atInfinity())
        return !from.light->emitsTowards(to.point) ? 0.0f
               : glm::dot(to.normal, to.normal) > 0.0f ? pdfSolidAngle * std::fabs(glm::dot(to.normal, d)) / std::sqrt(distance2)
                                                     : pdfSolidAngle;
    float pdf = pdfSolidAngle / distance2;
    // A point light and the pinhole have no surface: their density stays per unit solid angle
    // times 1/d^2, and no strategy's weight reads it (neither can be hit by chance).
    if (glm::dot(to.normal, to.normal) > 0.0f) pdf *= std::fabs(glm::dot(to.normal, d)) / std::sqrt(distance2);
    return pdf;
}

// Where one scattering step left a vertex, as the walk sampled it or as a test prescribes it.
struct ScatterStep {
    Vec3 wi{0.0f};
    int lobe = 0;  // its index in the material's lobes()
    Rgb weight{0.0f};      // f |cos| / pdf
    float pdf = 0.0f;      // solid angle, forward; 1 for a delta lobe (its Dirac cancels between strategies)
    bool delta = false;
};

// The step that scatters from `vertex` into `wi` through `lobe`: for a walk that must pass through
// given points (tests, and the same arithmetic as a sampled step).
ScatterStep prescribedStep(const ShadingPoint& vertex, int lobe, const Vec3& wi);
// The step Bsdf::sample takes, with its reverse density; nullopt when it scatters nothing.
std::optional<ScatterStep> sampledStep(const ShadingPoint& vertex, float uLobe, Vec2 u);

// Builders of subpath vertices.
BdptVertex cameraVertex(const Vec3& origin, bool directionDelta = false);
// x0 on `light`, at `point` with outward `normal`, where light sampling picks it with area
// density `pdfPosition` and emission with `pdfEmission`.
BdptVertex lightVertex(const Light& light, const Vec3& point, const Vec3& normal, float pdfPosition, float pdfEmission);
// The density per unit area with which light sampling from `receiver` picks `point` (of `normal`)
// on `light`: Light::pdf converted from solid angle (Veach 1997, eq. 8.10).
float lightSamplingAreaDensity(const Light& light, const Vec3& receiver, const Vec3& point, const Vec3& normal);
// Makes `v` the vertex where a walk's `ray`, leaving `previous` with solid-angle density
// `pdfSolidAngle` (through a delta lobe when `delta`), hits `hit`. When `previous` is a surface
// vertex, linkThrough then sets the density from the points. In place: a vertex returned and
// assigned copied its shading point twice (2% of a bdpt render's instructions, more of its time).
void setSurfaceVertex(BdptVertex& v, const SurfaceHit& hit, const Ray& ray, const Rgb& beta, const BdptVertex& previous,
                      float pdfSolidAngle, bool delta, const RenderContext& context, TransportMode mode);
// Once a walk has gone `before` -> `at` -> `here` through `at`'s lobe: here's area density as the
// walk sampled it (pdfFwd) and before's as the opposite walk would sample it from `at` (pdfRev),
// both with the BSDF's directions taken between the three points, as joinedDensities takes every
// other strategy's. Not from the traced ray: it left `at` from an origin offset off the surface
// (geometry/ray_offset.h), so its direction differs from at -> here by about offset / distance,
// and along a short grazing chord the density it gives (the sampled direction's, converted with
// the chord's cosine and length) differs by offset / cos^2 from the one the other strategies give
// the same path. The weights of a path's strategies then sum below one: a closed emissive sphere
// (kd 0.5, Le 1) read 0.49998 for its 0.5 of E D L (docs/integrators.md, bdpt).
void linkThrough(BdptVertex& before, const BdptVertex& at, BdptVertex& here);
// Makes surface vertex `z`, reached from `previous`, the origin x0 of a path on `emitter` (s = 0).
void markEmitter(BdptVertex& z, const Light& emitter, const BdptVertex& previous);

// Every strategy's density of one path, per vertex, in the path's order from the light. Only the
// first n entries are written and read: the arrays are left uninitialised, since clearing all
// 2 kMaxSubpathVertices of them per join cost more than the join's arithmetic.
struct PathDensities {
    int n = 0;
    std::array<double, 2 * kMaxSubpathVertices> fromLight;  // x_i sampled by a walk from the light
    std::array<double, 2 * kMaxSubpathVertices> fromEye;    // x_i sampled by a walk from the eye
    std::array<bool, 2 * kMaxSubpathVertices> connectible;  // x_i may end a joined subpath
    double originByNextEvent = 0.0;  // x0 chosen by light sampling (s = 1): choice * pdfPosition
    double originByEmission = 0.0;   // x0 chosen to start a light walk (s >= 2)
    bool originHittable = false;     // an eye walk can find x0 by chance (an area light: s = 0)
    bool cameraJoinable = true;      // light tracing (t = 1) can reach the camera: a pinhole, not an orthographic one
};

// The densities of the path made by joining light[0..s) and eye[0..t) (either may be empty: s = 0
// is an eye walk that hit a light, t = 0 is not a strategy of a pinhole), the joined ends scattering
// through `lightLobe` and `eyeLobe`.
PathDensities joinedDensities(std::span<const BdptVertex> light, int lightLobe, std::span<const BdptVertex> eye,
                              int eyeLobe, const RenderContext& context);

// The power-heuristic weight of strategy s for `path`: (n_s p_s)^2 / sum over the strategies that
// can make it of (n_k p_k)^2 (Veach 1997, eq. 9.13, with n_k samples of strategy k). The eye's
// strategies (s = 0, 1) take one sample per camera sample; light tracing (t = 1) takes `lightWalks`,
// the light walks traced per camera sample on average (0: none, the light walk's strategies out),
// and the joins (s, t >= 2), made from the first light walk only, min(lightWalks, 1).
float misWeight(const PathDensities& path, int s, double lightWalks);

}  // namespace lightpath
