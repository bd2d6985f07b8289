#pragma once
// Where the integrators hand every contribution: its radiance, the outputs (AOVs) whose
// expressions accepted its light path, and the path itself. The sink adds the value to the beauty
// and to each accepting AOV, or to `rest` when none accepted (DESIGN.md, "Recording paths").
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "integrators/path_record.h"
#include "lpe/automaton.h"
#include "math/types.h"

namespace lightpath {

struct LoggedContribution {
    Rgb value{0.0f};
    lpe::OutputMask accepted = 0;
    PathRecord path;
};

class ContributionSink {
public:
    // `layers` holds one accumulator per image layer: [0] beauty, [1..n] the n outputs, [n+1] rest.
    explicit ContributionSink(std::span<Rgb> layers, std::vector<LoggedContribution>* log = nullptr)
        : layers_(layers), log_(log) {}

    void add(const Rgb& value, lpe::OutputMask accepted, const PathRecord& path) {
        layers_[0] += value;
        if (accepted == 0) {
            layers_.back() += value;
        } else {
            for (lpe::OutputMask m = accepted; m != 0; m &= m - 1)
                layers_[1 + static_cast<std::size_t>(std::countr_zero(m))] += value;
        }
        if (log_ != nullptr) log_->push_back({value, accepted, path});
    }

private:
    std::span<Rgb> layers_;
    std::vector<LoggedContribution>* log_;
};

}  // namespace lightpath
