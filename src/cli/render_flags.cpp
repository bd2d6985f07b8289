#include "cli/render_flags.h"

#include "config/exit_codes.h"
#include "config/render_options.h"
#include "integrators/registry.h"

namespace lightpath {
namespace {

// How --help names an option's value: its choices, else its type.
std::string valueName(const Parameter& p) {
    const std::vector<std::string> choices = optionChoices(p);
    if (!choices.empty()) {
        std::string text = "{";
        for (const std::string& word : choices) text += (text.size() > 1 ? "," : "") + word;
        return text + "}";
    }
    switch (p.type) {
        case ParameterType::Integer: return "INT";
        case ParameterType::Number:
        case ParameterType::NumberOrTexture: return "FLOAT";
        default: return "TEXT";
    }
}

std::string withUnit(std::string help, const Parameter& p) {
    if (!p.unit.empty()) help += " (" + std::string(p.unit) + ")";
    return help;
}

}  // namespace

void RenderFlags::addOptions(CLI::App& command) {
    const auto describe = [](CLI::Option* option, const Parameter& p) {
        option->type_name(valueName(p));
        if (!p.defaultText.empty()) option->default_str(std::string(p.defaultText));
    };
    for (const Parameter& p : renderOptionsSchema().parameters) {
        const std::string name(p.name);
        const std::string help = withUnit(optionHelp(p), p);
        CLI::Option* option = nullptr;
        if (p.required) {
            option = command.add_option(name, texts_[name], help)->required();
        } else if (p.type == ParameterType::Boolean) {
            option = command.add_flag("--" + name, switches_[name], help);
        } else if (name == "lpe") {
            option = command.add_option("--lpe", lpes_, help);
        } else {
            option = command.add_option("--" + name, texts_[name], help);
            describe(option, p);
        }
        options_.emplace_back(name, option);
    }
    // Every integrator's own parameters, once each, as "--NAME" with "INTEGRATOR: " before its doc.
    std::map<std::string, CLI::Option*, std::less<>> added;
    for (const IntegratorInfo& info : integrators()) {
        for (const Parameter& p : info.schema.parameters) {
            if (added.contains(p.name)) continue;
            std::string owners;
            for (const IntegratorInfo& other : integrators())
                if (other.schema.find(p.name)) owners += (owners.empty() ? "" : ", ") + std::string(other.name);
            const std::string name(p.name);
            CLI::Option* option = command.add_option("--" + name, texts_[name], withUnit(owners + ": " + std::string(p.doc), p));
            describe(option, p);
            added.emplace(name, option);
            options_.emplace_back(name, option);
        }
        // The parser refuses options that exclude each other at once, as CLI11 words it.
        for (const Parameter& p : info.schema.parameters)
            if (!p.excludes.empty())
                if (const auto other = added.find(p.excludes); other != added.end())
                    other->second->excludes(added.at(std::string(p.name)));
    }
}

const RenderConfig& RenderFlags::apply() {
    for (const auto& [name, option] : options_) {
        if (option->count() == 0) continue;
        if (name == "lpe") {
            for (const std::string& lpe : lpes_) config_.set(name, lpe);
        } else if (const auto flag = switches_.find(name); flag != switches_.end()) {
            config_.set(name, flag->second ? "true" : "false");
        } else {
            config_.set(name, texts_.at(name));
        }
    }
    config_.validate();
    return config_;
}

void reportingConfigErrors(const std::function<void()>& action) {
    try {
        action();
    } catch (const ConfigError& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }
}

}  // namespace lightpath
