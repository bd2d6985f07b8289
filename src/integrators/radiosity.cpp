#include "integrators/radiosity.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "geometry/spawn_ray.h"
#include "integrators/direct_light.h"
#include "integrators/radiosity_gradients.h"
#include "integrators/registry.h"
#include "integrators/shading_point.h"
#include "math/random.h"
#include "util/progress.h"
#include "sampling/warp.h"
#include "util/parallel_chunks.h"

namespace lightpath {

// The point the camera sees, as the final gather weighs the light arriving there: by its kd
// (`albedo`: its patch's, times the texture there), or, where its material's diffuse part depends
// on the directions (Material::diffuseDependsOnView: a base under a GGX layer or a coat), by that
// part for each direction toward the eye (`bsdf` set), pi f.
struct SeenPoint {
    Rgb albedo{0.0f};
    const Bsdf* bsdf = nullptr;
    Vec3 wo{0.0f};
    Rgb from(const Vec3& wi) const { return bsdf->diffuseReflectanceBetween(wo, wi); }
};

namespace {

// More patches than this would need gigabytes of form factors: refused with a clear message.
constexpr std::size_t kMaxPatches = std::size_t{1} << 18;
// Refinement (preprocess): the first mesh is the budget's (or the size the user set); refining
// may grow it to kRefineGrowth times its elements where the error estimate asks. Below
// kRefineFloor of a bounce's mean radiosity, a patch's error is measured against that fraction
// instead (refinementCuts).
constexpr std::size_t kRefineGrowth = 4;
// Bounces the refinement passes solve (of every light) to decide where to cut.
constexpr int kRefineBounces = 4;
constexpr float kRefineFloor = 0.1f;
// A form-factor ray that met no patch (RadiosityIntegrator::rayTargets_).
constexpr std::uint32_t kNoTarget = ~std::uint32_t{0};
// Elements handed to a worker at a time, and one progress step.
constexpr std::uint32_t kChunk = 256;
// The display scale's test statistic of an element whose value has no sampling noise and differs
// from Gouraud's: far beyond any threshold (computeDisplayScale), kept finite so sums stay finite.
constexpr float kUnboundedZ = 1e6f;

// Gouraud's plane at a point of a patch side: its vertex values (`vertex`, one bounce's,
// vertexValueIndex order) weighed by the point's vertex weights.
Rgb gouraudPlane(const RadiosityPatch& patch, int side, const std::array<float, 4>& weights, const Rgb* vertex) {
    Rgb plane{0.0f};
    for (int v = 0; v < patch.vertexCount; ++v) plane += weights[v] * vertex[2 * std::size_t(patch.vertices[v]) + side];
    return plane;
}

// Runs work(begin, end) over [0, count) in chunks of kChunk on `threads` workers (0: all), one
// progress step per chunk; once `cancel` is set, the chunks left are skipped.
template <class Work>
void solveInChunks(std::uint32_t count, int threads, const std::atomic<bool>* cancel, ProgressBar& progress, Work work) {
    parallelChunks(count, kChunk, threadsOrAll(threads), [&](std::size_t begin, std::size_t end) {
        if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) return;
        work(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end));
        progress.tileDone();
    });
}

std::uint32_t chunkCount(std::uint32_t count) { return (count + kChunk - 1) / kChunk; }

// A stratified pattern of `side` x `side` points in [0,1)^2, one jittered point per cell: cell k.
Vec2 stratum(std::uint32_t k, std::uint32_t side, Pcg32& rng) {
    return {(float(k % side) + rng.nextFloat()) / float(side), (float(k / side) + rng.nextFloat()) / float(side)};
}

// A random permutation of 0..n-1 (Fisher-Yates), pairing two stratified patterns without
// correlating them.
void shuffle(std::vector<std::uint32_t>& order, Pcg32& rng) {
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.nextUint() % i]);
}

std::uint32_t strataPerSide(int samples) {
    return std::max(1u, static_cast<std::uint32_t>(std::lround(std::sqrt(double(std::max(samples, 1))))));
}

// A surface point of a patch as the ray-spawning code expects it.
SurfaceHit surfacePoint(const RadiosityPatch& patch, const PatchPoint& p) {
    SurfaceHit hit;
    hit.point = p.point;
    hit.normal = p.normal;
    hit.shadingNormal = p.normal;
    hit.object = patch.object;
    hit.primitive = patch.primitive;
    return hit;
}

// Radiance a Lambertian point `from` reflects from `light` on the side `normal` faces, over its kd:
// (1/pi) cos(theta) times a light sample's weight, plus, for an area light, the emitter's radiance
// met by a cosine-distributed ray (f cos / pdf = 1): two techniques weighed by Veach's power
// heuristic (Veach 1997, ch. 9), so neither the 1/d^2 of points near the emitter nor small bright
// emitters make the estimate noisy. Added to `sum` term by term; `cast` counts the rays. With a
// `seen` point, each term is weighed by its pi f for the term's direction instead of over kd.
void addDirectOverKd(const Light& light, const RenderContext& context, const SurfaceHit& from, const Vec3& normal,
                     Vec2 uLight, Vec2 uCosine, Rgb& sum, std::uint64_t& cast, const SeenPoint* seen = nullptr) {
    const LightSample s = light.sample(from.point, uLight);
    const float cosTheta = glm::dot(normal, s.wi);
    if (s.distance > 0.0f && cosTheta > 0.0f && !isBlack(s.weight)) {
        ++cast;
        if (!context.geometry.occluded(spawnShadowRay(from, s.point, s.normal, context.geometry.numerics()))) {
            const float weight = light.isDelta() ? 1.0f : powerHeuristic(s.pdf, cosineHemispherePdf(cosTheta));
            const Rgb term = (weight * cosTheta / kPi) * s.weight;
            sum += seen != nullptr ? term * seen->from(s.wi) : term;
        }
    }
    if (light.isDelta()) return;
    const Vec3 local = sampleCosineHemisphere(uCosine);
    const Vec3 direction = Frame(normal).toWorld(local);
    ++cast;
    const auto hit = context.geometry.intersect(spawnRay(from, direction, context.geometry.numerics()));
    if (!hit || context.lights.lightOfObject(hit->object) != &light) return;
    const Rgb emitted = light.radiance(*hit, -direction);
    if (isBlack(emitted)) return;
    const float lightPdf = light.pdf(from.point, hit->point, hit->normal);
    const Rgb term = powerHeuristic(cosineHemispherePdf(local.z), lightPdf) * emitted;
    sum += seen != nullptr ? term * seen->from(direction) : term;
}

// 0 when a ray travelling along `direction` meets the front side (the side the normal faces).
int sideFacing(const Vec3& normal, const Vec3& direction) { return glm::dot(normal, direction) < 0.0f ? 0 : 1; }

PathEvent unlabelledDiffuse(const Vec3& position) {
    return {lpe::EventType::Reflection, lpe::Scatter::Diffuse, Subject::None, 0, position};
}

// What the mesh could not resolve, as one sentence (empty: nothing). Issue 27: a mesh over the
// budget left every wall as 2 patches, 10-18% off, without a word. Now the budget's patch size
// merges the triangles smaller than it into clusters, whose shading inside is averaged away (a
// size the user set is what they asked for); and a cluster of more triangles than the light
// samples that gather its direct light leaves some of them unsampled, at any size.
std::string unresolvedMesh(const RadiosityMesh& mesh, const RadiosityOptions& options, std::uint32_t lightSamples) {
    std::size_t merged = 0, clusters = 0, largest = 0, undersampled = 0;
    for (const RadiosityCluster& c : mesh.clusters()) {
        if (c.memberCount < 2) continue;
        merged += c.memberCount;
        ++clusters;
        largest = std::max<std::size_t>(largest, c.memberCount);
        if (c.memberCount > lightSamples) ++undersampled;
    }
    const bool byBudget = options.patchSize <= 0.0f && clusters > 0;
    if (!byBudget && undersampled == 0) return {};
    char text[600];
    if (byBudget) {
        std::snprintf(text, sizeof text,
                      "radiosity: the budget of %zu elements kept patches at %.4g: %zu triangles smaller than that are "
                      "merged into %zu clusters (up to %zu triangles each), their shading averaged",
                      options.patchBudget, double(mesh.patchSize()), merged, clusters, largest);
    } else {
        std::snprintf(text, sizeof text, "radiosity: at patch size %.4g, %zu triangles are merged into %zu clusters",
                      double(mesh.patchSize()), merged, clusters);
    }
    std::string sentence = text;
    if (undersampled > 0) {
        std::snprintf(text, sizeof text,
                      "; %zu of them hold more triangles than the %u light samples that gather each, so some of "
                      "their triangles are never sampled",
                      undersampled, lightSamples);
        sentence += text;
    }
    return sentence + (byBudget ? "; raise --patches or set --patch-size" : "; set a smaller --patch-size or raise --light-samples");
}

}  // namespace

