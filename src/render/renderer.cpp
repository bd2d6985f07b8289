#include "render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <thread>

#include "util/timing.h"
#include "integrators/direct_light.h"
#include "integrators/registry.h"
#include "render/memory_limit.h"
#include "util/progress.h"
#include "sampling/sampler.h"
#include "util/parallel_chunks.h"
#include "util/worker_threads.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

constexpr int kTileSize = 16;
std::atomic<std::uint64_t> preprocessesRun_{0};  // Renderer::preprocessesRun
// State that one worker writes while another reads or writes nearby keeps a cache line to itself:
// two cores writing one line pass it back and forth (false sharing).
constexpr std::size_t kCacheLine = 64;
template <typename T>
struct alignas(kCacheLine) CacheLinePadded {
    T value{};
};

}  // namespace

std::shared_ptr<const SceneGeometry> Renderer::buildGeometry(const Scene& scene, const RenderOptions& options) {
    return std::make_shared<const SceneGeometry>(scene.spheres, scene.planes, scene.triangles, options.numerics,
                                                 options.accelerator, scene.triangleNormals, 0, scene.shapes, scene.triangleUvs,
                                                 scene.triangleTangents, scene.objectCoverage(), scene.triangleColors);
}

Renderer::Renderer(const Scene& scene, const AovSet& aovs, const RenderOptions& options)
    : Renderer(scene, aovs, options, buildGeometry(scene, options)) {}

Renderer::Renderer(const Scene& scene, const AovSet& aovs, const RenderOptions& options,
                   std::shared_ptr<const SceneGeometry> geometry)
    : scene_(scene),
      aovs_(aovs),
      options_(options),
      geometry_(std::move(geometry)),
      symbols_(scene, aovs.automaton()),
      analysis_(scene),
      lights_(scene_, *geometry_),
      lobeSteps_(scene_, aovs.automaton(), symbols_, lights_),
      camera_(scene.camera),
      filter_(options.filter),
      integrator_(makeIntegrator(options.integrator)),
      context_{scene_, *geometry_, aovs_.automaton(), symbols_, analysis_, lights_, lobeSteps_, camera_, options.maxDepth,
               aovs.automaton().allOutputs(), options.writeBeauty || !options.skip, options.skip, options.radiosity,
               options.threads, options.progress, options.cancel} {
    if (!integrator_) {
        std::string names;
        for (const std::string& name : integratorNames()) names += (names.empty() ? "" : ", ") + name;
        throw std::invalid_argument("unknown integrator \"" + options.integrator + "\"; expected one of " + names);
    }
    const IntegratorInfo& info = *findIntegrator(options.integrator);
    if (options.shadows == false && info.shadowRays == ShadowRays::Always)
        throw std::invalid_argument("shadow rays cannot be switched off under the " + options.integrator +
                                    " integrator: the light its scattered rays find is blocked like any ray, so "
                                    "unblocked direct light would count some light twice (raycast and whitted "
                                    "can: Szymczak's formula with its shadow term set to 1)");
    if (options.shadows == true && info.shadowRays == ShadowRays::Never)
        throw std::invalid_argument("the " + options.integrator + " integrator casts no rays, so it has no shadows; "
                                    "compare it with --integrator raycast --shadows off");
    context_.filter = &filter_;
    context_.seed = options.seed;
    context_.samplesPerPixel = options.samplesPerPixel;
    context_.eyeMedium = cameraMedium(context_);
    context_.preprocessSteps = options.preprocessSteps;
    if (options_.integratorParameters) context_.parameters = &*options_.integratorParameters;
    context_.shadows = info.shadowRays != ShadowRays::Never && options.shadows.value_or(true);
    if (options.maxDepth < 0 || options.maxDepth > kMaxDepth)
        throw std::invalid_argument("max depth " + std::to_string(options.maxDepth) + " is outside 0.." + std::to_string(kMaxDepth));
    checkSamplesPerPixel(options.samplesPerPixel);
    if (!options.writeBeauty && aovs.expressions().empty())
        throw std::invalid_argument("nothing to render: no beauty and no AOVs requested");
    writtenLayers_ = writtenLayers(aovs, options.writeBeauty);
    if (integrator_->splats() && options.targetError > 0.0)
        throw std::invalid_argument("adaptive sampling (--target-error) cannot be combined with the " + options.integrator +
                                    " integrator, whose light tracing adds to every pixel");
    if (integrator_->progressive() && options.targetError > 0.0)
        throw std::invalid_argument("adaptive sampling (--target-error) cannot be combined with the " + options.integrator +
                                    " integrator, which renders every pixel pass by pass");
    if (const std::size_t bytes = integrator_->preprocessBytes(camera_.width(), camera_.height()); bytes > 0)
        refuseBeyondMemory(bytes, "the " + options.integrator + " integrator's preprocess for " +
                                      pixelMemory(scene, aovs, options).describe());
    const auto preprocessStarted = std::chrono::steady_clock::now();
    integrator_->preprocess(context_);
    preprocessSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - preprocessStarted).count();
    preprocessesRun_.fetch_add(1, std::memory_order_relaxed);
}

