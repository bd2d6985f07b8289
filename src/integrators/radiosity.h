#pragma once
// Classic diffuse radiosity (Goral et al. 1984; Cohen and Wallace 1993), the lecture's fourth
// method, whose light paths are exactly E D* L.
//
// preprocess() meshes the scene (RadiosityMesh), estimates form factors by casting stratified
// cosine-weighted hemisphere rays from every side of every patch through the scene's BVH (so
// F_ij is the fraction of patch i's rays that land on patch j's facing side, and visibility is the
// tracer's own), gathers every light's direct light at sample points of each patch with shadow rays
// (bounce 1), then solves by Jacobi iteration: bounce k+1 = rho F (bounce k), each ray of F reading
// bounce k at its hit point (the hit patch's Gouraud plane scaled to its element's mean, so each
// element sends its own flux, spread as the light around it varies: solve). Iteration k holds
// exactly the light that has been reflected k times, kept per bounce and per light, so a camera ray
// can hand each to the automaton as its own path E D{k} L. Then it refines (RadiosityOptions::
// refineRounds): the patches whose vertex radiosities' mean (the mean of what the display
// interpolates) differs from their own by more than the tolerance and by more than a few standard
// deviations of its sampling noise are cut into four (RadiosityMesh::split) and everything is
// solved again, until nothing asks or the element budget is spent.
//
// A patch's reflectance is its material's diffuse kd (the Lambert lobe of the shared Bsdf). Glossy
// (ks), mirror (kr) and glass (kt) parts take no part, as in classic radiosity, and neither does
// the ambient term ka Ia. Emitters' own radiance is what the other integrators show for E L / E O.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "integrators/integrator.h"
#include "integrators/radiosity_mesh.h"

namespace lightpath {

class PatchGradients;
class ProgressBar;
struct SeenPoint;  // radiosity.cpp: the point the final gather weighs the light at

struct RadiosityStats {
    std::size_t patches = 0;
    std::size_t clusters = 0;          // elements solved: patches, the small ones clustered (RadiosityMesh)
    float patchSize = 0.0f;
    std::uint64_t formFactorRays = 0;
    std::uint64_t shadowRays = 0;      // direct light: shadow rays and, for area lights, rays towards them
    std::size_t refined = 0;           // patches cut into four by the refinement passes
    std::size_t clustersCut = 0;       // clusters cut into the eighths of their cells by them
    int refineRounds = 0;              // refinement passes that cut something
    int iterations = 0;                // bounces solved (Jacobi iterations, the first one direct)
    int lightsSolved = 0;              // lights some requested output accepts
    int lightBouncesSolved = 0;        // (light, bounce) solutions computed, summed over lights
    double residual = 0.0;             // the last iteration's flux over the solution's
    double seconds = 0.0;              // meshing, form factors, direct light and the solve
    // What the element budget kept the solve from resolving, as one sentence (empty: nothing):
    // printed as a warning and in --stats.
    std::string unresolved;
};

// `base` with the parameters of radiosity's schema (its registry row: --patch-size, --patches,
// --form-factor-rays, --light-samples, --radiosity-display) that `parameters` holds.
RadiosityOptions radiosityOptions(const ParameterValues& parameters, RadiosityOptions base = {});

class RadiosityIntegrator final : public Integrator {
public:
    void preprocess(const RenderContext& context) override;
    void traceCameraRay(const Ray& ray, PathState& path) const override;