RadiosityOptions radiosityOptions(const ParameterValues& parameters, RadiosityOptions base) {
    base.patchSize = parameters.number("patch-size");
    base.patchBudget = static_cast<std::size_t>(parameters.integer("patches"));
    base.formFactorRays = parameters.integer("form-factor-rays");
    base.lightSamples = parameters.integer("light-samples");
    base.refineRounds = parameters.integer("refine");
    base.finalGather = parameters.integer("final-gather");
    const std::string display = parameters.text("radiosity-display");
    base.display = display == "flat"      ? RadiosityDisplay::Flat
                   : display == "gouraud" ? RadiosityDisplay::Gouraud
                                          : RadiosityDisplay::Smooth;
    return base;
}

void RadiosityIntegrator::preprocess(const RenderContext& context) {
    const auto started = std::chrono::steady_clock::now();
    options_ = context.parameters ? radiosityOptions(*context.parameters, context.radiosity) : context.radiosity;
    const RadiosityOptions& options = options_;
    display_ = options.display;
    stats_ = {};
    // The first mesh is uniform, within the budget or at the size the user set; refining then
    // cuts where the error estimate asks, up to kRefineGrowth times the first mesh's elements.
    const int rounds = std::max(options.refineRounds, 0);
    const std::vector<std::uint8_t> buried = options.separateBuried
                                                 ? RadiosityMesh::buriedTriangles(context.geometry, context.threads)
                                                 : std::vector<std::uint8_t>{};
    const float patchSize = options.patchSize > 0.0f
                                ? options.patchSize
                                : RadiosityMesh::patchSizeForBudget(context.scene, context.geometry, options.patchBudget,
                                                                    options.planeRings, buried, options.cutPlanes);
    const std::size_t count = RadiosityMesh::countClusters(context.scene, context.geometry, patchSize, options.planeRings,
                                                           buried, options.cutPlanes);
    if (count > kMaxPatches)
        throw std::invalid_argument("radiosity: patch size " + std::to_string(patchSize) + " makes " +
                                    std::to_string(count) + " elements, more than the " + std::to_string(kMaxPatches) +
                                    " radiosity can hold; choose a larger --patch-size or a smaller --patches");
    mesh_.emplace(context.scene, context.geometry, patchSize, options.planeRings, buried, options.cutPlanes);
    const std::size_t elementCap = std::min(kMaxPatches, kRefineGrowth * mesh_->clusters().size());
    stats_.patchSize = patchSize;
    computeReflectance(context);

    int openFrom = 1;
    const std::vector<int> wanted = wantedBounces(context, openFrom);
    const int wantedMost = wanted.empty() ? 0 : *std::max_element(wanted.begin(), wanted.end());
    // Refinement decides on every light and its first kRefineBounces bounces, whatever the outputs
    // request, so the mesh (and an AOV's image) is the same whichever AOVs are rendered; the last
    // solve, on the refined mesh, solves only what is requested.
    const bool refining = rounds > 0 && wantedMost > 0;
    const std::vector<int> everything(wanted.size(), std::min(context.maxDepth, kRefineBounces));
    const auto passesFor = [](const std::vector<int>& w) {
        const int most = w.empty() ? 0 : *std::max_element(w.begin(), w.end());
        int passes = most > 1 ? 1 : 0;
        for (int b : w) passes += std::max(b, 0);  // its direct light, then b - 1 bounces
        return passes;
    };

    // Progress steps: chunks of form factors, of each light's direct light, and of each later
    // (light, bounce), per solve; a solve's elements are taken as growing 4x a round up to the
    // cap (the tolerance or the error estimate may stop sooner: the bar then ends early).
    int steps = 0;
    std::size_t elementsGuess = mesh_->clusters().size();
    for (int round = 0; round < (refining ? rounds : 0); ++round, elementsGuess = std::min(elementCap, 4 * elementsGuess))
        steps += static_cast<int>(chunkCount(static_cast<std::uint32_t>(2 * elementsGuess))) * passesFor(everything);
    steps += static_cast<int>(chunkCount(static_cast<std::uint32_t>(2 * elementsGuess))) * passesFor(wanted);
    ProgressBar progress(steps, context.progress, "radiosity steps", context.preprocessSteps);
    // deciding: a refinement pass's solve. Both it and the last solve under the smooth display keep
    // what the noise estimate needs (valueNoise): the error estimate and the display scale use it.
    const bool displayNoise = display_ == RadiosityDisplay::Smooth;
    const auto solveFor = [&](const std::vector<int>& w, bool deciding) {
        const bool keepNoise = deciding || displayNoise;
        bounces_ = w.empty() ? 0 : *std::max_element(w.begin(), w.end());
        solvedBounces_.assign(w.size(), 0);
        stats_.lightsSolved = static_cast<int>(std::count_if(w.begin(), w.end(), [](int b) { return b > 0; }));
        stats_.formFactorRays = 0;
        values_.assign(w.size() * std::size_t(bounces_) * elementCount(), Rgb{0.0f});
        directNoise_.assign(keepNoise ? values_.size() : 0, 0.0f);
        splitSlot_.assign(deciding && options.refineClusters ? mesh_->clusters().size() : 0, kNoSlot);
        splitSlots_ = 0;
        for (std::uint32_t c = 0; c < splitSlot_.size(); ++c)
            if (mesh_->clusterSplittable(c)) splitSlot_[c] = splitSlots_++;
        rayParts_.clear();
        directParts_.assign(std::size_t(splitSlots_) * w.size() * 2 * 8, PartSums{});
        rayTargets_.clear();
        raysPerElement_ = 0;
        rowStart_.assign(std::size_t(elementCount()) + 1, 0);
        targets_.clear();
        factors_.clear();
        gatherStart_.assign(std::size_t(elementCount()) + 1, 0);
        gatherHits_.clear();
        vertexValues_.assign(w.size() * std::size_t(bounces_) * 2 * mesh_->vertexCount(), Rgb{0.0f});
        if (bounces_ == 0) return;
        // Direct light alone (every wanted path is E D L) needs no form factors.
        if (bounces_ > 1) computeFormFactors(context, progress, keepNoise);
        gatherDirectLight(context, w, progress);
        solve(context, w, openFrom, progress);
        computeVertexValues();
    };
    std::size_t capped = 0;  // patches and clusters the last refinement pass asked to cut beyond the cap
    for (int round = 0; refining && round < rounds; ++round) {
        solveFor(everything, true);
        if (context.cancel != nullptr && context.cancel->load(std::memory_order_relaxed)) break;
        // Most urgent first while the cap has room: a patch cut adds three elements, a cluster cut
        // one fewer than its parts.
        std::size_t room = elementCap > mesh_->clusters().size() ? elementCap - mesh_->clusters().size() : 0;
        std::vector<std::uint32_t> patchCuts, clusterCuts;
        capped = 0;
        for (const RefineCut& c : refinementCuts(context.threads)) {
            const std::size_t adds = c.cluster ? mesh_->clusterParts(c.id) - 1 : 3;
            if (adds > room) {
                ++capped;
                continue;
            }
            room -= adds;
            (c.cluster ? clusterCuts : patchCuts).push_back(c.id);
        }
        if (patchCuts.empty() && clusterCuts.empty()) break;
        mesh_->split(patchCuts);
        mesh_->splitClusters(clusterCuts);
        computeReflectance(context);
        stats_.refined += patchCuts.size();
        stats_.clustersCut += clusterCuts.size();
        stats_.refineRounds = round + 1;
    }
    solveFor(wanted, false);
    if (displayNoise) computeDisplayScale(valueNoise(context.threads));
    completeGatherFields();
    directNoise_ = {};
    gatherStart_ = {};
    gatherHits_ = {};
    rayTargets_ = {};
    rayParts_ = {};
    directParts_ = {};
    // What the final mesh could not resolve: its clusters (fewer and smaller where refinement cut them).
    const std::uint32_t lightSamples = strataPerSide(options.lightSamples) * strataPerSide(options.lightSamples);
    stats_.unresolved = unresolvedMesh(*mesh_, options, lightSamples);
    if (capped > 0) {
        char text[400];
        std::snprintf(text, sizeof text,
                      "radiosity: refinement stopped at %zu elements (%zux the first mesh's) with %zu more patches "
                      "or clusters to cut: the light changes across them (shadow edges, contact lines, beside emitters) by over "
                      "%.3g%%%s, so the display smooths it; raise --patches for a finer first mesh, or --refine 0 "
                      "for the uniform mesh",
                      mesh_->clusters().size(), kRefineGrowth, capped, 100.0 * options.refineTolerance,
                      options.refineNoiseSigmas > 0.0 ? " and by more than their sampling noise" : "");
        stats_.unresolved += (stats_.unresolved.empty() ? "" : "; ") + std::string(text);
    }
    stats_.patches = mesh_->patches().size();
    stats_.clusters = mesh_->clusters().size();
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void RadiosityIntegrator::computeReflectance(const RenderContext& context) {
    reflectance_.clear();
    for (const RadiosityCluster& c : mesh_->clusters()) {
        const Material& material = *context.scene.materials[context.scene.objects[c.object].material];
        Rgb rho = material.diffuseReflectance();
        if (material.vertexColored) {
            // Times the area-weighted mean of the vertex colour at its patches' centroids.
            Rgb colour{0.0f};
            float area = 0.0f;
            for (const std::uint32_t p : mesh_->membersOf(c)) {
                const RadiosityPatch& patch = mesh_->patches()[p];
                SurfaceHit centre;
                centre.primitive = patch.primitive;
                centre.point = (patch.a + patch.b + patch.c) / 3.0f;
                colour += patch.area * context.geometry.vertexColorAt(centre);
                area += patch.area;
            }
            if (area > 0.0f) rho *= colour / area;
        }
        reflectance_.push_back(rho);
    }
}

std::vector<float> RadiosityIntegrator::valueNoise(int threads) const {
    // Bounce 1: the light samples' own estimate (gatherDirectLight). Bounce k > 1 of element e is
    // rho_e times the mean of B_{k-1} over its N form-factor rays' targets, so its variance is
    // estimated from those rays: pairs of neighbouring direction strata (k, k + 1), each pair's
    // squared difference over N^2 (the collapsed-strata estimator, as for the direct light), plus
    // the noise the targets' own values carry, sum_j F_ej^2 var(B_j) times rho_e's luminance
    // squared (the colour's mix neglected: an estimate, not a bound). Each ray is read at its
    // target element's value B_j, as the constant gather read it: the reconstructed gather (solve)
    // reads the plane at the hit, which varies over the element too, so this slightly
    // underestimates the spread between the rays.
    std::vector<float> noise(values_.size(), 0.0f);
    const std::uint32_t elements = elementCount();
    const std::uint32_t rays = raysPerElement_;
    for (std::size_t l = 0; l < solvedBounces_.size(); ++l) {
        if (solvedBounces_[l] < 1) continue;
        for (std::uint32_t e = 0; e < elements; ++e) noise[valueIndex(l, 1, e)] = directNoise_[valueIndex(l, 1, e)];
        for (int k = 2; k <= solvedBounces_[l] && rays > 0; ++k) {
            const Rgb* previous = &values_[valueIndex(l, k - 1, 0)];
            const float* previousNoise = &noise[valueIndex(l, k - 1, 0)];
            float* out = &noise[valueIndex(l, k, 0)];
            parallelChunks(elements, kChunk, threadsOrAll(threads), [&](std::size_t begin, std::size_t end) {
                for (std::size_t e = begin; e < end; ++e) {
                    const Rgb rho = reflectance_[e / 2];
                    if (isBlack(rho)) continue;
                    const std::uint32_t* target = &rayTargets_[e * rays];
                    const auto reflected = [&](std::uint32_t r) {
                        return target[r] == kNoTarget ? 0.0f : luminance(rho * previous[target[r]]);
                    };
                    float pairs = 0.0f;
                    for (std::uint32_t r = 0; r + 1 < rays; r += 2) {
                        const float d = reflected(r) - reflected(r + 1);
                        pairs += d * d;
                    }
                    float carried = 0.0f;
                    for (std::uint64_t i = rowStart_[e]; i < rowStart_[e + 1]; ++i)
                        carried += factors_[i] * factors_[i] * previousNoise[targets_[i]];
                    const float albedo = luminance(rho);
                    out[e] = pairs / (float(rays) * float(rays)) + albedo * albedo * carried;
                }
            });
        }
    }
    return noise;
}

std::vector<RadiosityIntegrator::RefineCut> RadiosityIntegrator::refinementCuts(int threads) const {
    // The error estimate: Gouraud shading shows, over a triangle, the plane through its vertices'
    // values (each the area-weighted mean of the patches around the vertex), whose mean over the
    // triangle is the mean of those values. Where the light varies linearly, that mean is the
    // patch's own radiosity B; where the plane cannot follow it (a shadow's edge, a contact line,
    // the curve of an emitter's falloff), the two differ, and the patch is cut when they differ by
    // more than the tolerance times B (Hanrahan, Salzman and Aupperle 1991 refine where the
    // transported light's error estimate exceeds a bound; here the bound is relative, as the error
    // that matters on screen is). A vertex value's own difference from B (issue 27's first
    // estimate) measured the light's slope, which the plane already shows, and asked for cuts all
    // over a wall beside a lamp. Checked per light and bounce, as each is its own output; patches
    // darker than a tenth of their bounce's mean (over the lit area) are held to that floor.
    // And the difference must exceed options_.refineNoiseSigmas standard deviations of its
    // sampling noise: it is d = sum_j c_j B_j - B over the patches j around the vertices (c_j:
    // their area shares, averaged over the vertices), of variance sum_{j != p} c_j^2 var(B_j) +
    // (1 - c_p)^2 var(B) (the patches' estimates independent: each casts its own rays). Without
    // it, the form factors' noise alone kept asking for cuts on the Cornell box's dim sides. (The
    // shares c_j count every patch around a vertex, the unlit ones too: a slight underestimate
    // of the noise beside them.)
    // Patches with the largest relative error times area go first.
    const auto& patches = mesh_->patches();
    const std::uint32_t elements = elementCount();
    const int maxLevel = options_.refineRounds;
    const float sigmas = float(std::max(options_.refineNoiseSigmas, 0.0));
    const auto& clusters = mesh_->clusters();
    const std::vector<float> noise = sigmas > 0.0f ? valueNoise(threads) : std::vector<float>{};
    // The patches around each vertex, and per candidate patch its weights c_j.
    std::vector<float> vertexArea(mesh_->vertexCount(), 0.0f);
    for (const RadiosityPatch& p : patches)
        for (int v = 0; v < p.vertexCount; ++v) vertexArea[p.vertices[v]] += p.area;
    const auto [aroundStart, around] = mesh_->patchesAroundVertices();
    struct Weight {
        std::uint32_t patch;
        float share;
    };
    std::vector<std::uint64_t> weightStart(1, 0);
    std::vector<Weight> weights;
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t p = 0; p < patches.size(); ++p) {
        const RadiosityPatch& patch = patches[p];
        if (int(patch.level) >= maxLevel || !mesh_->splittable(p)) continue;
        candidates.push_back(p);
        const std::size_t first = weights.size();
        for (int v = 0; v < patch.vertexCount; ++v) {
            const std::uint32_t vertex = patch.vertices[v];
            for (std::uint32_t i = aroundStart[vertex]; i < aroundStart[vertex + 1]; ++i) {
                const std::uint32_t q = around[i];
                const float share = patches[q].area / (vertexArea[vertex] * float(patch.vertexCount));
                auto found = std::find_if(weights.begin() + std::ptrdiff_t(first), weights.end(),
                                          [&](const Weight& w) { return w.patch == q; });
                if (found == weights.end()) {
                    weights.push_back({q, share});
                } else {
                    found->share += share;
                }
            }
        }
        weightStart.push_back(weights.size());
    }
    std::vector<float> worst(candidates.size(), 0.0f);
    // Per light and bounce (slot order): kRefineFloor of its mean over the lit area; 0: nothing lit.
    std::vector<float> floors(solvedBounces_.size() * std::size_t(bounces_), 0.0f);
    for (std::size_t l = 0; l < solvedBounces_.size(); ++l) {
        for (int k = 1; k <= solvedBounces_[l]; ++k) {
            double flux = 0.0, litArea = 0.0;
            for (std::uint32_t e = 0; e < elements; ++e) {
                const float b = luminance(values_[valueIndex(l, k, e)]);
                if (b <= 0.0f) continue;
                flux += double(clusters[e / 2].area) * b;
                litArea += clusters[e / 2].area;
            }
            if (!(litArea > 0.0)) continue;
            const float floor = kRefineFloor * float(flux / litArea);
            floors[slot(l, k)] = floor;
            for (std::size_t c = 0; c < candidates.size(); ++c) {
                const RadiosityPatch& patch = patches[candidates[c]];
                for (int side = 0; side < 2; ++side) {
                    const std::size_t element = valueIndex(l, k, 2 * patch.cluster + std::uint32_t(side));
                    const float b = luminance(values_[element]);
                    // Unlit here: left out of its vertices' values (computeVertexValues), it is
                    // only ever a neighbour's question.
                    if (isBlack(values_[element])) continue;
                    float shown = 0.0f;
                    for (int v = 0; v < patch.vertexCount; ++v)
                        shown += luminance(vertexValues_[vertexValueIndex(l, k, patch.vertices[v], side)]);
                    const float difference = std::fabs(shown / float(patch.vertexCount) - b);
                    float excess = difference / (std::max(b, floor) * float(options_.refineTolerance));
                    if (sigmas > 0.0f && excess > 1.0f) {
                        float variance = 0.0f;
                        for (std::uint64_t i = weightStart[c]; i < weightStart[c + 1]; ++i) {
                            const Weight& w = weights[i];
                            const float share = w.patch == candidates[c] ? 1.0f - w.share : w.share;
                            variance += share * share *
                                        noise[valueIndex(l, k, 2 * patches[w.patch].cluster + std::uint32_t(side))];
                        }
                        excess = std::min(excess, difference / (sigmas * std::sqrt(variance)));
                    }
                    worst[c] = std::max(worst[c], excess);
                }
            }
        }
    }
    std::vector<RefineCut> asking;
    for (std::size_t c = 0; c < candidates.size(); ++c)
        if (worst[c] > 1.0f) asking.push_back({worst[c] * patches[candidates[c]].area, candidates[c], false});
    if (splitSlots_ > 0) clustersToRefine(floors, asking);
    std::sort(asking.begin(), asking.end(), [](const RefineCut& a, const RefineCut& b) {
        if (a.priority != b.priority) return a.priority > b.priority;
        return a.cluster != b.cluster ? b.cluster : a.id < b.id;
    });
    return asking;
}

