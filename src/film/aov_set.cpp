#include "film/aov_set.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>

namespace lightpath {
namespace {

bool isIdentifier(std::string_view s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

}  // namespace

AovSet::AovSet(std::vector<lpe::NamedExpression> expressions)
    : expressions_(std::move(expressions)), automaton_(lpe::Automaton::compile(expressions_)) {
    for (std::size_t i = 0; i < expressions_.size(); ++i) {
        const std::string& name = expressions_[i].name;
        if (!isIdentifier(name))
            throw std::invalid_argument("AOV name \"" + name + "\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*)");
        if (name == "beauty" || name == "rest")
            throw std::invalid_argument("AOV name \"" + name + "\" is reserved for the " + name + " layer");
        for (std::size_t j = 0; j < i; ++j)
            if (expressions_[j].name == name) throw std::invalid_argument("AOV name \"" + name + "\" is given twice");
    }
}

std::vector<std::string> AovSet::layerNames() const {
    std::vector<std::string> names{"beauty"};
    for (const auto& e : expressions_) names.push_back(e.name);
    names.push_back("rest");
    return names;
}

lpe::NamedExpression parseNamedExpression(std::string_view argument, std::size_t index) {
    const auto equals = argument.find('=');
    if (equals == std::string_view::npos) return {"lpe" + std::to_string(index), std::string(argument)};
    return {std::string(argument.substr(0, equals)), std::string(argument.substr(equals + 1))};
}

}  // namespace lightpath