void Renderer::checkSamplesPerPixel(int samplesPerPixel) const {
    if (integrator_->samplesPixelCentres() && (samplesPerPixel != 1 || options_.targetError > 0.0))
        throw std::invalid_argument("the " + options_.integrator + " integrator samples each pixel once, at its centre: "
                                    "use --spp 1 and no --target-error");
    if (samplesPerPixel < 1) throw std::invalid_argument("samples per pixel must be at least 1");
}

std::uint64_t Renderer::preprocessesRun() { return preprocessesRun_.load(std::memory_order_relaxed); }

std::vector<std::size_t> Renderer::writtenLayers(const AovSet& aovs, bool writeBeauty) {
    // One contiguous run (render() copies it as a block): every layer, or all but beauty and rest.
    std::vector<std::size_t> layers;
    for (std::size_t l = 0; l < aovs.layerCount(); ++l) {
        const bool beautyOrRest = l == 0 || l + 1 == aovs.layerCount();
        if (writeBeauty || !beautyOrRest) layers.push_back(l);
    }
    return layers;
}

PixelMemory Renderer::pixelMemory(const Scene& scene, const AovSet& aovs, const RenderOptions& options) {
    const std::unique_ptr<Integrator> integrator = makeIntegrator(options.integrator);
    if (!integrator) throw std::invalid_argument("unknown integrator \"" + options.integrator + "\"");
    PixelMemory memory;
    memory.width = scene.camera.width;
    memory.height = scene.camera.height;
    const auto all = aovs.layerNames();
    for (std::size_t l : writtenLayers(aovs, options.writeBeauty)) memory.layers.push_back(all[l]);
    memory.film = Film::bytes(memory.width, memory.height, memory.layers.size());
    // The splat film has every layer: the sink splats by automaton output (render()).
    if (integrator->splats()) memory.splats = SplatFilm::bytes(memory.width, memory.height, aovs.layerCount());
    memory.preprocess = integrator->preprocessBytes(memory.width, memory.height);
    return memory;
}

std::string PixelMemory::describe() const {
    std::string names;
    for (const std::string& name : layers) names += (names.empty() ? "" : ", ") + name;
    return "a " + std::to_string(width) + "x" + std::to_string(height) + " image of " + std::to_string(layers.size()) +
           " layer" + (layers.size() == 1 ? "" : "s") + " (" + names + ")";
}

namespace {

// Adaptive sampling's test: the standard error of the pixel's mean luminance, estimated from its
// samples, relative to that mean (an absolute floor keeps black pixels from sampling forever).
bool converged(double sum, double sumOfSquares, int n, double targetError) {
    const double mean = sum / n;
    const double variance = std::max(0.0, (sumOfSquares - n * mean * mean) / (n - 1));
    return std::sqrt(variance / n) <= targetError * std::max(mean, 1e-4);
}

// Adaptive sampling looks at a pixel's samples in batches of this many, from this many on.
constexpr int kAdaptiveBatch = 4;
constexpr int kAdaptiveMinimum = 8;

}  // namespace

LIGHTPATH_HOT_PATH
void Renderer::traceSample(int x, int y, std::uint64_t seed, int sample, int spp, PathState& path,
                           ProgressiveRender* progressive) const {
    Sampler sampler = Sampler::forPixel(options_.sampler, x, y, sample, spp, seed);
    path.sampler = &sampler;
    path.sampleIndex = sample;
    // One sample goes through the pixel centre, as in the lecture; more are spread around it
    // as the pixel filter weighs them. Under light tracing even one is spread: its splats
    // estimate the filter's mean over the pixel, and so must the eye's strategies.
    Vec2 offset{0.5f};
    if (spp > 1 || integrator_->splats()) offset += filter_.sample(sampler.next2D());
    else sampler.skip2D();
    const Ray ray = camera_.generateRay(static_cast<float>(x) + offset.x, static_cast<float>(y) + offset.y);
    // E is where the ray starts: the eye, or an orthographic camera's point on its film.
    if (!path.push({lpe::EventType::Camera, lpe::Scatter::None, Subject::None, 0, ray.origin})) {
        ++path.counters.cameraDead;
        return;
    }
    ++path.counters.camera;
    if (progressive != nullptr) progressive->traceCameraRay(ray, path, x, y);
    else integrator_->traceCameraRay(ray, path);
    path.pop();
}