void RadiosityIntegrator::clustersToRefine(const std::vector<float>& floors, std::vector<RefineCut>& out) const {
    // A cluster's value is exact for the mean of the light over its members (RadiosityMesh), and
    // the display shows that one value over all of them, so its error is how far the light its
    // parts receive (the eighths of its cell, RadiosityMesh::splitClusters) is from it: each part's
    // own estimate, from the samples that started on it (the direct light's for bounce 1, the
    // form-factor rays' rho B_{k-1}(target) for bounce k > 1), against the cluster's value B. The
    // Gouraud estimate of refinementCuts sees none of this (a curved mesh's vertices weld with no
    // neighbour, so they show B). A cluster is cut when some part differs from B by more than the
    // tolerance (against max(B, floor), as for patches) and by more than refineNoiseSigmas standard
    // deviations of the part's mean (its samples' spread over their count: a part has a fraction
    // of the cluster's samples). Priority: the excess times the cluster's area, as for patches.
    const auto& clusters = mesh_->clusters();
    const float sigmas = float(std::max(options_.refineNoiseSigmas, 0.0));
    const std::uint32_t rays = raysPerElement_;
    for (std::uint32_t c = 0; c < clusters.size(); ++c) {
        const std::uint32_t slotOf = splitSlot_[c];
        if (slotOf == kNoSlot) continue;
        const Rgb rho = reflectance_[c];
        if (isBlack(rho)) continue;
        float worst = 0.0f;
        for (std::size_t l = 0; l < solvedBounces_.size(); ++l) {
            for (int k = 1; k <= solvedBounces_[l]; ++k) {
                const float floor = floors[slot(l, k)];
                for (int side = 0; side < 2; ++side) {
                    const std::uint32_t e = 2 * c + std::uint32_t(side);
                    if (isBlack(values_[valueIndex(l, k, e)])) continue;
                    const float b = luminance(values_[valueIndex(l, k, e)]);
                    std::array<PartSums, 8> parts{};
                    if (k == 1) {
                        for (std::uint32_t part = 0; part < 8; ++part) parts[part] = directParts_[partSlot(l, slotOf, side, part)];
                    } else if (rays > 0) {
                        const Rgb* previous = &values_[valueIndex(l, k - 1, 0)];
                        for (std::uint32_t r = 0; r < rays; ++r) {
                            const std::uint32_t target = rayTargets_[std::size_t(e) * rays + r];
                            parts[rayParts_[std::size_t(e) * rays + r]].add(
                                target == kNoTarget ? 0.0f : luminance(rho * previous[target]));
                        }
                    }
                    for (const PartSums& part : parts) {
                        if (part.count < 2) continue;
                        const float n = float(part.count), mean = part.sum / n;
                        const float difference = std::fabs(mean - b);
                        float excess = difference / (std::max(b, floor) * float(options_.refineTolerance));
                        if (sigmas > 0.0f && excess > 1.0f) {
                            const float variance = std::max(part.squares - n * mean * mean, 0.0f) / (n * (n - 1.0f));
                            if (variance > 0.0f) excess = std::min(excess, difference / (sigmas * std::sqrt(variance)));
                        }
                        worst = std::max(worst, excess);
                    }
                }
            }
        }
        if (worst > 1.0f) out.push_back({worst * clusters[c].area, c, true});
    }
}

