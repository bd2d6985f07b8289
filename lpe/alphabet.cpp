#include "lpe/alphabet.h"

#include <utility>

#include "lpe/error.h"

namespace lpe::detail {
namespace {

// Bounds the symbol count (35 per label class) and with it the dense transition table.
constexpr std::size_t kMaxLabels = 1000;

}  // namespace

Alphabet::Alphabet(const std::vector<std::string>& labels) {
    for (const std::string& label : labels) {
        if (classes_.count(label)) continue;
        if (labels_.size() == kMaxLabels) {
            throw LimitError("LPE limit: the expressions name more than " +
                             std::to_string(kMaxLabels) + " different labels");
        }
        labels_.push_back(label);
        classes_.emplace(label, static_cast<std::uint32_t>(labels_.size()));
    }
}

std::uint32_t Alphabet::labelClass(std::string_view label) const {
    const auto found = classes_.find(label);
    return found == classes_.end() ? 0 : found->second;
}

std::vector<bool> Alphabet::allowedClasses(const syntax::EventPattern& pattern) const {
    std::vector<bool> allowed(classCount(), true);
    for (const syntax::LabelTest& test : pattern.labelTests) {
        std::vector<bool> named(classCount(), false);
        for (const std::string& label : test.labels) named[labelClass(label)] = true;
        // Class 0 is "no label, or one no expression names": it is never one of the named labels.
        named[0] = false;
        for (std::size_t c = 0; c < allowed.size(); ++c) allowed[c] = allowed[c] && named[c] != test.negated;
    }
    return allowed;
}

// The camera, emitters and the background do not scatter (event.h): their events are matched as
// if their scattering were None, whatever it says. Otherwise an emitter event claiming diffuse
// scattering would match both `D` and `L`, and every automaton would grow states that exist only
// for events no renderer produces (E(D|G|S)*L would need five states instead of four).
Scatter Alphabet::effectiveScatter(int type, int scatter) {
    return scatters(static_cast<EventType>(type)) ? static_cast<Scatter>(scatter) : Scatter::None;
}

SymbolSet Alphabet::symbols(const syntax::EventSet& events) const {
    SymbolSet set(symbolCount(), false);
    for (const syntax::EventPattern& pattern : events.patterns) {
        const std::vector<bool> allowed = allowedClasses(pattern);
        for (std::uint32_t label = 0; label < classCount(); ++label) {
            if (!allowed[label]) continue;
            for (int type = 0; type < kEventTypeCount; ++type) {
                if (!(pattern.types & syntax::bit(static_cast<EventType>(type)))) continue;
                for (int scatter = 0; scatter < kScatterCount; ++scatter) {
                    if (pattern.scatters & syntax::bit(effectiveScatter(type, scatter))) {
                        set[symbolOf(type, scatter, label)] = true;
                    }
                }
            }
        }
    }
    if (events.negated) set.flip();
    return set;
}

Event eventOfSymbol(std::uint32_t symbol, const std::vector<std::string>& labels) {
    Event event;
    event.type = static_cast<EventType>(symbol % kEventTypeCount);
    event.scatter = static_cast<Scatter>(symbol / kEventTypeCount % kScatterCount);
    const std::uint32_t label = symbol / (kEventTypeCount * kScatterCount);
    if (label > 0) event.label = labels[label - 1];
    return event;
}

std::vector<std::uint32_t> preferenceOrder(std::size_t classCount) {
    using T = EventType;
    using S = Scatter;
    // The events a renderer produces come first; volumes (which lightpath never produces) and
    // emitting objects after lights and the background, so examples end in L where they can.
    std::vector<std::pair<T, S>> pairs = {
        {T::Reflection, S::Diffuse},    {T::Reflection, S::Glossy},    {T::Reflection, S::Specular},
        {T::Reflection, S::Straight},   {T::Transmission, S::Specular}, {T::Transmission, S::Diffuse},
        {T::Transmission, S::Glossy},   {T::Transmission, S::Straight}, {T::Camera, S::None},
        {T::Emitter, S::None},          {T::Background, S::None},       {T::ObjectEmission, S::None},
        {T::Volume, S::Diffuse},        {T::Volume, S::Glossy},         {T::Volume, S::Specular},
        {T::Volume, S::Straight},       {T::Reflection, S::None},       {T::Transmission, S::None},
        {T::Volume, S::None},
    };
    for (const T type : {T::Camera, T::Emitter, T::Background, T::ObjectEmission}) {
        for (const S scatter : {S::Diffuse, S::Glossy, S::Specular, S::Straight})
            pairs.emplace_back(type, scatter);
    }
    std::vector<std::uint32_t> order;
    for (std::uint32_t label = 0; label < classCount; ++label) {
        for (const auto& [type, scatter] : pairs) {
            order.push_back(symbolOf(static_cast<int>(type), static_cast<int>(scatter), label));
        }
    }
    return order;
}

Letters compressAlphabet(const std::vector<SymbolSet>& predicates, std::size_t symbolCount) {
    // Partition refinement: start with one letter, split every letter by each predicate in turn.
    Letters letters;
    letters.ofSymbol.assign(symbolCount, 0);
    letters.count = symbolCount == 0 ? 0 : 1;
    for (const SymbolSet& predicate : predicates) {
        std::vector<std::uint32_t> renamed(2 * letters.count, UINT32_MAX);
        std::uint32_t count = 0;
        for (std::size_t s = 0; s < symbolCount; ++s) {
            std::uint32_t& target = renamed[2 * letters.ofSymbol[s] + (predicate[s] ? 1 : 0)];
            if (target == UINT32_MAX) target = count++;
            letters.ofSymbol[s] = target;
        }
        letters.count = count;
    }
    letters.inPredicate.assign(predicates.size() * letters.count, 0);
    for (std::size_t p = 0; p < predicates.size(); ++p) {
        for (std::size_t s = 0; s < symbolCount; ++s) {
            if (predicates[p][s]) letters.inPredicate[p * letters.count + letters.ofSymbol[s]] = 1;
        }
    }
    return letters;
}

}  // namespace lpe::detail
