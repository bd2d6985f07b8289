#include "serve/session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "config/render_config.h"
#include "lpe/error.h"
#include "render/memory_limit.h"
#include "serve/request_error.h"

namespace lightpath::serve {
namespace {

// The expression of `set` whose text a syntax error quotes.
std::size_t expressionOf(const std::vector<lpe::NamedExpression>& set, const std::string& text) {
    for (std::size_t i = 0; i < set.size(); ++i)
        if (set[i].expression == text) return i;
    return set.size();
}

double maxSumError(const Film& film) {
    double worst = 0.0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const Rgb* pixel = &film.at(0, x, y);
            Rgb sum{0.0f};
            for (std::size_t l = 1; l < film.layerCount(); ++l) sum += pixel[l];
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(static_cast<double>(pixel[0][c]) - sum[c]));
        }
    }
    return worst;
}

}  // namespace

Job::Job(std::uint64_t generation, Settings settings, Scene scene, AovSet aovs, RenderOptions options,
         std::vector<std::string> warnings, std::shared_ptr<const SceneGeometry> geometry)
    : generation(generation),
      settings(std::move(settings)),
      scene(std::move(scene)),
      aovs(std::move(aovs)),
      warnings(std::move(warnings)),
      options_(options),
      geometry_(std::move(geometry)) {
    options_.cancel = &cancelled_;
    options_.preprocessSteps = &preprocessSteps_;
}

int Job::samplesPerPass() const { return std::min(kSamplesPerPass, settings.samplesPerPixel); }