std::vector<int> RadiosityIntegrator::wantedBounces(const RenderContext& context, int& openFrom) const {
    const auto lights = context.lights.all();
    std::vector<int> wanted(lights.size(), 0);
    openFrom = 1;
    if (context.maxDepth == 0) return wanted;
    // outputs[k]: the requested outputs some light's bounce k reaches.
    std::vector<lpe::OutputMask> outputs(std::size_t(context.maxDepth) + 1, lpe::OutputMask{});
    // Probe the automaton along E D_object D{k-1} L for every object that reflects: the paths
    // radiosity can show. A light no requested output accepts after any of them is not solved,
    // and neither is any bounce beyond the last one some output accepts.
    ContributionSink sink({});
    RayCounters counters;
    PathState path(context, sink, counters);
    if (!path.push({lpe::EventType::Camera, lpe::Scatter::None, Subject::None, 0, Vec3{0.0f}})) return wanted;
    // Objects with a patch that reflects: radiosity shows light only on those. One per automaton
    // symbol is probed: objects the expressions cannot tell apart are accepted alike.
    std::vector<bool> reflects(context.scene.objects.size(), false);
    for (std::size_t c = 0; c < mesh_->clusters().size(); ++c)
        if (!isBlack(reflectance_[c])) reflects[mesh_->clusters()[c].object] = true;
    const auto labelled = [](std::uint32_t object) {
        return PathEvent{lpe::EventType::Reflection, lpe::Scatter::Diffuse, Subject::Object, object, Vec3{0.0f}};
    };
    std::vector<PathEvent> surfaces;
    std::vector<lpe::Automaton::Symbol> symbols;
    for (std::uint32_t object = 0; object < reflects.size(); ++object) {
        if (!reflects[object]) continue;
        const lpe::Automaton::Symbol symbol = context.symbols(labelled(object));
        if (std::find(symbols.begin(), symbols.end(), symbol) != symbols.end()) continue;
        symbols.push_back(symbol);
        surfaces.push_back(labelled(object));
    }
    const auto accept = [&](int k) {
        for (std::size_t l = 0; l < lights.size(); ++l) {
            const lpe::OutputMask accepted = path.acceptsAfter(path.state(), lights[l]->event());
            if (!path.wanted(accepted)) continue;
            wanted[l] = std::max(wanted[l], k);
            outputs[std::size_t(k)] |= accepted;
        }
    };
    // The paths radiosity shows: E D_object D{k-1} L, the second reflection labelled by the object a
    // final gather ray meets (traceCameraRay), the later ones unlabelled (sums over every patch).
    const std::vector<PathEvent> seconds =
        options_.finalGather > 0 ? surfaces : std::vector<PathEvent>{unlabelledDiffuse(Vec3{0.0f})};
    for (const PathEvent& first : surfaces) {
        if (!path.push(first)) continue;
        accept(1);
        for (const PathEvent& second : seconds) {
            if (context.maxDepth < 2 || !path.push(second)) continue;
            for (int k = 2; k <= context.maxDepth; ++k) {
                accept(k);
                if (k == context.maxDepth || !path.push(unlabelledDiffuse(Vec3{0.0f}))) break;
            }
            while (path.size() > 2) path.pop();
        }
        path.pop();
    }
    const std::size_t deepest = outputs.size() - 1;
    std::size_t from = deepest;
    while (from > 1 && outputs[from - 1] == outputs[deepest]) --from;
    openFrom = static_cast<int>(from);
    return wanted;
}