LIGHTPATH_HOT_PATH
int Renderer::renderPixel(int x, int y, std::uint64_t seed, int spp, std::span<Rgb> layers, PathState& path) const {
    const bool adaptive = options_.targetError > 0.0;
    double sum = 0.0, sumOfSquares = 0.0;
    int taken = 0;
    while (taken < spp) {
        const Rgb beautyBefore = layers[0];
        traceSample(x, y, seed, taken, spp, path);
        ++taken;
        if (!adaptive) continue;
        const double value = luminance(layers[0] - beautyBefore);
        sum += value;
        sumOfSquares += value * value;
        if (taken >= kAdaptiveMinimum && taken % kAdaptiveBatch == 0 && converged(sum, sumOfSquares, taken, options_.targetError))
            break;
    }
    if (taken > 1) {
        const float weight = 1.0f / static_cast<float>(taken);
        for (Rgb& layer : layers) layer *= weight;
    }
    return taken;
}

void Renderer::addSplats(const SplatFilm& splats, int samplesPerPixel, Film& film) const {
    // Every pixel sample traced one light path, so the splats of the whole image are divided by
    // the samples per pixel, like each pixel's own mean (Veach 1997, 10.3.4.3).
    const float weight = 1.0f / static_cast<float>(samplesPerPixel);
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const std::span<Rgb> pixel = film.pixel(x, y);
            for (std::size_t l = 0; l < writtenLayers_.size(); ++l) pixel[l] += splats.at(x, y, writtenLayers_[l]) * weight;
        }
    }
}

bool Renderer::cancelled() const {
    return options_.cancel != nullptr && options_.cancel->load(std::memory_order_relaxed);
}

std::vector<std::string> Renderer::layerNames() const {
    const auto all = aovs_.layerNames();
    std::vector<std::string> names;
    for (std::size_t l : writtenLayers_) names.push_back(all[l]);
    return names;
}

RenderResult Renderer::render() const { return render(options_.seed, options_.samplesPerPixel); }

RenderResult Renderer::render(std::uint64_t seed) const { return render(seed, options_.samplesPerPixel); }

RenderResult Renderer::render(std::uint64_t seed, int samplesPerPixel) const { return render(seed, samplesPerPixel, {}); }

bool Renderer::progressive() const { return integrator_->progressive(); }