const Renderer& Job::renderer() const {
    std::call_once(rendererOnce_, [this] {
        RenderOptions options = options_;
        options.samplesPerPixel = samplesPerPass();
        const auto started = std::chrono::steady_clock::now();
        preparationStarted_.store(started.time_since_epoch().count());
        renderer_ = std::make_unique<Renderer>(scene, aovs, options, geometry_);
        preparationSeconds_.store(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    });
    return *renderer_;
}

Preparation Job::preparation() const {
    Preparation preparation;
    // The total first: a step is counted only after the total it belongs to.
    preparation.totalSteps = preprocessSteps_.total.load(std::memory_order_relaxed);
    preparation.steps = std::min(preprocessSteps_.done.load(std::memory_order_relaxed), preparation.totalSteps);
    if (const double seconds = preparationSeconds_.load(); seconds >= 0.0) {
        preparation.state = Preparation::State::Done;
        preparation.seconds = seconds;
    } else if (const std::int64_t started = preparationStarted_.load(); started != 0) {
        preparation.state = Preparation::State::Running;
        const std::chrono::steady_clock::time_point since{std::chrono::steady_clock::duration{started}};
        preparation.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
    }
    return preparation;
}

Session::Session(Scene scene, std::string scenePath, int threads)
    : scene_(std::move(scene)),
      scenePath_(std::move(scenePath)),
      threads_(threads),
      geometry_(Renderer::buildGeometry(scene_, RenderConfig{}.renderOptions())) {
    job_ = prepare(defaultSettings(scene_), 1);
    progress_.job = job_;
    worker_ = std::thread([this] { work(); });
}

Session::~Session() { stop(); }

void Session::stop() { stopWithin(std::numeric_limits<double>::infinity()); }

bool Session::stopWithin(double seconds) {
    std::unique_lock lock(mutex_);
    stopping_ = true;
    if (job_) job_->cancel();
    if (explaining_) explaining_->store(true);
    changed_.notify_all();
    const auto finished = [this] { return workerDone_; };
    if (std::isinf(seconds)) changed_.wait(lock, finished);
    else if (!changed_.wait_for(lock, std::chrono::duration<double>(seconds), finished)) return false;
    lock.unlock();
    if (worker_.joinable()) worker_.join();
    return true;
}

std::shared_ptr<Job> Session::prepare(const Settings& settings, std::uint64_t generation) const {
    // Compiled here first for the syntax error's column and the expression it belongs to.
    try {
        AovSet check(settings.lpes);
    } catch (const lpe::SyntaxError& e) {
        const std::size_t i = expressionOf(settings.lpes, e.text());
        const std::string name = i < settings.lpes.size() ? settings.lpes[i].name : "?";
        RequestError error(400, "lpes[" + std::to_string(i) + "].expression", name + ": " + e.what());
        error.column = e.position();
        error.expression = e.text();
        throw error;
    } catch (const std::exception& e) {
        throw RequestError(400, "lpes", e.what());
    }

    const RenderConfig config = renderConfig(settings, scenePath_);  // the command line's own checks and warnings
    std::vector<std::string> warnings;
    std::optional<AovSet> aovs;
    try {
        config.validate();
        aovs.emplace(config.buildAovSet(scene_, &warnings));
    } catch (const ConfigError& e) {
        throw requestError(e, settings);
    }

    Scene scene = scene_;
    scene.camera.width = settings.width;
    scene.camera.height = settings.height;
    RenderOptions options = config.renderOptions();
    options.progress = false;
    options.threads = threads_;
    // A session holds up to five films of this size at once (the previous job's image, the one
    // shown, the sum of the passes, the pass being rendered and its new mean): refused here, not
    // by std::bad_alloc on the render thread.
    constexpr std::uint64_t kFilmsHeld = 5;
    try {
        const PixelMemory memory = Renderer::pixelMemory(scene, *aovs, options);
        refuseBeyondMemory(kFilmsHeld * memory.film + memory.splats + memory.preprocess,
                           memory.describe() + ", held " + std::to_string(kFilmsHeld) + " times,");
    } catch (const MemoryLimitError& e) {
        throw RequestError(400, "width,height", std::string("width,height: ") + e.what() + "; expected fewer pixels or lpes");
    }
    return std::make_shared<Job>(generation, settings, std::move(scene), std::move(*aovs), options, std::move(warnings),
                                 geometry_);
}

std::shared_ptr<const Job> Session::update(const Settings& settings) {
    std::uint64_t generation = 0;
    {
        std::lock_guard lock(mutex_);
        if (stopping_) throw RequestError(503, "", "the server is stopping");
        if (job_->settings == settings) return job_;
        generation = ++lastGeneration_;
    }
    std::shared_ptr<Job> next = prepare(settings, generation);  // outside the lock: compiling takes time
    {
        std::lock_guard lock(mutex_);
        if (stopping_) throw RequestError(503, "", "the server is stopping");
        // Two updates racing: the one that asked later wins, whichever finished preparing first.
        if (job_->generation > next->generation) return job_;
        job_->cancel();
        if (explaining_) explaining_->store(true);  // it explains the old settings' image
        job_ = next;
        idle_ = false;
    }
    changed_.notify_all();
    return next;
}

std::shared_ptr<std::atomic<bool>> Session::startExplaining() {
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    std::lock_guard lock(mutex_);
    if (explaining_) explaining_->store(true);
    if (stopping_) cancel->store(true);
    explaining_ = cancel;
    return cancel;
}

bool Session::stopping() const {
    std::lock_guard lock(mutex_);
    return stopping_;
}

std::shared_ptr<const Job> Session::job() const {
    std::lock_guard lock(mutex_);
    return job_;
}

Progress Session::progress() const {
    std::lock_guard lock(mutex_);
    return progress_;
}

Progress Session::progressOf(std::uint64_t generation) const {
    std::lock_guard lock(mutex_);
    if (progress_.job->generation != generation && previous_.job && previous_.job->generation == generation) return previous_;
    return progress_;
}

Progress Session::waitForProgress(std::uint64_t generation, int pass, double timeoutSeconds) const {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), [&] {
        if (stopping_) return true;
        const std::uint64_t current = progress_.job->generation;
        return current > generation || (current == generation && (progress_.passes > pass || progress_.done));
    });
    return progress_;
}

void Session::waitUntilIdle() const {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return workerDone_ || idle_; });
}

void Session::publish(const Progress& progress) {
    {
        std::lock_guard lock(mutex_);
        if (progress.job != job_) return;  // superseded while rendering
        progress_ = progress;
    }
    changed_.notify_all();
}

