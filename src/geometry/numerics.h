#pragma once
// Which numerical method each geometric operation uses. The robust methods are the default; the
// naive ones stay selectable so a lecture can show what goes wrong (Szymczak, "Ray-primitive
// intersections: accuracy" and "Is p in shadow? A way around roundoff errors").
namespace lightpath {

enum class SphereTest {
    Stable,  // discriminant r^2 - |f - (f.d)d|^2 and the stable pair of roots
    Naive,   // b^2 - 4ac and (-b +- sqrt(disc)) / 2a, as in the lecture's first derivation
};

enum class TriangleTest {
    Watertight,      // Woop, Benthin and Wald 2013
    MollerTrumbore,  // Moller and Trumbore 1997 with a |det| < epsilon parallel test
};

enum class RayOffset {
    Robust,        // origin moved past a bound of the hit point's rounding error (pbrt-v4)
    WachterBinder, // Wachter and Binder 2019: a fixed number of ulps, absolute near the origin
    FixedEpsilon,  // the lecture's fix: start at t_min = epsilon
    None,          // start exactly at the computed hit point: shadow acne
    OwnPrimitive,  // the lecture's "treat the primitive containing p differently": ignore it
};

struct NumericsOptions {
    SphereTest sphere = SphereTest::Stable;
    TriangleTest triangle = TriangleTest::Watertight;
    RayOffset offset = RayOffset::Robust;
    float epsilon = 1e-4f;  // t_min of FixedEpsilon; the |det| threshold of MollerTrumbore is 1e-6

    static NumericsOptions naive() {
        return {SphereTest::Naive, TriangleTest::MollerTrumbore, RayOffset::FixedEpsilon, 1e-4f};
    }
};

}  // namespace lightpath