RenderResult Renderer::render(std::uint64_t seed, int samplesPerPixel, const PassObserver& observer) const {
    checkSamplesPerPixel(samplesPerPixel);
    const auto started = std::chrono::steady_clock::now();
    const double startedCpu = threadCpuSeconds();
    const int width = camera_.width(), height = camera_.height();
    {
        const PixelMemory memory = pixelMemory(scene_, aovs_, options_);
        refuseBeyondMemory(memory.film + memory.splats, memory.describe());
    }
    // A progressive integrator renders every pixel's sample k in its pass k, adding to the film;
    // the others render each pixel's samples at once, in one pass.
    const std::unique_ptr<ProgressiveRender> progressive = integrator_->startProgressive(context_, samplesPerPixel);
    const int passes = progressive ? progressive->passes() : 1;
    const int perPass = progressive ? progressive->samplesPerPass() : samplesPerPixel;
    // Unset: each worker writes the pixels of its tiles, so the film's pages (174 MB at 1080p with
    // the classes AOVs) are first touched by the workers in parallel, not zeroed by this thread
    // before they start (which made the AOVs cost 36-64% on two threads and 1.4% on one). Passes
    // add to it, so it starts at zero then.
    Film film = progressive ? Film(width, height, layerNames()) : Film(width, height, layerNames(), Film::Unset{});
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    const int tileCount = tilesX * tilesY;
    int threadCount = static_cast<int>(threadsOrAll(options_.threads));
    threadCount = std::clamp(threadCount, 1, std::max(1, tileCount));

    ProgressBar progress(tileCount * passes, options_.progress);
    CacheLinePadded<std::atomic<int>> nextTile;  // bumped per tile, away from the locals the workers read
    std::vector<RayCounters> counters(static_cast<std::size_t>(threadCount));
    std::vector<CacheLinePadded<double>> workerCpu(static_cast<std::size_t>(threadCount));
    std::optional<SplatFilm> splats;
    if (integrator_->splats()) splats.emplace(width, height, aovs_.layerCount());
    const auto clearTileFrom = [&](int tile, int x, int y) {  // the pixels of `tile` from (x, y) on
        if (progressive) return;  // the film holds the passes before: it was set to zero
        const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
        for (; y < std::min(y0 + kTileSize, height); ++y, x = x0)
            for (; x < std::min(x0 + kTileSize, width); ++x) std::ranges::fill(film.pixel(x, y), Rgb{0.0f});
    };
    const double serialBeforeCpu = threadCpuSeconds() - startedCpu;
    double passesCpu = 0.0;  // beginPass's, on the calling thread (a pass's photons)
    int pass = 0;
    // A worker's exception stops the others and is rethrown here once all have joined: thrown out
    // of a std::jthread it would call std::terminate (and take `serve` down).
    WorkerErrors errors;
    auto work = [&](unsigned worker) {
        const double workerStarted = threadCpuSeconds();
        double& cpu = workerCpu[static_cast<std::size_t>(worker)].value;
        // A cache line of padding on each side of the worker's accumulators: the heap may have put
        // another worker's data next to them.
        constexpr std::size_t kPad = (kCacheLine + sizeof(Rgb) - 1) / sizeof(Rgb);
        std::vector<Rgb> padded(aovs_.layerCount() + 2 * kPad);
        const std::span<Rgb> layers(padded.data() + kPad, aovs_.layerCount());
        ContributionSink sink(layers, splats ? &*splats : nullptr);
        PathState path(context_, sink, counters[static_cast<std::size_t>(worker)]);
        // The written layers are one run of the accumulators (all of them, or all but beauty and
        // rest): each pixel is one block copy, not a lookup per layer.
        const std::span<const Rgb> written = layers.subspan(writtenLayers_.front(), writtenLayers_.size());
        // Tiles are handed out dynamically; each pixel is written by exactly one worker.
        for (int tile = nextTile.value++; tile < tileCount; tile = nextTile.value++) {
            const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
            for (int y = y0; y < std::min(y0 + kTileSize, height); ++y) {
                for (int x = x0; x < std::min(x0 + kTileSize, width); ++x) {
                    // Checked per pixel, not per tile: a tile at thousands of samples per pixel
                    // takes seconds, and Ctrl-C must stop the render promptly. The film is unset:
                    // the rest of the tile is cleared.
                    if (cancelled() || errors.failed()) {
                        clearTileFrom(tile, x, y);
                        cpu += threadCpuSeconds() - workerStarted;
                        return;
                    }
                    std::fill(layers.begin(), layers.end(), Rgb{0.0f});
                    if (progressive) {
                        for (int k = 0; k < perPass; ++k)
                            traceSample(x, y, seed, pass * perPass + k, passes * perPass, path, progressive.get());
                        const std::span<Rgb> pixel = film.pixel(x, y);
                        for (std::size_t l = 0; l < written.size(); ++l) pixel[l] += written[l];
                    } else {
                        renderPixel(x, y, seed, samplesPerPixel, layers, path);
                        // One block copy: copied layer by layer it was 7 instructions a layer.
                        std::memcpy(film.pixel(x, y).data(), written.data(), written.size_bytes());
                    }
                }
            }
            progress.tileDone();
        }
        cpu += threadCpuSeconds() - workerStarted;
    };
    for (; pass < passes && !cancelled(); ++pass) {
        if (progressive) {
            const double before = threadCpuSeconds();
            progressive->beginPass(pass);
            passesCpu += threadCpuSeconds() - before;
            nextTile.value = 0;
        }
        runWorkers(static_cast<unsigned>(threadCount), errors, work);
        if (observer && progressive && pass + 1 < passes && !cancelled() && !errors.failed()) observer(film, (pass + 1) * perPass);
    }
    const double afterWorkersCpu = threadCpuSeconds();
    // Tiles no worker took (a cancelled render) are still unset.
    for (int tile = nextTile.value.load(); tile < tileCount; ++tile) clearTileFrom(tile, (tile % tilesX) * kTileSize, (tile / tilesX) * kTileSize);
    if (splats) addSplats(*splats, samplesPerPixel, film);
    if (progressive && pass * perPass > 1) {
        // The mean of the passes' samples (of those begun, when cancelled).
        film.scale(1.0f / static_cast<float>(pass * perPass));
    }

    RenderStats stats;
    for (const RayCounters& c : counters) stats.rays += c;
    for (const auto& c : workerCpu) stats.cpuSeconds += c.value;
    stats.samples = stats.rays.camera + stats.rays.cameraDead;  // adaptive sampling takes fewer
    stats.threads = threadCount;
    stats.accelerator = geometry_->acceleratorStats();
    stats.preprocessSeconds = preprocessSeconds_;
    if (const auto* radiosity = dynamic_cast<const RadiosityIntegrator*>(integrator_.get())) stats.radiosity = radiosity->stats();
    if (const auto* photon = dynamic_cast<const PhotonIntegrator*>(integrator_.get())) stats.photon = photon->stats();
    if (const auto* bdpt = dynamic_cast<const BdptIntegrator*>(integrator_.get())) stats.bdpt = bdpt->stats();
    if (const auto* sppm = dynamic_cast<const SppmRender*>(progressive.get())) stats.photon = sppm->stats();
    for (const auto& cpu : workerCpu) stats.workerCpuSeconds.push_back(cpu.value);
    stats.serialCpuSeconds = serialBeforeCpu + passesCpu + (threadCpuSeconds() - afterWorkersCpu);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return {std::move(film), stats, cancelled()};
}