void Session::work() {
    struct Done {  // however the loop ends
        Session& session;
        ~Done() {
            {
                std::lock_guard lock(session.mutex_);
                session.workerDone_ = true;
            }
            session.changed_.notify_all();
        }
    } done{*this};
    std::shared_ptr<Job> rendered;
    while (true) {
        std::shared_ptr<Job> job;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] {
                if (stopping_ || job_ != rendered) return true;
                idle_ = true;  // the current job is rendered to its end or given up: say so once blocked
                changed_.notify_all();
                return false;
            });
            idle_ = false;
            if (stopping_) return;
            job = job_;
            if (progress_.image) previous_ = progress_;
            progress_ = Progress{};
            progress_.job = job;
        }
        changed_.notify_all();
        rendered = job;
        renderJob(job);
    }
}

void Session::renderJob(const std::shared_ptr<Job>& job) {
    Progress progress;
    progress.job = job;
    RenderResult first = job->renderer().render(0, 1);
    if (first.cancelled) return;
    progress.image = std::make_shared<Film>(first.film);
    progress.passes = 1;
    progress.samples = 1;
    progress.seconds = first.stats.seconds;
    progress.done = job->settings.samplesPerPixel == 1;
    progress.sumError = maxSumError(first.film);
    publish(progress);

    if (job->renderer().progressive()) {
        continueProgressive(job, progress);
        return;
    }
    // The mean of the jittered passes: each is an independent estimate (its own seed).
    const int perPass = job->samplesPerPass();
    const int passes = (job->settings.samplesPerPixel + perPass - 1) / perPass;
    std::optional<Film> sum;
    for (int pass = 1; pass <= passes && !progress.done; ++pass) {
        RenderResult result = job->renderer().render(static_cast<std::uint64_t>(pass), perPass);
        if (result.cancelled) return;
        if (!sum) {
            sum.emplace(std::move(result.film));
        } else {
            for (int y = 0; y < sum->height(); ++y)
                for (int x = 0; x < sum->width(); ++x) {
                    const std::span<Rgb> to = sum->pixel(x, y), from = result.film.pixel(x, y);
                    for (std::size_t l = 0; l < to.size(); ++l) to[l] += from[l];
                }
        }
        auto mean = std::make_shared<Film>(*sum);
        mean->scale(1.0f / static_cast<float>(pass));
        progress.image = std::move(mean);
        progress.passes = pass + 1;
        progress.samples = pass * perPass;
        progress.seconds += result.stats.seconds;
        progress.done = pass == passes;
        progress.sumError = maxSumError(*progress.image);
        publish(progress);
    }
}

// A progressive integrator's passes share one state (sppm: each pixel's radius shrinks with the
// photons it has found), so averaging independent short renders would keep the first passes'
// blur: one render of the whole target runs instead, its running mean shown every samplesPerPass
// samples.
void Session::continueProgressive(const std::shared_ptr<Job>& job, Progress& progress) {
    const int perPass = job->samplesPerPass();
    const int target = job->settings.samplesPerPixel;
    const auto started = std::chrono::steady_clock::now();
    const double before = progress.seconds;
    const auto show = [&](std::shared_ptr<Film> image, int samples, bool done) {
        progress.image = std::move(image);
        progress.passes = 1 + (samples + perPass - 1) / perPass;
        progress.samples = samples;
        progress.seconds = before + std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        progress.done = done;
        progress.sumError = maxSumError(*progress.image);
        publish(progress);
    };
    int shown = 0;
    RenderResult result = job->renderer().render(1, target, [&](const Film& sum, int samples) {
        if (samples - shown < perPass) return;
        shown = samples;
        auto mean = std::make_shared<Film>(sum);
        mean->scale(1.0f / static_cast<float>(samples));
        show(std::move(mean), samples, false);
    });
    if (result.cancelled) return;
    // The integrator's passes may hold fewer samples than asked (sppm's --passes not dividing --spp).
    const auto pixels = static_cast<std::uint64_t>(result.film.width()) * static_cast<std::uint64_t>(result.film.height());
    const int samples = static_cast<int>(result.stats.samples / std::max<std::uint64_t>(1, pixels));
    show(std::make_shared<Film>(std::move(result.film)), samples, true);
}

}  // namespace lightpath::serve