void RadiosityIntegrator::computeFormFactors(const RenderContext& context, ProgressBar& progress, bool keepRays) {
    const std::uint32_t side = strataPerSide(options_.formFactorRays);
    const std::uint32_t rays = side * side;
    const std::uint32_t elements = elementCount();
    const auto& patches = mesh_->patches();
    if (keepRays) {
        raysPerElement_ = rays;
        rayTargets_.assign(std::size_t(elements) * rays, kNoTarget);
    }
    const bool keepParts = keepRays && splitSlots_ > 0;
    if (keepParts) rayParts_.assign(std::size_t(elements) * rays, 0);
    // The hit patches' sides and vertex weights too, for the reconstructed gather (solve).
    const bool reconstruct = options_.reconstructGather;
    // Each chunk writes its own rows; they are joined in element order afterwards.
    struct ChunkRows {
        std::vector<std::uint32_t> lengths, targets, gatherLengths;
        std::vector<float> factors;
        std::vector<GatherHit> gather;
        std::uint64_t rays = 0;
    };
    std::vector<ChunkRows> rows(chunkCount(elements));
    solveInChunks(elements, context.threads, context.cancel, progress, [&](std::uint32_t begin, std::uint32_t end) {
        ChunkRows& out = rows[begin / kChunk];
        std::vector<std::uint32_t> order(rays), hits;
        std::vector<GatherHit> gatherHits;
        hits.reserve(rays);
        for (std::uint32_t e = begin; e < end; ++e) {
            const std::uint32_t p = e / 2;
            hits.clear();
            gatherHits.clear();
            if (!isBlack(reflectance_[p])) {
                Pcg32 rng(mixBits(e), 0xf0f0u);
                shuffle(order, rng);
                for (std::uint32_t k = 0; k < rays; ++k) {
                    const PatchPoint point = mesh_->sampleClusterPoint(p, stratum(order[k], side, rng));
                    if (keepParts && splitSlot_[p] != kNoSlot)
                        rayParts_[std::size_t(e) * rays + k] = static_cast<std::uint8_t>(mesh_->clusterPart(point.patch));
                    const Vec3 normal = e % 2 == 0 ? point.normal : -point.normal;
                    const Vec3 direction = Frame(normal).toWorld(sampleCosineHemisphere(stratum(k, side, rng)));
                    const auto hit = context.geometry.intersect(
                        spawnRay(surfacePoint(patches[point.patch], point), direction, context.geometry.numerics()));
                    if (!hit) continue;
                    const auto found = mesh_->lookup(*hit);
                    if (!found) continue;
                    const std::uint32_t hitSide = std::uint32_t(sideFacing(hit->normal, direction));
                    const std::uint32_t target = 2 * patches[found->patch].cluster + hitSide;
                    hits.push_back(target);
                    if (reconstruct) gatherHits.push_back({2 * found->patch + hitSide, found->weights});
                    if (keepRays) rayTargets_[std::size_t(e) * rays + k] = target;
                }
                out.rays += rays;
            }
            std::sort(hits.begin(), hits.end());
            std::uint32_t length = 0;
            for (std::size_t i = 0; i < hits.size();) {
                std::size_t j = i;
                while (j < hits.size() && hits[j] == hits[i]) ++j;
                out.targets.push_back(hits[i]);
                out.factors.push_back(float(j - i) / float(rays));
                ++length;
                i = j;
            }
            out.lengths.push_back(length);
            // The rays that met one patch side merged: their vertex weights summed, over all the rays.
            std::sort(gatherHits.begin(), gatherHits.end(),
                      [](const GatherHit& a, const GatherHit& b) { return a.side < b.side; });
            std::uint32_t gathered = 0;
            for (std::size_t i = 0; i < gatherHits.size();) {
                GatherHit merged{gatherHits[i].side, {}};
                for (; i < gatherHits.size() && gatherHits[i].side == merged.side; ++i)
                    for (int v = 0; v < 4; ++v) merged.weights[v] += gatherHits[i].weights[v] / float(rays);
                out.gather.push_back(merged);
                ++gathered;
            }
            out.gatherLengths.push_back(gathered);
        }
    });
    rowStart_.assign(1, 0);
    targets_.clear();
    factors_.clear();
    gatherStart_.assign(1, 0);
    gatherHits_.clear();
    for (const ChunkRows& chunk : rows) {
        for (std::uint32_t length : chunk.lengths) rowStart_.push_back(rowStart_.back() + length);
        targets_.insert(targets_.end(), chunk.targets.begin(), chunk.targets.end());
        factors_.insert(factors_.end(), chunk.factors.begin(), chunk.factors.end());
        for (std::uint32_t length : chunk.gatherLengths) gatherStart_.push_back(gatherStart_.back() + length);
        gatherHits_.insert(gatherHits_.end(), chunk.gather.begin(), chunk.gather.end());
        stats_.formFactorRays += chunk.rays;
    }
    rowStart_.resize(std::size_t(elements) + 1, rowStart_.back());  // rows of a cancelled solve stay empty
    if (reconstruct) gatherStart_.resize(std::size_t(elements) + 1, gatherStart_.back());
}

void RadiosityIntegrator::gatherDirectLight(const RenderContext& context, const std::vector<int>& wanted,
                                            ProgressBar& progress) {
    const std::uint32_t side = strataPerSide(options_.lightSamples);
    const auto lights = context.lights.all();
    const auto& patches = mesh_->patches();
    std::vector<std::uint32_t> clusterLevel(mesh_->clusters().size(), 0);
    for (const RadiosityPatch& patch : patches) clusterLevel[patch.cluster] = std::max(clusterLevel[patch.cluster], patch.level);
    const std::uint32_t maxLevel = clusterLevel.empty() ? 0 : *std::max_element(clusterLevel.begin(), clusterLevel.end());
    std::atomic<std::uint64_t> shadowRays{0};
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (wanted[l] == 0) continue;
        const Light& light = *lights[l];
        solveInChunks(elementCount(), context.threads, context.cancel, progress, [&](std::uint32_t begin, std::uint32_t end) {
            std::vector<std::uint32_t> order;
            order.reserve(std::size_t(side) * side * (1 + maxLevel) * (1 + maxLevel));
            std::uint64_t cast = 0;
            for (std::uint32_t e = begin; e < end; ++e) {
                const std::uint32_t p = e / 2;
                if (isBlack(reflectance_[p])) continue;
                // A refined patch is where the light changes fast (near an emitter's 1/d^2, say):
                // (1 + level)^2 times the samples, so cutting it does not make its estimate noisier.
                const std::uint32_t strata = side * (1 + clusterLevel[p]);
                const std::uint32_t samples = strata * strata;
                order.resize(samples);
                Pcg32 rng(mixBits(e ^ (std::uint64_t(l) << 40)), 0x1165u);
                shuffle(order, rng);
                const auto sampleDirect = [&](std::uint32_t k, Rgb& sum, std::uint32_t& origin) {
                    const PatchPoint point = mesh_->sampleClusterPoint(p, stratum(k, strata, rng));
                    origin = point.patch;
                    const Vec2 uLight = stratum(order[k], strata, rng);
                    const Vec2 uCosine = light.isDelta() ? Vec2{0.0f} : Vec2{rng.nextFloat(), rng.nextFloat()};
                    addDirectOverKd(light, context, surfacePoint(patches[point.patch], point),
                                    e % 2 == 0 ? point.normal : -point.normal, uLight, uCosine, sum, cast);
                };
                // The noise estimate pairs samples of neighbouring point strata (k, k + 1: one row
                // of the pattern), each pair's squared difference estimating the variance of their
                // sum (the collapsed-strata estimator, Cochran 1977, 5A.12): unlike the spread of
                // independent samples it does not count as noise the light's change over the patch
                // that stratification already averages.
                // A cluster's samples are also summed per part, for its error estimate (clustersToRefine).
                const bool estimateNoise = !directNoise_.empty();
                const std::uint32_t partsSlot = directParts_.empty() ? kNoSlot : splitSlot_[p];
                Rgb sum{0.0f};
                float pairs = 0.0f, first = 0.0f;
                for (std::uint32_t k = 0; k < samples; ++k) {
                    const Rgb before = sum;
                    std::uint32_t origin = 0;
                    sampleDirect(k, sum, origin);
                    if (!estimateNoise) continue;
                    const float x = luminance(reflectance_[p] * (sum - before));
                    if (partsSlot != kNoSlot) directParts_[partSlot(l, partsSlot, int(e % 2), mesh_->clusterPart(origin))].add(x);
                    if (k % 2 == 0) {
                        first = x;
                    } else {
                        pairs += (x - first) * (x - first);
                    }
                }
                values_[valueIndex(l, 1, e)] = reflectance_[p] * sum / float(samples);
                if (estimateNoise) directNoise_[valueIndex(l, 1, e)] = pairs / (float(samples) * float(samples));
            }
            shadowRays += cast;
        });
        solvedBounces_[l] = 1;
    }
    stats_.shadowRays = shadowRays.load();
    stats_.iterations = 1;
    stats_.lightBouncesSolved = static_cast<int>(std::count_if(wanted.begin(), wanted.end(), [](int b) { return b > 0; }));
}

