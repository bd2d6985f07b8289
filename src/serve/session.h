#pragma once
// One scene explored from the page: the current settings, the render of them refined pass by
// pass on a worker thread, and the pixel explanations. A change of settings cancels the render in
// flight (RenderOptions::cancel, checked per pixel) and starts the new one; one render runs at a
// time. Every method may be called from any HTTP thread.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "film/aov_set.h"
#include "film/film.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "serve/settings.h"
#include "util/progress.h"

namespace lightpath::serve {

// Pass 0 is one sample through each pixel centre (the lecture's image, and a first image fast);
// every later pass takes this many jittered samples with its own seed, and their mean replaces it.
inline constexpr int kSamplesPerPass = 4;

// Building a job's renderer: its integrator's preprocess (radiosity's meshing and solve), which
// may take far longer than a pass and comes before the first.
struct Preparation {
    enum class State { Waiting, Running, Done };
    State state = State::Waiting;
    double seconds = 0.0;  // so far while running, in all once done
    int steps = 0;         // the preprocess's steps done (util/progress.h), of
    int totalSteps = 0;    // its total; 0 for an integrator without a counted preprocess
};

// Everything one set of settings renders with. Renderers hold references into it, so it lives as
// long as the last request using it (shared_ptr).
class Job {
public:
    // `geometry`: the scene's shapes, built once per session and shared by every job's renderers.
    Job(std::uint64_t generation, Settings settings, Scene scene, AovSet aovs, RenderOptions options,
        std::vector<std::string> warnings, std::shared_ptr<const SceneGeometry> geometry);

    const std::uint64_t generation;
    const Settings settings;
    const Scene scene;  // the loaded scene at this job's resolution
    const AovSet aovs;
    const std::vector<std::string> warnings;  // overlaps, AOVs that stay black, readings (config/render_config.h)

    // The one renderer of these settings (one preprocess: radiosity solves once per change). It
    // renders pass 0 and `explain` with one sample through each pixel centre (as `lightpath
    // explain` does) and passes 1, 2, ... with samplesPerPass() jittered samples.
    const Renderer& renderer() const;
    // kSamplesPerPass (or the target, if fewer).
    int samplesPerPass() const;
    // How far building renderer() has come; any thread may ask while another builds it.
    Preparation preparation() const;

    void cancel() { cancelled_.store(true); }
    bool cancelled() const { return cancelled_.load(); }

private:
    RenderOptions options_;
    std::shared_ptr<const SceneGeometry> geometry_;
    std::atomic<bool> cancelled_{false};
    StepCounter preprocessSteps_;
    mutable std::atomic<std::int64_t> preparationStarted_{0};  // steady_clock ticks; 0: not yet (set in renderer())
    mutable std::atomic<double> preparationSeconds_{-1.0};      // < 0 until the renderer is built
    mutable std::once_flag rendererOnce_;
    mutable std::unique_ptr<Renderer> renderer_;
};

// What the page shows: the mean of the passes so far.
struct Progress {
    std::shared_ptr<const Job> job;
    std::shared_ptr<const Film> image;  // null until pass 0 is done
    int passes = 0;                      // passes in `image`
    int samples = 0;                     // samples per pixel in `image`
    bool done = false;                   // the target is reached: nothing more will change
    double seconds = 0.0;                // rendering time of the passes so far (Job::preparation() apart)
    double sumError = 0.0;               // max over pixels and channels of |beauty - sum of AOVs - rest|
};

class Session {
public:
    // `scene` is the scene the command line named, loaded once; nothing else is ever read.
    // `threads`: render threads per pass (0: one per core).
    Session(Scene scene, std::string scenePath, int threads = 0);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    const Scene& scene() const { return scene_; }
    const std::string& scenePath() const { return scenePath_; }

    // Checks `settings` (throws RequestError naming the field) and, when they differ from the
    // current ones, cancels the render in flight and starts theirs. Returns the job now current.
    std::shared_ptr<const Job> update(const Settings& settings);
    std::shared_ptr<const Job> job() const;
    Progress progress() const;
    // The progress of `generation` while it is held: the current one, or the one before it until
    // the current one has an image (so a page asking for the image it was just told about gets
    // it, even if the settings changed meanwhile). Otherwise the current progress.
    Progress progressOf(std::uint64_t generation) const;
    // Waits until a pass of a job at least `generation` newer than `pass` is published, or the
    // timeout passes (the caller's bound on a request's time); returns the progress then.
    Progress waitForProgress(std::uint64_t generation, int pass, double timeoutSeconds) const;

    // Starts an explanation: the flag it returns is set when a newer explanation starts, the
    // settings change or the server stops, and stops it (Renderer::explainPixel's cancel). Under
    // light tracing an explanation traces the whole image on the HTTP thread: only the newest runs.
    std::shared_ptr<std::atomic<bool>> startExplaining();
    bool stopping() const;

    // Waits until the worker has finished with the current job (rendered it to its target or given
    // it up) and waits for a change: then no render code runs until the next update. The fuzz
    // target needs this to see the same code run for the same input on any machine.
    void waitUntilIdle() const;

    // Stops the worker (cancelling its render and any explanation); later updates are refused.
    void stop();
    // The same, but waits at most `seconds` for the worker: building a renderer's acceleration
    // structure cannot be cancelled. Returns false if the worker is still busy (then only process
    // exit ends it; the destructor would wait).
    bool stopWithin(double seconds);

private:
    std::shared_ptr<Job> prepare(const Settings& settings, std::uint64_t generation) const;
    void work();
    void renderJob(const std::shared_ptr<Job>& job);
    void continueProgressive(const std::shared_ptr<Job>& job, Progress& progress);
    void publish(const Progress& progress);

    const Scene scene_;
    const std::string scenePath_;
    const int threads_;
    // Settings change the camera, the AOVs and the integrator, never the shapes or the numerics:
    // the BVH is built once.
    const std::shared_ptr<const SceneGeometry> geometry_;

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::shared_ptr<Job> job_;
    std::uint64_t lastGeneration_ = 1;  // handed out in the order updates arrive
    Progress progress_;
    Progress previous_;  // the last progress with an image, of an older generation
    std::shared_ptr<std::atomic<bool>> explaining_;  // the newest explanation's cancel flag
    bool stopping_ = false;
    bool workerDone_ = false;
    bool idle_ = false;  // the worker waits for a change, the current job finished
    std::thread worker_;
};

}  // namespace lightpath::serve
