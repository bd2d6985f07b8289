#include "config/messages.h"

#include <algorithm>
#include <cctype>
#include <iostream>

#include "scene/spelling.h"

#ifndef LIGHTPATH_VERSION
#error "LIGHTPATH_VERSION comes from the project's VERSION in CMakeLists.txt"
#endif

namespace lightpath {
namespace {

std::string lowered(std::string word) {
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
    return word;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

}  // namespace

std::optional<std::string> nearestName(const std::string& word, const std::vector<std::string>& names) {
    std::vector<std::string> lowerNames;
    for (const std::string& name : names) lowerNames.push_back(lowered(name));
    const auto match = closestMatch(lowered(word), lowerNames);
    if (!match) return std::nullopt;
    return names[static_cast<std::size_t>(std::find(lowerNames.begin(), lowerNames.end(), *match) - lowerNames.begin())];
}

std::string choiceMessage(const std::string& word, const std::vector<std::string>& names) {
    std::string message = word + " is not one of " + joined(names);
    if (const auto match = nearestName(word, names)) message += "; did you mean " + *match + "?";
    return message;
}

namespace {
std::string& activityText() {
    static std::string text;
    return text;
}
}  // namespace

void setActivity(std::string activity) { activityText() = std::move(activity); }
const std::string& activity() { return activityText(); }

std::string versionText() {
    std::string text = "lightpath " LIGHTPATH_VERSION "\nbuild: ";
#ifdef LIGHTPATH_HAS_EMBREE
    text += "Embree on (--accel embree)";
#else
    text += "Embree off (built without libembree-dev; --accel embree unavailable)";
#endif
#ifdef NDEBUG
    text += ", release (assertions off)";
#else
    text += ", debug (assertions on)";
#endif
    return text;
}

void Warnings::operator()(const std::string& message) const {
    if (!quiet_) std::cerr << "warning: " << message << "\n";
}

}  // namespace lightpath