void RadiosityIntegrator::solve(const RenderContext& context, const std::vector<int>& wanted, int openFrom,
                                ProgressBar& progress) {
    const auto& clusters = mesh_->clusters();
    // Flux leaving all elements in one bounce, summed over lights (luminance, per unit pi).
    const auto flux = [&](int bounce) {
        double total = 0.0;
        for (std::size_t l = 0; l < wanted.size(); ++l) {
            if (wanted[l] < bounce) continue;
            for (std::uint32_t e = 0; e < elementCount(); ++e)
                total += double(clusters[e / 2].area) * luminance(values_[valueIndex(l, bounce, e)]);
        }
        return total;
    };
    // The tolerance bounds the light left out against the light so far of the outputs that would
    // receive it: those accepting every bounce from openFrom on. Against all the light (as before
    // issue 27's radiosity bullet), an open scene stopped too soon: the lecture room's bounce 4
    // added 1e-4 of the flux (most of its floor's light leaves for the sky), so bounces 5 and 6
    // were dropped and ED{4,}L came out 29% low against the path tracer at the same --max-depth.
    double solution = openFrom <= 1 ? flux(1) : 0.0;
    stats_.residual = flux(1) > 0.0 ? 1.0 : 0.0;
    // The reconstructed gather (options_.reconstructGather): bounce k-1's radiosity at a ray's hit
    // point x on patch p of element t is Gouraud's plane there, sum_v w_v(x) V_v (V_v the vertex
    // values, computeVertexValues), times B_t / G_t per channel (G_t: that plane's mean over t,
    // gouraudMeans), so each element still sends exactly its own flux (the plane's mean times the
    // scale is B_t: energy is kept bounce by bounce as with constant elements) but spread over it as
    // the light around it varies. With constant elements a receiver that sees mostly one part of an
    // element (a ball's underside and the floor beside its contact, where both are brightest) gets
    // the element's mean: each bounce between them lost light towards the open scene, the error of
    // the element's size (Heckbert and Winget 1991 on the piecewise-constant basis; higher order
    // reconstruction as in Zatz 1993's and Troutman and Max 1993's linear elements, here only for the
    // light sent, the element's own value staying its mean). Measured: szymczak-one-light's ED{4,}L
    // was 0.909 of the path tracer on the uniform mesh, 0.968 at 4x the elements, 0.982 at 16x.
    // A triangle patch solved on its own is read through its least-squares gradient instead
    // (options_.gatherGradients, radiosity_gradients.h): the plane through vertex means cannot rise
    // to a peak at an element's edge (the foot of szymczak's pyramid over the floor, where the two
    // exchange light at close range), since a vertex there averages only the patches beside it.
    const auto& patches = mesh_->patches();
    const bool reconstruct = gatherStart_.size() == std::size_t(elementCount()) + 1 && !gatherHits_.empty();
    std::optional<PatchGradients> gradients;
    if (reconstruct && options_.gatherGradients) gradients.emplace(*mesh_);
    // The final gather reads the same fields (gatheredRadiance): kept, not made twice.
    const bool keepFields = reconstruct && options_.finalGather > 0;
    gatherFields_.assign(keepFields ? wanted.size() * std::size_t(bounces_) : 0, GatherField{});
    GatherField field;
    for (int k = 2; k <= bounces_; ++k) {
        if (context.cancel != nullptr && context.cancel->load(std::memory_order_relaxed)) return;
        // Jacobi: bounce k = rho F (bounce k-1), per light (Cohen and Wallace 1993, 5.3).
        for (std::size_t l = 0; l < wanted.size(); ++l) {
            if (wanted[l] < k) continue;
            const Rgb* previous = &values_[valueIndex(l, k - 1, 0)];
            Rgb* next = &values_[valueIndex(l, k, 0)];
            if (reconstruct) {
                computeVertexValues(l, k - 1);
                field = makeGatherField(l, k - 1, gradients ? &*gradients : nullptr);
            }
            const Rgb* vertex = reconstruct ? &vertexValues_[vertexValueIndex(l, k - 1, 0, 0)] : nullptr;
            solveInChunks(elementCount(), context.threads, context.cancel, progress,
                           [&](std::uint32_t begin, std::uint32_t end) {
                               for (std::uint32_t e = begin; e < end; ++e) {
                                   Rgb gathered{0.0f};
                                   if (reconstruct) {
                                       for (std::uint64_t i = gatherStart_[e]; i < gatherStart_[e + 1]; ++i) {
                                           const GatherHit& h = gatherHits_[i];
                                           gathered += field.at(patches[h.side / 2], h.side / 2, int(h.side % 2),
                                                                h.weights, vertex);
                                       }
                                   } else {
                                       for (std::uint64_t i = rowStart_[e]; i < rowStart_[e + 1]; ++i)
                                           gathered += factors_[i] * previous[targets_[i]];
                                   }
                                   next[e] = reflectance_[e / 2] * gathered;
                               }
                           });
            if (keepFields) gatherFields_[slot(l, k - 1)] = std::move(field);
            solvedBounces_[l] = k;
            ++stats_.lightBouncesSolved;
        }
        stats_.iterations = k;
        const double added = flux(k);
        if (k < openFrom) continue;
        solution += added;
        stats_.residual = solution > 0.0 ? added / solution : 0.0;
        if (stats_.residual < options_.tolerance) break;
    }
}

void RadiosityIntegrator::computeVertexValues() {
    vertexValues_.assign(solvedBounces_.size() * std::size_t(bounces_) * 2 * mesh_->vertexCount(), Rgb{0.0f});
    for (std::size_t l = 0; l < solvedBounces_.size(); ++l)
        for (int k = 1; k <= solvedBounces_[l]; ++k) computeVertexValues(l, k);
}

void RadiosityIntegrator::gouraudMeans(std::size_t l, int k, std::vector<Rgb>& shown) const {
    const auto& patches = mesh_->patches();
    const auto& clusters = mesh_->clusters();
    shown.assign(elementCount(), Rgb{0.0f});
    for (const RadiosityPatch& p : patches)
        for (int side = 0; side < 2; ++side) {
            Rgb mean{0.0f};
            for (int v = 0; v < p.vertexCount; ++v) mean += vertexValues_[vertexValueIndex(l, k, p.vertices[v], side)];
            shown[2 * p.cluster + std::uint32_t(side)] += (p.area / float(p.vertexCount)) * mean;
        }
    for (std::uint32_t e = 0; e < elementCount(); ++e) shown[e] = shown[e] / clusters[e / 2].area;
}

void RadiosityIntegrator::computeVertexValues(std::size_t l, int k) {
    // A vertex's radiosity is the area-weighted mean of the patches around it (Cohen and Wallace
    // 1993, 9.3): what Gouraud shading interpolates. Patches that received none of this light and
    // bounce (the floor under a block, buried at the contact line) are left out of the mean: else
    // the visible floor beside the block darkens towards them, a contact line no mesh resolves
    // (refinement chased it to the element cap on the Cornell box).
    const auto& patches = mesh_->patches();
    std::vector<float> vertexArea(2 * mesh_->vertexCount(), 0.0f);
    for (std::size_t v = 0; v < mesh_->vertexCount(); ++v)
        for (int side = 0; side < 2; ++side) vertexValues_[vertexValueIndex(l, k, v, side)] = Rgb{0.0f};
    for (std::uint32_t patch = 0; patch < patches.size(); ++patch) {
        const RadiosityPatch& p = patches[patch];
        for (int side = 0; side < 2; ++side) {
            const Rgb& value = values_[valueIndex(l, k, 2 * p.cluster + std::uint32_t(side))];
            if (isBlack(value)) continue;
            const Rgb weighted = p.area * value;
            for (int v = 0; v < p.vertexCount; ++v) {
                vertexValues_[vertexValueIndex(l, k, p.vertices[v], side)] += weighted;
                vertexArea[2 * std::size_t(p.vertices[v]) + std::size_t(side)] += p.area;
            }
        }
    }
    for (std::size_t v = 0; v < mesh_->vertexCount(); ++v)
        for (int side = 0; side < 2; ++side)
            if (vertexArea[2 * v + std::size_t(side)] > 0.0f)
                vertexValues_[vertexValueIndex(l, k, v, side)] /= vertexArea[2 * v + std::size_t(side)];
}