    const RadiosityStats& stats() const { return stats_; }
    const RadiosityMesh& mesh() const { return *mesh_; }
    // The solved radiance leaving side `side` (0: front, along the patch's normal) of `patch` after
    // exactly `bounce` reflections of light `light` (LightSet::all() order); zero if not solved.
    Rgb patchRadiance(std::size_t light, int bounce, std::uint32_t patch, int side) const;
    // The form factors from one side of a patch's cluster (the ray estimates): to element
    // 2 * cluster + side of each cluster its rays reached (cluster = patch where nothing is clustered).
    struct FormFactorRow {
        std::span<const std::uint32_t> targets;
        std::span<const float> factors;
    };
    FormFactorRow formFactors(std::uint32_t patch, int side) const;

private:
    // An element is one side of one cluster: 2 * cluster + side.
    std::uint32_t elementCount() const { return static_cast<std::uint32_t>(2 * mesh_->clusters().size()); }
    // Bounces 1..bounces_ of each light, one after the other.
    std::size_t slot(std::size_t light, int bounce) const { return light * std::size_t(bounces_) + std::size_t(bounce - 1); }
    std::size_t valueIndex(std::size_t light, int bounce, std::size_t element) const {
        return slot(light, bounce) * elementCount() + element;
    }
    std::size_t vertexValueIndex(std::size_t light, int bounce, std::size_t vertex, int side) const {
        return slot(light, bounce) * 2 * mesh_->vertexCount() + 2 * vertex + std::size_t(side);
    }
    // The highest bounce of each light that a requested output can accept (0: none), and in
    // openFrom the first bounce from which the same outputs accept every later bounce (the
    // open-ended group: 1 for ED*L, 4 for ED{4,}L beside EDL..EDDDL, 2 for the classes).
    std::vector<int> wantedBounces(const RenderContext& context, int& openFrom) const;
    // keepRays: also keep each ray's target element (rayTargets_), for the noise estimate.
    void computeFormFactors(const RenderContext& context, ProgressBar& progress, bool keepRays);
    void gatherDirectLight(const RenderContext& context, const std::vector<int>& wanted, ProgressBar& progress);
    void solve(const RenderContext& context, const std::vector<int>& wanted, int openFrom, ProgressBar& progress);
    // What the display shows of (light, bounce) at a patch point on `side`: the element's value
    // (flat) or the vertex values interpolated there (gouraud), scaled per element (smooth).
    Rgb shownRadiance(std::size_t light, int bounce, const PatchLookup& at, int side) const;
    // The diffuse reflectance at the hit toward the ray's origin over the mean its element was
    // solved with, per channel (1: a constant Lambertian kd): a texture or vertex colour the
    // patch's radiosity averages, and a base that reflects less at grazing views (under a GGX
    // layer or a coat), read back at the point for the direction it is seen from.
    Rgb reflectanceRatio(const SurfaceHit& hit, const Ray& ray, std::uint32_t cluster, const RenderContext& context) const;
    // Emits bounces 1..last of every wanted light as shown at `at`, times `weight`, with an
    // unlabelled D event between them; the path's last event is the point's own reflection.
    // gathered: read as the solve's gather reads it (gatheredRadiance), else as the display shows it.
    void emitSolution(const Vec3& point, const PatchLookup& at, int side, int last, const Rgb& weight, bool gathered,
                      PathState& path) const;
    // (light, bounce) at a patch point as the solve's own gather reads it (solve): the element's
    // value, or the Gouraud plane scaled to exactly the element's mean, or a triangle's fitted
    // gradient. The final gather reads this, so the image's later bounces average the same field
    // the solve's bounces were made from (the display's smoothing, tuned to hide noise, is not).
    Rgb gatheredRadiance(std::size_t light, int bounce, const PatchLookup& at, int side) const;
    // Per (light, bounce) slot below bounces_, what the solve's gather reads (and gatheredRadiance):
    // the exact scale of the Gouraud plane per element (empty: constant elements) and the fitted
    // triangles' corners, cornerSlot per patch side 2 * patch + side (kNoTarget in radiosity.cpp:
    // none fitted; empty: no gradients).
    struct GatherField {
        std::vector<Rgb> scale;
        std::vector<std::uint32_t> cornerSlot;
        std::vector<std::array<Rgb, 3>> corners;
        // The light at a point of patch side (patch, side), vertex weights `weights`, of the bounce
        // whose vertex values start at `vertex` (vertexValueIndex(light, bounce, 0, 0)).
        Rgb at(const RadiosityPatch& patch, std::uint32_t patchIndex, int side, const std::array<float, 4>& weights,
               const Rgb* vertex) const;
    };
    // The field of (light, bounce) from its values and vertex values (computed before);
    // gradients: the triangles' fits, or nullptr for the scaled plane alone.
    GatherField makeGatherField(std::size_t light, int bounce, const PatchGradients* gradients) const;
    // After the last solve: the fields the final gather reads that the solve's own gather did not
    // make (each light's last solved bounce); none without a final gather.
    void completeGatherFields();
    // With the final gather, bounce 1 at a camera hit: every wanted light's direct light there,
    // sampled as the patches' own is (radiosity.cpp, addDirectOverKd), times the hit's kd.
    // `seen`: what weighs the light arriving there (its kd, or its own diffuse part per direction).
    void emitDirectLight(const SurfaceHit& hit, int side, const SeenPoint& seen, PathState& path) const;
    // The final gather (RadiosityOptions::finalGather): bounces 2..bounces_ at a camera hit, each
    // ray labelled by the object it meets and reading the solution's bounces there.
    void gatherLaterBounces(const SurfaceHit& hit, int side, const SeenPoint& seen, PathState& path) const;
    // The vertex radiosities (vertexValues_) of every solved light and bounce, or of one.
    void computeVertexValues();
    void computeVertexValues(std::size_t light, int bounce);
    // Per element, the area-weighted mean over its patches of their vertex values' mean: what
    // Gouraud shows across it, on average (light, bounce: its vertex values must be computed).
    void gouraudMeans(std::size_t light, int bounce, std::vector<Rgb>& shown) const;
    // displayScale_ from values_ and vertexValues_ (the smooth display's per-element scale), its
    // correction shrunk by the elements' sampling noise (noise: valueNoise's, of this solve).
    void computeDisplayScale(const std::vector<float>& noise);
    void computeReflectance(const RenderContext& context);
    // The variance of each solved value's luminance (valueIndex order) from its own samples: the
    // direct light's (directNoise_) and, for later bounces, the form-factor rays' (rayTargets_).
    std::vector<float> valueNoise(int threads) const;
    // What a refinement pass cuts: a patch into four (RadiosityMesh::split) or a cluster into the
    // eighths of its cell (RadiosityMesh::splitClusters).
    struct RefineCut {
        float priority;
        std::uint32_t id;
        bool cluster;
    };
    // The patches and clusters the error estimate asks to cut, most urgent first.
    std::vector<RefineCut> refinementCuts(int threads) const;
    // The clusters' part of it: each part's (eighth's) own estimate against the cluster's value,
    // per light, bounce and side, floors[light * bounces_ + bounce - 1] as in refinementCuts.
    void clustersToRefine(const std::vector<float>& floors, std::vector<RefineCut>& out) const;

