#pragma once
// Where the integrators hand every contribution: its radiance, the outputs (AOVs) whose
// expressions accepted its light path, and the path itself. The sink adds the value to the beauty
// and to each accepting AOV, or to `rest` when none accepted (docs/design.md, "Recording paths").
// Light tracing's contributions to other pixels go to the splat film, classified the same way.
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "film/splat_film.h"
#include "integrators/path_record.h"
#include "lpe/automaton.h"
#include "math/types.h"

namespace lightpath {

// One named factor of a contribution, for `explain`: kd, N.L, I, attenuation, a pdf, a MIS weight.
struct TermFactor {
    const char* name = "";
    Rgb value{0.0f};
    // False for a value the estimate depends on but is not multiplied by (the two pdfs MIS weighs):
    // `explain` shows those apart, so the factors read as the product they are.
    bool inProduct = true;
};
// The most a term has: MIS's five, a medium's transmittance and the throughput.
inline constexpr std::size_t kMaxTermFactors = 7;

struct LoggedContribution {
    Rgb value{0.0f};
    lpe::OutputMask accepted = 0;
    PathRecord path;
    bool splatted = false;  // light tracing's: it landed on this pixel from the light's side
    // Bidirectional path tracing's strategy: s vertices from the light, t from the eye; -1 for
    // the other integrators.
    std::int8_t lightVertices = -1, eyeVertices = -1;
    std::array<TermFactor, kMaxTermFactors> factors{};
    std::size_t factorCount = 0;
};

// A term that added nothing, the path it would have had, and why (`explain`).
struct Rejection {
    PathRecord path;
    std::string reason;
};

class ContributionSink {
public:
    // `layers` holds one accumulator per image layer: [0] beauty, [1..n] the n outputs, [n+1] rest.
    explicit ContributionSink(std::span<Rgb> layers, SplatFilm* splats = nullptr,
                              std::vector<LoggedContribution>* log = nullptr,
                              std::vector<Rejection>* rejections = nullptr)
        : layers_(layers), splats_(splats), log_(log), rejections_(rejections) {}

    // True while `explain` logs: integrators then also report factors and rejections.
    bool explaining() const { return log_ != nullptr; }

    void add(const Rgb& value, lpe::OutputMask accepted, const PathRecord& path,
             std::span<const TermFactor> factors = {}) {
        layers_[0] += value;
        if (accepted == 0) {
            layers_.back() += value;
        } else {
            for (lpe::OutputMask m = accepted; m != 0; m &= m - 1)
                layers_[1 + static_cast<std::size_t>(std::countr_zero(m))] += value;
        }
        if (log_ != nullptr) [[unlikely]]
            logContribution(value, accepted, path, factors);
    }

    void reject(const PathRecord& path, std::string reason) {
        if (rejections_ != nullptr) rejections_->push_back({path, std::move(reason)});
    }

    // A contribution to pixel (x, y) of the whole image, wherever the current sample is.
    void splat(int x, int y, const Rgb& value, lpe::OutputMask accepted, const PathRecord& path) {
        if (log_ != nullptr) {
            if (x == logX_ && y == logY_) log_->push_back({value, accepted, path, true, strategyS_, strategyT_});
            return;
        }
        if (splats_ == nullptr) return;
        splats_->add(x, y, 0, value);
        if (accepted == 0) {
            splats_->add(x, y, layers_.size() - 1, value);
        } else {
            for (lpe::OutputMask m = accepted; m != 0; m &= m - 1)
                splats_->add(x, y, 1 + static_cast<std::size_t>(std::countr_zero(m)), value);
        }
    }

    // The bidirectional strategy the next contributions come from (only `explain` reads it).
    void setStrategy(int s, int t) {
        strategyS_ = static_cast<std::int8_t>(s);
        strategyT_ = static_cast<std::int8_t>(t);
    }

    // `explain` logs splats that land on the pixel it explains.
    void logSplatsAt(int x, int y) {
        logX_ = x;
        logY_ = y;
    }

private:
    // `explain`'s part of add, out of line: inline, it made add too large for GCC to inline into
    // the light loop (addDirectLight), whose every term comes here (docs/performance.md, Shading
    // share, eighth pass).
    [[gnu::cold, gnu::noinline]] void logContribution(const Rgb& value, lpe::OutputMask accepted,
                                                      const PathRecord& path, std::span<const TermFactor> factors) {
        LoggedContribution& logged = log_->emplace_back(LoggedContribution{value, accepted, path, false, strategyS_, strategyT_});
        logged.factorCount = std::min(factors.size(), kMaxTermFactors);
        std::copy_n(factors.begin(), logged.factorCount, logged.factors.begin());
    }

    std::span<Rgb> layers_;
    SplatFilm* splats_;
    std::vector<LoggedContribution>* log_;
    std::vector<Rejection>* rejections_;
    int logX_ = -1, logY_ = -1;
    std::int8_t strategyS_ = -1, strategyT_ = -1;
};

}  // namespace lightpath