void RadiosityIntegrator::computeDisplayScale(const std::vector<float>& noise) {
    // Gouraud shows over a triangle the plane through its vertex values, whose mean is their mean;
    // beside a steep change (a contact, a shadow's edge) that mean takes the neighbours' light, not
    // the patch's own (issue 27: taxonomy's floor beside the glass ball's contact showed 2-3x the
    // path tracer at bounce 2, its 4x4 region 27% off where the flat display is 9%). So the smooth
    // display scales the interpolated value over each element towards B_e / G_e, per channel: G_e
    // the area-weighted mean over the element's member patches of their vertex values' mean (what
    // Gouraud shows over the element, on average), B_e the element's solved radiosity. A cluster
    // is scaled as a whole, so its members stay smooth among themselves.
    // But B_e carries its own sampling noise, which the vertex means average out: scaled fully,
    // each element showed it (the emissive closed box, exactly uniform, 3.6% off in a pixel). So
    // the correction is shrunk towards Gouraud: the scale is 1 + w (B_e / G_e - 1), w the
    // non-negative garrote's max(0, 1 - lambda^2 / t^2) (Breiman 1995; as a threshold rule, Gao
    // 1998) of a test statistic t, the larger of two:
    //  - the element's own z = (B_e - G_e) / sigma_e (luminance; sigma_e^2 from valueNoise, the
    //    variance of B_e: the difference's is a little less, as G_e holds a share of B_e, so this
    //    shrinks a little more than needed);
    //  - its neighbourhood's sum z / sqrt(L) over the L (element, vertex) incidences of the lit
    //    elements around its patches' vertices (each counted once per shared vertex): a bias that
    //    keeps its sign over several elements (a floor's light curving away from the lamp, which
    //    Gouraud's neighbour means overshoot) shows there while each element alone is within its
    //    noise (block thresholding: Cai and Silverman 2001).
    // lambda = sqrt(2 ln n), n the lit elements of that light and bounce, the universal threshold
    // (Donoho and Johnstone 1994): the largest of n standard normals stays below it with
    // probability tending to 1, so where B_e - G_e is noise alone (the closed box) no element is
    // corrected, whatever the mesh's size. G_e > 0 wherever B_e > 0 (the element's own value
    // enters its vertices' means); where a channel's G_e is 0, so is B_e.
    const auto& patches = mesh_->patches();
    const std::uint32_t elements = elementCount();
    const std::size_t corners = 2 * mesh_->vertexCount();
    displayScale_.assign(values_.size(), Rgb{0.0f});
    std::vector<Rgb> shown(elements);
    std::vector<float> z(elements), neighbourZ(elements), neighbours(elements), cornerZ(corners), cornerCount(corners);
    for (std::size_t l = 0; l < solvedBounces_.size(); ++l) {
        for (int k = 1; k <= solvedBounces_[l]; ++k) {
            gouraudMeans(l, k, shown);
            std::uint32_t lit = 0;
            for (std::uint32_t e = 0; e < elements; ++e) {
                const std::size_t i = valueIndex(l, k, e);
                z[e] = 0.0f;
                if (isBlack(values_[i])) continue;
                ++lit;
                const float difference = luminance(values_[i]) - luminance(shown[e]);
                // No noise (every sample alike): the difference is all signal.
                z[e] = noise[i] > 0.0f ? difference / std::sqrt(noise[i])
                                       : (difference > 0.0f ? kUnboundedZ : difference < 0.0f ? -kUnboundedZ : 0.0f);
            }
            std::fill(cornerZ.begin(), cornerZ.end(), 0.0f);
            std::fill(cornerCount.begin(), cornerCount.end(), 0.0f);
            for (const RadiosityPatch& p : patches)
                for (int side = 0; side < 2; ++side) {
                    const std::uint32_t e = 2 * p.cluster + std::uint32_t(side);
                    if (isBlack(values_[valueIndex(l, k, e)])) continue;
                    for (int v = 0; v < p.vertexCount; ++v) {
                        cornerZ[2 * std::size_t(p.vertices[v]) + std::size_t(side)] += z[e];
                        cornerCount[2 * std::size_t(p.vertices[v]) + std::size_t(side)] += 1.0f;
                    }
                }
            std::fill(neighbourZ.begin(), neighbourZ.end(), 0.0f);
            std::fill(neighbours.begin(), neighbours.end(), 0.0f);
            for (const RadiosityPatch& p : patches)
                for (int side = 0; side < 2; ++side) {
                    const std::uint32_t e = 2 * p.cluster + std::uint32_t(side);
                    for (int v = 0; v < p.vertexCount; ++v) {
                        neighbourZ[e] += cornerZ[2 * std::size_t(p.vertices[v]) + std::size_t(side)];
                        neighbours[e] += cornerCount[2 * std::size_t(p.vertices[v]) + std::size_t(side)];
                    }
                }
            const float lambdaSquared = lit > 1 ? 2.0f * std::log(float(lit)) : 0.0f;
            for (std::uint32_t e = 0; e < elements; ++e) {
                const std::size_t i = valueIndex(l, k, e);
                if (isBlack(values_[i])) continue;
                const float block = neighbours[e] > 0.0f ? neighbourZ[e] * neighbourZ[e] / neighbours[e] : 0.0f;
                const float t2 = std::max(z[e] * z[e], block);
                const float w = t2 > lambdaSquared ? 1.0f - lambdaSquared / t2 : 0.0f;
                const Rgb g = shown[e], b = values_[i];
                for (int c = 0; c < 3; ++c) displayScale_[i][c] = g[c] > 0.0f ? 1.0f + w * (b[c] / g[c] - 1.0f) : 0.0f;
            }
        }
    }
}

Rgb RadiosityIntegrator::patchRadiance(std::size_t light, int bounce, std::uint32_t patch, int side) const {
    if (light >= solvedBounces_.size() || bounce < 1 || bounce > solvedBounces_[light]) return Rgb{0.0f};
    return values_[valueIndex(light, bounce, 2 * mesh_->patches()[patch].cluster + std::uint32_t(side))];
}

RadiosityIntegrator::FormFactorRow RadiosityIntegrator::formFactors(std::uint32_t patch, int side) const {
    if (patch >= mesh_->patches().size()) return {};
    const std::uint32_t e = 2 * mesh_->patches()[patch].cluster + std::uint32_t(side);
    if (std::size_t(e) + 1 >= rowStart_.size()) return {};
    const std::size_t begin = rowStart_[e], length = rowStart_[e + 1] - begin;
    return {std::span(targets_).subspan(begin, length), std::span(factors_).subspan(begin, length)};
}

void RadiosityIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    const RenderContext& ctx = path.context;
    const auto hit = ctx.geometry.intersect(ray);
    if (!hit) {
        addBackground(ray, Rgb{1.0f}, path);
        return;
    }
    // Bounce 0: an emitter's own radiance, exactly as every other integrator shows it.
    addEmission(*hit, ray, Rgb{1.0f}, 1.0f, path);
    if (bounces_ == 0) return;
    const auto found = mesh_->lookup(*hit);
    if (!found) return;  // a clipped plane beyond its rectangle: no patch, no radiosity
    if (!path.push({lpe::EventType::Reflection, lpe::Scatter::Diffuse, Subject::Object, hit->object, hit->point})) {
        ++path.counters.reflectionDead;
        return;
    }
    const int side = sideFacing(hit->normal, ray.direction);
    const std::uint32_t cluster = mesh_->patches()[found->patch].cluster;
    const Material& material = *ctx.scene.materials[ctx.scene.objects[hit->object].material];
    if (options_.finalGather > 0 && material.diffuseDependsOnView()) {
        const ShadingPoint shading = makeShadingPoint(*hit, ray, ctx);
        const SeenPoint seen{Rgb{0.0f}, &shading.bsdf, -ray.direction};
        emitDirectLight(*hit, side, seen, path);
        if (bounces_ > 1) gatherLaterBounces(*hit, side, seen, path);
    } else if (options_.finalGather > 0) {
        const SeenPoint seen{reflectance_[cluster] * reflectanceRatio(*hit, ray, cluster, ctx)};
        emitDirectLight(*hit, side, seen, path);
        if (bounces_ > 1) gatherLaterBounces(*hit, side, seen, path);
    } else {
        emitSolution(hit->point, *found, side, bounces_, reflectanceRatio(*hit, ray, cluster, ctx), false, path);
    }
    path.pop();
}

Rgb RadiosityIntegrator::shownRadiance(std::size_t light, int bounce, const PatchLookup& at, int side) const {
    const RadiosityPatch& patch = mesh_->patches()[at.patch];
    const std::size_t element = valueIndex(light, bounce, 2 * patch.cluster + std::uint32_t(side));
    if (display_ == RadiosityDisplay::Flat) return values_[element];
    const Rgb value = gouraudPlane(patch, side, at.weights, &vertexValues_[vertexValueIndex(light, bounce, 0, 0)]);
    return display_ == RadiosityDisplay::Smooth ? value * displayScale_[element] : value;
}

RadiosityIntegrator::GatherField RadiosityIntegrator::makeGatherField(std::size_t light, int bounce,
                                                                       const PatchGradients* gradients) const {
    GatherField field;
    std::vector<Rgb> shown;
    gouraudMeans(light, bounce, shown);
    const Rgb* value = &values_[valueIndex(light, bounce, 0)];
    field.scale.resize(elementCount());
    for (std::uint32_t e = 0; e < elementCount(); ++e)
        for (int c = 0; c < 3; ++c) field.scale[e][c] = shown[e][c] > 0.0f ? value[e][c] / shown[e][c] : 0.0f;
    if (gradients == nullptr) return field;
    std::vector<std::array<Rgb, 3>> corners;
    std::vector<std::uint8_t> fitted;
    gradients->fit(std::span(value, elementCount()), corners, fitted);
    field.cornerSlot.assign(fitted.size(), kNoTarget);
    for (std::size_t s = 0; s < fitted.size(); ++s)
        if (fitted[s] != 0) {
            field.cornerSlot[s] = static_cast<std::uint32_t>(field.corners.size());
            field.corners.push_back(corners[s]);
        }
    return field;
}

Rgb RadiosityIntegrator::GatherField::at(const RadiosityPatch& patch, std::uint32_t patchIndex, int side,
                                         const std::array<float, 4>& weights, const Rgb* vertex) const {
    if (!cornerSlot.empty()) {
        const std::uint32_t s = cornerSlot[2 * std::size_t(patchIndex) + std::size_t(side)];
        if (s != kNoTarget) {
            const std::array<Rgb, 3>& c = corners[s];
            return weights[0] * c[0] + weights[1] * c[1] + weights[2] * c[2];
        }
    }
    return scale[2 * patch.cluster + std::uint32_t(side)] * gouraudPlane(patch, side, weights, vertex);
}

