#include <algorithm>
#include <map>
#include <utility>

#include "lpe/dfa.h"

namespace lpe::detail {
namespace {

// A refinable partition of 0..n-1 (Valmari and Lehtinen 2008): the members of each block are
// contiguous in `elements_`, so marking a state and splitting a block off cost O(1) per state.
class Partition {
public:
    explicit Partition(const std::vector<std::uint32_t>& initialBlock) {
        const std::size_t n = initialBlock.size();
        const std::uint32_t blocks =
            n == 0 ? 0 : *std::max_element(initialBlock.begin(), initialBlock.end()) + 1;
        first_.assign(blocks + 1, 0);
        for (const std::uint32_t b : initialBlock) ++first_[b + 1];
        for (std::uint32_t b = 0; b < blocks; ++b) first_[b + 1] += first_[b];
        past_.assign(first_.begin() + 1, first_.end());
        first_.pop_back();
        marked_.assign(blocks, 0);

        elements_.resize(n);
        location_.resize(n);
        blockOf_ = initialBlock;
        std::vector<std::size_t> fill(first_);
        for (std::uint32_t s = 0; s < n; ++s) {
            location_[s] = fill[initialBlock[s]]++;
            elements_[location_[s]] = s;
        }
    }

    std::size_t blockCount() const { return first_.size(); }
    std::uint32_t blockOf(std::uint32_t state) const { return blockOf_[state]; }
    std::size_t size(std::uint32_t block) const { return past_[block] - first_[block]; }
    std::vector<std::uint32_t> members(std::uint32_t block) const {
        return {elements_.begin() + static_cast<std::ptrdiff_t>(first_[block]),
                elements_.begin() + static_cast<std::ptrdiff_t>(past_[block])};
    }

    // Moves `state` to the marked front of its block; remembers blocks marked for the first time.
    void mark(std::uint32_t state) {
        const std::uint32_t block = blockOf_[state];
        const std::size_t at = location_[state];
        const std::size_t boundary = first_[block] + marked_[block];
        if (at < boundary) return;
        std::swap(elements_[at], elements_[boundary]);
        location_[elements_[at]] = at;
        location_[elements_[boundary]] = boundary;
        if (marked_[block]++ == 0) touched_.push_back(block);
    }

    // Splits every touched block into its marked and unmarked parts; the marked part becomes a new
    // block. Returns (old block, new block) for every split made.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> splitMarked() {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> splits;
        for (const std::uint32_t block : touched_) {
            const std::size_t marked = marked_[block];
            marked_[block] = 0;
            if (marked == size(block)) continue;
            const auto created = static_cast<std::uint32_t>(first_.size());
            first_.push_back(first_[block]);
            past_.push_back(first_[block] + marked);
            marked_.push_back(0);
            first_[block] += marked;
            for (std::size_t i = first_[created]; i < past_[created]; ++i) blockOf_[elements_[i]] = created;
            splits.emplace_back(block, created);
        }
        touched_.clear();
        return splits;
    }

private:
    std::vector<std::uint32_t> elements_;
    std::vector<std::size_t> location_;
    std::vector<std::uint32_t> blockOf_;
    std::vector<std::size_t> first_, past_, marked_;
    std::vector<std::uint32_t> touched_;
};

// Predecessors by letter, as compressed rows: sources of (target, letter) edges.
struct Inverse {
    std::vector<std::size_t> offset;  // (target * letters + letter) -> range in `sources`
    std::vector<std::uint32_t> sources;
};

Inverse invert(const Dfa& dfa) {
    const std::size_t rows = dfa.stateCount() * dfa.letterCount;
    Inverse inverse;
    inverse.offset.assign(rows + 1, 0);
    for (std::uint32_t s = 0; s < dfa.stateCount(); ++s) {
        for (std::uint32_t a = 0; a < dfa.letterCount; ++a)
            ++inverse.offset[dfa.step(s, a) * dfa.letterCount + a + 1];
    }
    for (std::size_t r = 0; r < rows; ++r) inverse.offset[r + 1] += inverse.offset[r];
    inverse.sources.resize(rows);
    std::vector<std::size_t> fill(inverse.offset.begin(), inverse.offset.end() - 1);
    for (std::uint32_t s = 0; s < dfa.stateCount(); ++s) {
        for (std::uint32_t a = 0; a < dfa.letterCount; ++a) {
            inverse.sources[fill[dfa.step(s, a) * dfa.letterCount + a]++] = s;
        }
    }
    return inverse;
}

}  // namespace

Dfa minimise(const Dfa& dfa) {
    const std::size_t letters = dfa.letterCount;

    // Initial partition: states with equal accept masks (Moore's and Hopcroft's starting point,
    // generalised from accept/reject to one class per set of accepting outputs).
    std::map<OutputMask, std::uint32_t> blockOfMask;
    std::vector<std::uint32_t> initial(dfa.stateCount());
    for (std::uint32_t s = 0; s < dfa.stateCount(); ++s) {
        initial[s] = blockOfMask.emplace(dfa.accepts[s], static_cast<std::uint32_t>(blockOfMask.size()))
                         .first->second;
    }
    Partition partition(initial);
    const Inverse inverse = invert(dfa);

    // Hopcroft's worklist of splitters (block, letter). Every initial block but a largest one
    // suffices; after a split, the smaller half suffices unless the block was still waiting.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> work;
    std::vector<std::uint8_t> waiting(partition.blockCount() * letters, 0);
    const auto push = [&](std::uint32_t block, std::uint32_t letter) {
        work.emplace_back(block, letter);
        waiting[block * letters + letter] = 1;
    };
    std::uint32_t largest = 0;
    for (std::uint32_t b = 0; b < partition.blockCount(); ++b) {
        if (partition.size(b) > partition.size(largest)) largest = b;
    }
    for (std::uint32_t b = 0; b < partition.blockCount(); ++b) {
        if (b == largest) continue;
        for (std::uint32_t a = 0; a < letters; ++a) push(b, a);
    }

    while (!work.empty()) {
        const auto [splitter, letter] = work.back();
        work.pop_back();
        waiting[splitter * letters + letter] = 0;

        for (const std::uint32_t target : partition.members(splitter)) {
            const std::size_t row = target * letters + letter;
            for (std::size_t i = inverse.offset[row]; i < inverse.offset[row + 1]; ++i) {
                partition.mark(inverse.sources[i]);
            }
        }
        for (const auto& [old, created] : partition.splitMarked()) {
            waiting.resize(partition.blockCount() * letters, 0);
            for (std::uint32_t a = 0; a < letters; ++a) {
                if (waiting[old * letters + a]) {
                    push(created, a);
                } else {
                    push(partition.size(created) < partition.size(old) ? created : old, a);
                }
            }
        }
    }

    // The quotient automaton: one state per block, transitions taken from any member.
    Dfa quotient;
    quotient.letterCount = letters;
    quotient.accepts.resize(partition.blockCount());
    quotient.next.resize(partition.blockCount() * letters);
    quotient.start = partition.blockOf(dfa.start);
    for (std::uint32_t s = 0; s < dfa.stateCount(); ++s) {
        const std::uint32_t block = partition.blockOf(s);
        quotient.accepts[block] = dfa.accepts[s];
        for (std::uint32_t a = 0; a < letters; ++a) {
            quotient.next[block * letters + a] = partition.blockOf(dfa.step(s, a));
        }
    }
    return quotient;
}

}  // namespace lpe::detail