std::vector<LoggedContribution> Renderer::explainPixel(int x, int y, std::vector<Rejection>* rejections,
                                                       const ExplainOptions& options) const {
    const int spp = options.samplesPerPixel > 0 ? options.samplesPerPixel : options_.samplesPerPixel;
    checkSamplesPerPixel(spp);
    const auto cancelled = [&] { return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed); };
    if (x < 0 || y < 0 || x >= camera_.width() || y >= camera_.height())
        throw std::invalid_argument("pixel " + std::to_string(x) + "," + std::to_string(y) +
                                    " is outside the " + std::to_string(camera_.width()) + "x" +
                                    std::to_string(camera_.height()) + " image");
    std::vector<Rgb> layers(aovs_.layerCount());
    std::vector<LoggedContribution> log;
    ContributionSink sink(layers, nullptr, &log, rejections);
    RayCounters counters;
    PathState path(context_, sink, counters);
    sink.logSplatsAt(x, y);
    if (const std::unique_ptr<ProgressiveRender> progressive = integrator_->startProgressive(context_, spp)) {
        // The pixel's passes, each after its pass's preparation (photon mapping's photons): the
        // pixel's own state evolves as in the render, so the logged terms sum to its value there.
        const int passes = progressive->passes(), perPass = progressive->samplesPerPass();
        for (int pass = 0; pass < passes; ++pass) {
            if (cancelled()) throw ExplainCancelled();
            progressive->beginPass(pass);
            for (int k = 0; k < perPass; ++k)
                traceSample(x, y, options_.seed, pass * perPass + k, passes * perPass, path, progressive.get());
        }
        for (LoggedContribution& c : log) c.value *= 1.0f / static_cast<float>(passes * perPass);
        return log;
    }
    renderPixel(x, y, options_.seed, spp, layers, path);
    if (integrator_->splats()) {
        // Light tracing lands on this pixel from any pixel's sample: trace every pixel's paths
        // (one thread, the whole image's work) and keep the splats that land here.
        std::vector<LoggedContribution> other;
        ContributionSink otherSink(layers, nullptr, &other);
        otherSink.logSplatsAt(x, y);
        PathState otherPath(context_, otherSink, counters);
        for (int py = 0; py < camera_.height(); ++py) {
            for (int px = 0; px < camera_.width(); ++px) {
                if (px == x && py == y) continue;
                if (cancelled()) throw ExplainCancelled();
                renderPixel(px, py, options_.seed, spp, layers, otherPath);
                for (LoggedContribution& c : other)
                    if (c.splatted) log.push_back(c);
                other.clear();
            }
        }
    }
    // Logged values are per sample; scale them like the pixel so they sum to it.
    const float weight = 1.0f / static_cast<float>(spp);
    for (LoggedContribution& c : log) c.value *= weight;
    return log;
}

}  // namespace lightpath
