#pragma once
// The events of the light path currently being traced, kept on a fixed-size stack so recording
// costs no allocation. Only `lightpath explain` ever turns them into strings.
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>

#include "math/random.h"
#include "transport/path_event.h"

namespace lightpath {

class PathRecord {
public:
    void push(const PathEvent& event) {
        assert(size_ < events_.size());
        events_[size_++] = event;
    }
    void pop() { --size_; }
    std::size_t size() const { return size_; }
    // A hash of the events so far: names the vertex this path has reached.
    std::uint64_t key() const {
        std::uint64_t key = size_;
        for (std::size_t i = 0; i < size_; ++i) {
            const PathEvent& e = events_[i];
            key = mixBits(key ^ ((std::uint64_t{static_cast<std::uint8_t>(e.type)} << 40) |
                                 (std::uint64_t{static_cast<std::uint8_t>(e.scatter)} << 32) | e.index));
        }
        return key;
    }
    const PathEvent& operator[](std::size_t i) const { return events_[i]; }

private:
    std::array<PathEvent, kMaxPathEvents> events_{};
    std::size_t size_ = 0;
};

}  // namespace lightpath
