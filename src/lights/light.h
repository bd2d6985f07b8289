#pragma once
// The one light interface every integrator reads (docs/design.md): sample a point towards a
// receiver (next-event estimation, ray casting's shadow rays), the density of that sampling (MIS),
// sample a ray leaving the light (light tracing), and its power (choosing lights). A new kind of
// shapeless light is one file implementing this and scene/scene_light.h's SceneLight, which
// registers its LightType (scene/light_type.h; lights/spot_light.cpp is one).
#include "geometry/bounds.h"
#include "geometry/surface_hit.h"
#include "transport/path_event.h"
#include "math/ray.h"
#include "math/types.h"

namespace lightpath {

// One point on a light as seen from a receiver.
struct LightSample {
    Vec3 point{0.0f};   // on the light
    Vec3 normal{0.0f};  // the light's unit normal at `point`; zero for a point light
    Vec3 wi{0.0f};      // unit, from the receiver towards `point`
    float distance = 0.0f;
    // What f |cos theta_i| is multiplied by: incident radiance over the sample's solid-angle density.
    // A point light gives pi I falloff(d); an area light Le cos(theta_light) / (pdf_area d^2).
    Rgb weight{0.0f};
    float pdf = 0.0f;   // solid-angle density at the receiver; 0 for a delta light
};

// A ray leaving a light, for tracing light from the light's side.
struct EmittedRay {
    Ray ray;
    Vec3 normal{0.0f};        // the light's normal at the origin; zero for a point light
    Rgb radiance{0.0f};       // Le along the ray (a point light: its radiant intensity pi I)
    float pdfPosition = 0.0f; // per unit area (1 for a point light: a delta in position)
    float pdfDirection = 0.0f;// per steradian
};

class Light {
public:
    explicit Light(const PathEvent& event) : event_(event) {}
    virtual ~Light() = default;

    // A point on the light towards `receiver`.
    virtual LightSample sample(const Vec3& receiver, Vec2 u) const = 0;
    // The solid-angle density at `receiver` with which sample() returns `point` (normal `normal`)
    // on this light; 0 for a delta light, which no other technique can reach.
    virtual float pdf(const Vec3& receiver, const Vec3& point, const Vec3& normal) const = 0;
    // Whether sample() towards `receiver` picks points with sampleEmission()'s density per unit
    // area (true for a delta light); false where it samples the solid angle the light subtends
    // instead (a sphere seen from outside), so that bidirectional path tracing weighs the two apart.
    virtual bool samplesByArea(const Vec3& /*receiver*/) const { return true; }
    // A ray leaving the light: a point by area, a direction by cosine (area) or uniformly (point).
    virtual EmittedRay sampleEmission(Vec2 uPoint, Vec2 uDirection) const = 0;
    // The ray leaving `from`'s point along unit `direction` instead: its radiance that way (zero
    // where the light sends none), the normal of the side it leaves by, and pdfDirection as
    // pdfEmissionDirection gives it. Light walks aimed elsewhere (lights/emission_guide.h) take it.
    virtual EmittedRay emitAlong(const EmittedRay& from, const Vec3& direction) const = 0;
    // The density per unit area of sampleEmission()'s points (1 for a point light: a delta).
    virtual float pdfEmissionPosition() const { return 1.0f; }
    // The density per steradian with which sampleEmission() leaves a point of outward normal
    // `normal` (zero for a point light) along unit `direction`: bidirectional path tracing weighs
    // a path that another strategy found by it (MIS, Veach 1997 ch. 10).
    virtual float pdfEmissionDirection(const Vec3& normal, const Vec3& direction) const = 0;
    // The radiance leaving the light at `hit` towards `towardViewer` (zero for a point light).
    virtual Rgb radiance(const SurfaceHit& hit, const Vec3& towardViewer) const = 0;
    // How light from the light falls off over distance d, in place of 1/d^2: the lecture's
    // attenuation 1 / (c0 + c1 d + c2 d^2) for point lights, physical 1/d^2 for area lights.
    virtual float falloff(float distance) const { return 1.0f / (distance * distance); }
    // The share of its axis' intensity a delta light sends along unit `leaving` (a spot's cone;
    // 1 for a point light): `explain` prints it as a factor of its own beside I and attenuation.
    virtual float intensityShare(const Vec3& /*leaving*/) const { return 1.0f; }
    // Emitted flux (W): lights are chosen in proportion to it.
    virtual Rgb power() const = 0;
    virtual bool isDelta() const = 0;
    // A light at infinity (directional): its rays are parallel, a delta in direction. Its
    // sampleEmission() then picks the ray's place on a disk across the scene with pdfDirection
    // per unit area perpendicular to the rays (pdfPosition 1), and the density of a receiver per
    // unit area is that times |cos| at the receiver, with no 1/d^2 (pbrt-v4's DistantLight).
    virtual bool atInfinity() const { return false; }
    // Whether sampleEmission()'s rays can reach `receiver` at all: a light at infinity's disk
    // covers the scene's bounds, not an unbounded plane beyond them, where only light sampling
    // finds its light (and bidirectional path tracing must weigh it so).
    virtual bool emitsTowards(const Vec3& /*receiver*/) const { return true; }
    // The box around the scene's bounded shapes and the camera, once before rendering: a light at
    // infinity sizes its emission disk by it (pbrt-v4 DistantLight::Preprocess).
    virtual void preprocess(const Bounds& /*sceneBounds*/) {}
    // Whether light sampling and light tracing may start on it; an emitter too small for its
    // densities to be floats is seen only where a ray hits it (LightSet chooses it never).
    virtual bool sampleable() const { return true; }

    // The event this light ends a path with: `L` for a [[lights]] entry, `O` for a surface whose
    // material emits (OSL's object emission), with the subject that labels it.
    const PathEvent& event() const { return event_; }

private:
    PathEvent event_;
};

}  // namespace lightpath
