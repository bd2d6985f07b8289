#pragma once
// What `--integrator radiosity` is asked for on the command line (docs/integrators.md, "Radiosity").
#include <cstddef>
#include <cstdint>

namespace lightpath {

enum class RadiosityDisplay : std::uint8_t {
    Smooth,   // Gouraud scaled per element so each element shows its own mean (radiosity.cpp,
              // computeVertexValues): smooth where the mesh resolves the light, exact in the mean everywhere
    Gouraud,  // vertex radiosities interpolated across each patch, unscaled (before issue 27's
              // display fix: a patch beside a steep change shows its neighbours' light)
    Flat,     // each patch's own radiosity: the mesh is visible
};

struct RadiosityOptions {
    // Target patch edge in scene units; 0: the finest size within `patchBudget`.
    float patchSize = 0.0f;
    // The default budget and rounds suit the final gather (docs/integrators.md, "Final gather"):
    // it reads each bounce over whole hemispheres, so a finer first mesh serves it better than a
    // third round of cuts at shadow edges, and costs less (bench/radiosity_bounces.py: every shipped
    // scene within 2% in the mean and 3.3% per region, against up to 7.8% at 4096 and 3 rounds).
    std::size_t patchBudget = 8192;
    // Hemisphere rays cast from each side of each patch to estimate its form factors (rounded to a
    // square number, for stratification), and light samples per side of a patch and light.
    int formFactorRays = 256;
    int lightSamples = 64;
    // Refinement passes after the first solve (radiosity.h): each cuts the patches whose vertex
    // radiosities differ from their own by more than `refineTolerance` into four and solves again,
    // up to kRefineGrowth times the first mesh's elements (radiosity.cpp). 0: uniform patches.
    int refineRounds = 2;
    double refineTolerance = 0.05;
    // A patch is cut only where that difference also exceeds this many standard deviations of its
    // own sampling noise (the form factors' and the light samples', estimated from the rays
    // themselves: radiosity.cpp, refinementCuts), so refinement chases the mesh's error, not the
    // noise. 0: noise-blind, as before (the tests' control). Not a command-line option.
    double refineNoiseSigmas = 4.0;
    // Refinement also cuts clusters (RadiosityMesh::splitClusters) where the light their parts
    // receive differs from the cluster's by more than the tolerance and the noise (radiosity.cpp,
    // clustersToRefine). false: clusters are never cut, as before (the tests' control). Not a
    // command-line option.
    bool refineClusters = true;
    // Jacobi stops once a bounce adds less than this fraction of the light so far of the outputs
    // that receive it (radiosity.cpp, solve), or at --max-depth.
    double tolerance = 1e-4;
    RadiosityDisplay display = RadiosityDisplay::Smooth;
    // Final gather (the view pass of two-pass methods: Chen et al. 1991; Reichert 1992; Cohen and
    // Wallace 1993, 9.2.2): at a camera hit, bounce 1 is the direct light sampled there with
    // shadow rays (this many samples of an area light per camera sample) and bounces 2 and up are
    // gathered over its hemisphere, this many cosine-weighted rays each reading the solution's
    // previous bounce where it lands, rather than read from the hit's own element. The mesh's
    // error then reaches the image only through an average over the hemisphere: a shadow's edge,
    // a contact or a ball's underside, which a patch's value smears, shows as the path tracer
    // shows it (issue 27's 5% per 4x4 region). 0: every bounce read from the solution at the hit,
    // the classic display, noise-free and view-independent.
    int finalGather = 16;
    // Coarser rings around an unbounded surface's rectangle over the scene (RadiosityMesh); 0 clips
    // it to the rectangle, as before issue 27 (the light it bounces from beyond is lost: the tests'
    // control). Not a command-line option.
    int planeRings = 3;
    // Buried triangles (inside another object, behind a plane: RadiosityMesh::buriedTriangles) are
    // clustered apart from exposed ones. false: clustered together, as before issue 27's fix (they
    // dilute the exposed triangles' light: the tests' control). Not a command-line option.
    bool separateBuried = true;
    // An unbounded surface's rectangle is cut along the lines where other surfaces meet it (a wall's
    // foot on a floor plane), so no patch straddles one (RadiosityMesh). false: whole, as before
    // (its patches run under the walls: the tests' control). Not a command-line option.
    bool cutPlanes = true;
    // Later bounces gather each form-factor ray's light from the radiosity reconstructed at its hit
    // point (the Gouraud plane of the hit patch, scaled to its element's own mean: radiosity.cpp,
    // solve) rather than from the element's constant value. false: the constant, as before (where
    // an element's light is brighter on the side its receivers see, a ball's contact with a floor,
    // later bounces came out low: the tests' control). Not a command-line option.
    bool reconstructGather = true;
    // With reconstructGather, a triangle patch solved on its own is read through its least-squares
    // gradient (radiosity_gradients.h: its value at the centroid, sloped as its neighbours say,
    // which rises to a peak at a contact line) rather than the scaled plane through its vertex
    // means (which flattens it). false: the scaled plane everywhere, as before (the tests'
    // control). Not a command-line option.
    bool gatherGradients = true;
};

}  // namespace lightpath