void RadiosityIntegrator::completeGatherFields() {
    if (options_.finalGather <= 0 || bounces_ < 2) {
        gatherFields_.clear();
        return;
    }
    gatherFields_.resize(solvedBounces_.size() * std::size_t(bounces_));
    if (!options_.reconstructGather) return;  // constant elements: gatheredRadiance reads the values
    std::optional<PatchGradients> gradients;
    if (options_.gatherGradients) gradients.emplace(*mesh_);
    for (std::size_t l = 0; l < solvedBounces_.size(); ++l)
        for (int k = 1; k < bounces_ && k <= solvedBounces_[l]; ++k)
            if (gatherFields_[slot(l, k)].scale.empty())
                gatherFields_[slot(l, k)] = makeGatherField(l, k, gradients ? &*gradients : nullptr);
}

Rgb RadiosityIntegrator::gatheredRadiance(std::size_t light, int bounce, const PatchLookup& at, int side) const {
    const RadiosityPatch& patch = mesh_->patches()[at.patch];
    const GatherField& field = gatherFields_[slot(light, bounce)];
    if (field.scale.empty()) return values_[valueIndex(light, bounce, 2 * patch.cluster + std::uint32_t(side))];
    return field.at(patch, at.patch, side, at.weights, &vertexValues_[vertexValueIndex(light, bounce, 0, 0)]);
}

Rgb RadiosityIntegrator::reflectanceRatio(const SurfaceHit& hit, const Ray& ray, std::uint32_t cluster,
                                          const RenderContext& context) const {
    const Material& material = *context.scene.materials[context.scene.objects[hit.object].material];
    if (!material.textured && !material.vertexColored && !material.diffuseDependsOnView()) return Rgb{1.0f};
    const Rgb mean = reflectance_[cluster];
    const Rgb here = makeShadingPoint(hit, ray, context).bsdf.diffuseReflectanceToward(-ray.direction);
    Rgb ratio{0.0f};
    for (int c = 0; c < 3; ++c) ratio[c] = mean[c] > 0.0f ? here[c] / mean[c] : 0.0f;
    return ratio;
}

void RadiosityIntegrator::emitSolution(const Vec3& point, const PatchLookup& at, int side, int last, const Rgb& weight,
                                       bool gathered, PathState& path) const {
    const auto lights = path.context.lights.all();
    const std::size_t start = path.size();
    for (int k = 1; k <= last; ++k) {
        for (std::size_t l = 0; l < lights.size(); ++l) {
            if (k > solvedBounces_[l]) continue;
            const PathEvent& light = lights[l]->event();
            if (!path.wants(light)) continue;
            const Rgb value = weight * (gathered ? gatheredRadiance(l, k, at, side) : shownRadiance(l, k, at, side));
            if (!isBlack(value) || !path.context.skipEnabled) path.emit(light, value);
        }
        if (k == last) break;
        // The intermediate reflections are a sum over every patch: unlabelled D events.
        if (!path.push(unlabelledDiffuse(point))) {
            ++path.counters.reflectionDead;
            break;
        }
    }
    while (path.size() > start) path.pop();
}

void RadiosityIntegrator::emitDirectLight(const SurfaceHit& hit, int side, const SeenPoint& seen,
                                          PathState& path) const {
    const RenderContext& ctx = path.context;
    const auto lights = ctx.lights.all();
    const Vec3 normal = side == 0 ? hit.normal : -hit.normal;
    // The patches' own estimator (addDirectOverKd), at the pixel's point: N stratified samples of
    // an area light per camera sample, each pattern shifted as a whole by the pixel's sequence; a
    // point light needs one. Each light draws from its own sampler (Sampler::forVertex), so its
    // numbers, and an AOV rendered alone, do not depend on which other lights are wanted.
    const std::uint32_t strata = strataPerSide(options_.finalGather);
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (solvedBounces_[l] < 1) continue;
        const PathEvent& event = lights[l]->event();
        if (!path.wants(event)) continue;
        const Light& light = *lights[l];
        const std::uint32_t n = light.isDelta() ? 1 : strata;
        Sampler sampler = path.sampler->forVertex(path.key() ^ (0x9e3779b97f4a7c15ull * (l + 1)));
        const Vec2 shiftLight = sampler.next2D();
        const Vec2 shiftCosine = light.isDelta() ? Vec2{0.0f} : sampler.next2D();
        Rgb sum{0.0f};
        std::uint64_t cast = 0;
        for (std::uint32_t k = 0; k < n * n; ++k) {
            const Vec2 cell{float(k % n), float(k / n)};
            addDirectOverKd(light, ctx, hit, normal, (cell + shiftLight) / float(n), (cell + shiftCosine) / float(n), sum,
                            cast, seen.bsdf != nullptr ? &seen : nullptr);
        }
        path.counters.shadow += cast;
        const Rgb value = seen.bsdf != nullptr ? sum / float(n * n) : seen.albedo * sum / float(n * n);
        if (!isBlack(value) || !ctx.skipEnabled) path.emit(event, value);
    }
}

void RadiosityIntegrator::gatherLaterBounces(const SurfaceHit& hit, int side, const SeenPoint& seen,
                                             PathState& path) const {
    const RenderContext& ctx = path.context;
    // A Lambertian surface's bounce k is albedo times the mean of bounce k - 1's radiance over
    // cosine-weighted directions. The directions are stratified, a square pattern shifted as a
    // whole by one 2D sample per camera sample (Cranley and Patterson 1976), so a pixel's samples
    // cover the strata too.
    const std::uint32_t strata = strataPerSide(options_.finalGather);
    const std::uint32_t rays = strata * strata;
    const Vec2 shift = path.sampler->forVertex(path.key()).next2D();
    const Frame frame(side == 0 ? hit.normal : -hit.normal);
    const Rgb weight = seen.albedo / float(rays);
    for (std::uint32_t k = 0; k < rays; ++k) {
        const Vec2 u{(float(k % strata) + shift.x) / float(strata), (float(k / strata) + shift.y) / float(strata)};
        const Vec3 direction = frame.toWorld(sampleCosineHemisphere(u));
        const Ray gatherRay = spawnRay(hit, direction, ctx.geometry.numerics());
        ++path.counters.reflection;
        const auto there = ctx.geometry.intersect(gatherRay);
        if (!there) continue;
        const auto found = mesh_->lookup(*there);
        if (!found) continue;
        if (!path.push({lpe::EventType::Reflection, lpe::Scatter::Diffuse, Subject::Object, there->object, there->point})) {
            ++path.counters.reflectionDead;
            continue;
        }
        const Rgb ratio = reflectanceRatio(*there, gatherRay, mesh_->patches()[found->patch].cluster, ctx);
        const Rgb here = seen.bsdf != nullptr ? seen.from(direction) / float(rays) : weight;
        emitSolution(there->point, *found, sideFacing(there->normal, direction), bounces_ - 1, here * ratio, true,
                     path);
        path.pop();
    }
}

}  // namespace lightpath

// Its patches' diffuse bounces (ED+L), emitters and the background seen directly (EL).
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::integratorRow(
    "radiosity", "diffuse patches, form factors by ray casting, solved bounce by bounce (Jacobi)", "ED*[<L.[^'ambient']>OB]",
    "radiosity follows diffuse bounces only: no highlight, mirror, refraction or ambient term (ka Ia)",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::RadiosityIntegrator>()); },
    lightpath::ShadowRays::Always, 4,
    {{.name = "patch-size", .type = lightpath::ParameterType::Number, .unit = "scene units", .range = lightpath::kPositive,
      .doc = "target patch edge (default: the finest size within --patches)", .excludes = "patches"},
     {.name = "patches", .type = lightpath::ParameterType::Integer, .defaultText = "8192",
      .range = {1.0, static_cast<double>(lightpath::kMaxPatches)},
      .doc = "the most solved elements (patches; triangles smaller than a patch clustered); the finest patch size within it"},
     {.name = "form-factor-rays", .type = lightpath::ParameterType::Integer, .defaultText = "256", .range = {1.0, 65536.0},
      .doc = "hemisphere rays per side of each patch (a square number, stratified)"},
     {.name = "light-samples", .type = lightpath::ParameterType::Integer, .defaultText = "64", .range = {1.0, 65536.0},
      .doc = "shadow rays per side of each patch and light"},
     {.name = "refine", .type = lightpath::ParameterType::Integer, .defaultText = "2", .range = {0.0, 8.0},
      .doc = "refinement passes: cut into four the patches whose Gouraud mean differs from their radiosity by over 5% and over its sampling noise, solve again (0: uniform patches)"},
     {.name = "final-gather", .type = lightpath::ParameterType::Integer, .defaultText = "16", .range = {0.0, 4096.0},
      .doc = "per camera sample: samples of each area light for the direct light at the hit, and rays gathering bounces 2 and up from the solution over its hemisphere (0: every bounce read from the solution at the hit, the classic display)"},
     {.name = "radiosity-display", .type = lightpath::ParameterType::Name, .defaultText = "smooth",
      .doc = "smooth (vertex radiosities interpolated, scaled so each patch shows its own mean), gouraud (interpolated, unscaled) or flat (one value per patch)",
      .choices = "smooth|gouraud|flat"}}))