    std::optional<RadiosityMesh> mesh_;
    RadiosityOptions options_;  // of this render: the context's, with its parameters applied
    RadiosityDisplay display_ = RadiosityDisplay::Smooth;
    std::vector<Rgb> reflectance_;  // per cluster: its object's material's kd
    // Form factors, one sparse row per element: targets_[rowStart_[e] .. rowStart_[e+1]).
    std::vector<std::uint64_t> rowStart_;
    std::vector<std::uint32_t> targets_;
    std::vector<float> factors_;
    // The same rays by the patch side they hit (RadiosityOptions::reconstructGather): per element
    // gatherStart_[e] .. gatherStart_[e+1] of gatherHits_, each a hit side 2 * patch + side and the
    // sum over the rays that met it of their vertex weights there, over the element's rays.
    struct GatherHit {
        std::uint32_t side;
        std::array<float, 4> weights;
    };
    std::vector<std::uint64_t> gatherStart_;
    std::vector<GatherHit> gatherHits_;
    int bounces_ = 0;                 // bounces kept (1..bounces_), the same for every light
    std::vector<int> solvedBounces_;  // per light: bounces 1..solvedBounces_[l] hold its light
    std::vector<Rgb> values_;         // valueIndex(light, bounce, element)
    std::vector<Rgb> vertexValues_;   // vertexValueIndex(light, bounce, vertex, side)
    // The smooth display's scale of the interpolated value, per channel, valueIndex order: the
    // element's radiosity over the mean Gouraud shows across it, shrunk towards 1 where that
    // difference is within the sampling noise (computeDisplayScale).
    std::vector<Rgb> displayScale_;
    // The final gather's fields (RadiosityOptions::finalGather; empty without it), slot order: the
    // last solve's own, completed by completeGatherFields.
    std::vector<GatherField> gatherFields_;
    // For the noise estimate (filled by the refinement passes' solves, and by the last solve under
    // the smooth display, whose scale uses it; freed after preprocess): the
    // variance of each element's direct light, valueIndex(light, 1, element), and each form-factor
    // ray's target element (kNoTarget: it met nothing), rayTargets_[element * raysPerElement_ + k]
    // for ray k of its stratified pattern.
    std::vector<float> directNoise_;
    std::vector<std::uint32_t> rayTargets_;
    std::uint32_t raysPerElement_ = 0;
    // For the clusters' error estimate (refinement passes with RadiosityOptions::refineClusters):
    // per cluster its slot among those splitClusters can cut (kNoSlot: none), per ray of those
    // its origin's part (RadiosityMesh::clusterPart), and per (light, slot, side, part) the sums of
    // its direct-light samples, partSlot(light, slot, side, part).
    struct PartSums {
        float sum = 0.0f, squares = 0.0f;
        std::uint32_t count = 0;
        void add(float x) {
            sum += x;
            squares += x * x;
            ++count;
        }
    };
    static constexpr std::uint32_t kNoSlot = ~std::uint32_t{0};
    std::vector<std::uint32_t> splitSlot_;
    std::uint32_t splitSlots_ = 0;
    std::vector<std::uint8_t> rayParts_;
    std::vector<PartSums> directParts_;
    std::size_t partSlot(std::size_t light, std::uint32_t slot, int side, std::uint32_t part) const {
        return ((light * splitSlots_ + slot) * 2 + std::size_t(side)) * 8 + part;
    }
    RadiosityStats stats_;
};

}  // namespace lightpath
