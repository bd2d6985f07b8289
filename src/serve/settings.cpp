#include "serve/settings.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>

#include "config/lpe_verdict.h"
#include "config/render_options.h"
#include "film/aov_presets.h"
#include "integrators/registry.h"
#include "transport/path_event.h"
#include "serve/request_error.h"

namespace lightpath::serve {
namespace {

using nlohmann::json;

// Each JSON field and the render option it sets (config/render_options.h).
struct Field {
    std::string_view json;
    std::string_view option;
};
constexpr Field kFields[] = {{"integrator", "integrator"}, {"spp", "spp"},        {"width", "resolution"},
                             {"height", "resolution"},     {"maxDepth", "max-depth"}, {"lpes", "lpe"}};

const Parameter& optionOf(std::string_view json) {
    for (const Field& f : kFields)
        if (f.json == json) return *renderOptionsSchema().find(f.option);
    throw std::logic_error("serve: no render option behind the field " + std::string(json));
}

// An integer field: the range of its render option, no wider than the session's `limit`.
int integerOption(const json& value, const std::string& field, int limit);

[[noreturn]] void bad(const std::string& field, const std::string& message) {
    throw RequestError(400, field, field + ": " + message);
}

std::string describe(const json& value) {
    const std::string text = value.dump();
    return text.size() > 40 ? text.substr(0, 40) + "..." : text;
}

int integerIn(const json& value, const std::string& field, int low, int high) {
    const std::string expected = "expected an integer " + std::to_string(low) + ".." + std::to_string(high);
    if (!value.is_number_integer()) bad(field, expected + ", got " + describe(value));
    const bool inRange = value.is_number_unsigned() ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(high) &&
                                                          value.get<std::uint64_t>() >= static_cast<std::uint64_t>(std::max(low, 0))
                                                    : value.get<std::int64_t>() >= low && value.get<std::int64_t>() <= high;
    if (!inRange) bad(field, expected + ", got " + describe(value));
    return static_cast<int>(value.get<std::int64_t>());
}

// The parameter `name` of the first integrator whose schema has one, or nullptr.
const Parameter* integratorParameter(std::string_view name) {
    for (const IntegratorInfo& info : integrators())
        if (const Parameter* p = info.schema.find(name)) return p;
    return nullptr;
}

std::string integratorParameterNames() {
    std::string names;
    for (const IntegratorInfo& info : integrators())
        for (const Parameter& p : info.schema.parameters)
            names += (names.empty() ? "" : ", ") + std::string(p.name) + " (" + info.name + ")";
    return names;
}

int integerOption(const json& value, const std::string& field, int limit) {
    const Range& range = optionOf(field).range;
    return integerIn(value, field, static_cast<int>(range.low), std::min(limit, static_cast<int>(range.high)));
}

std::string stringOf(const json& value, const std::string& field, std::size_t maxLength) {
    if (!value.is_string()) bad(field, "expected a string, got " + describe(value));
    const std::string& text = value.get_ref<const std::string&>();
    if (text.size() > maxLength)
        bad(field, "expected at most " + std::to_string(maxLength) + " characters, got " + std::to_string(text.size()));
    return text;
}

std::vector<lpe::NamedExpression> expressionsOf(const json& value) {
    if (!value.is_array()) bad("lpes", "expected an array of {\"name\", \"expression\"} objects, got " + describe(value));
    if (value.size() > kMaxExpressions)
        bad("lpes", "expected at most " + std::to_string(kMaxExpressions) + " expressions, got " + std::to_string(value.size()));
    std::vector<lpe::NamedExpression> list;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = "lpes[" + std::to_string(i) + "]";
        const json& item = value[i];
        if (!item.is_object()) bad(at, "expected an object {\"name\", \"expression\"}, got " + describe(item));
        for (const auto& [key, unused] : item.items())
            if (key != "name" && key != "expression") bad(at + "." + key, "unknown field; expected name or expression");
        if (!item.contains("name") || !item.contains("expression")) bad(at, "expected both \"name\" and \"expression\"");
        list.push_back({stringOf(item["name"], at + ".name", 64), stringOf(item["expression"], at + ".expression", kMaxExpressionLength)});
    }
    return list;
}

// {"patches": 1024, ...}: each value as the command line would take it typed (`--patches 1024`);
// its type and range are the render configuration's to check (RenderConfig::validate).
std::map<std::string, std::string, std::less<>> parametersOf(const json& value) {
    if (!value.is_object())
        bad("parameters", "expected an object of integrator parameters such as {\"patches\": 1024}, got " + describe(value));
    std::map<std::string, std::string, std::less<>> parameters;
    for (const auto& [name, given] : value.items()) {
        if (name.size() > 64) bad("parameters", "expected parameter names of at most 64 characters");
        const std::string at = "parameters." + name;
        if (!integratorParameter(name)) bad(at, "no integrator has a parameter of this name; expected one of " + integratorParameterNames());
        if (given.is_string()) parameters[name] = stringOf(given, at, 64);
        else if (given.is_boolean()) parameters[name] = given.get<bool>() ? "true" : "false";
        else if (given.is_number()) parameters[name] = given.dump();
        else bad(at, "expected a number, a string or a boolean, got " + describe(given));
    }
    return parameters;
}

// A parameter's text as JSON of its type: a number for Number and Integer, a boolean for Boolean.
json typedJson(std::string_view name, const std::string& text) {
    const Parameter* p = integratorParameter(name);
    const json parsed = json::parse(text, nullptr, false);
    if (!p || parsed.is_discarded()) return text;
    const bool numeric = p->type == ParameterType::Number || p->type == ParameterType::Integer;
    if ((numeric && parsed.is_number()) || (p->type == ParameterType::Boolean && parsed.is_boolean())) return parsed;
    return text;
}

json rangeBound(double bound) { return std::isfinite(bound) ? json(bound) : json(nullptr); }

}  // namespace

bool Settings::operator==(const Settings& other) const {
    const auto same = [](const lpe::NamedExpression& a, const lpe::NamedExpression& b) {
        return a.name == b.name && a.expression == b.expression;
    };
    return integrator == other.integrator && samplesPerPixel == other.samplesPerPixel && width == other.width &&
           height == other.height && maxDepth == other.maxDepth && parameters == other.parameters &&
           std::equal(lpes.begin(), lpes.end(), other.lpes.begin(), other.lpes.end(), same);
}

Settings defaultSettings(const Scene& scene) {
    Settings settings;
    settings.width = scene.camera.width;
    settings.height = scene.camera.height;
    settings.lpes = classesSet();
    return settings;
}

Settings applySettings(const Settings& current, const std::string& body, std::vector<std::string>* notices) {
    const json request = json::parse(body, nullptr, false);
    if (request.is_discarded()) throw RequestError(400, "", "malformed JSON: expected an object such as {\"spp\": 16}");
    if (!request.is_object()) throw RequestError(400, "", "expected a JSON object, got " + describe(request));
    Settings settings = current;
    for (const auto& [key, value] : request.items()) {
        const std::string& field = key;  // clang 14 cannot capture a structured binding
        if (field != "parameters" &&
            std::none_of(std::begin(kFields), std::end(kFields), [&](const Field& f) { return f.json == field; })) {
            std::string known;
            for (const Field& f : kFields) known += (known.empty() ? "" : ", ") + std::string(f.json);
            bad(key, "unknown field; expected one of " + known + ", parameters");
        }
        if (key == "parameters") {
            settings.parameters = parametersOf(value);
        } else if (key == "integrator") {
            settings.integrator = stringOf(value, key, 64);
            const auto names = integratorNames();
            if (std::find(names.begin(), names.end(), settings.integrator) == names.end()) {
                std::string known;
                for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
                bad(key, "unknown integrator \"" + settings.integrator + "\"; expected one of " + known);
            }
        } else if (key == "spp") {
            settings.samplesPerPixel = integerOption(value, key, kMaxSamples);
        } else if (key == "width") {
            settings.width = integerIn(value, key, 1, std::min(kMaxSide, kMaxResolution));
        } else if (key == "height") {
            settings.height = integerIn(value, key, 1, std::min(kMaxSide, kMaxResolution));
        } else if (key == "maxDepth") {
            settings.maxDepth = integerOption(value, key, std::numeric_limits<int>::max());
        } else {
            settings.lpes = expressionsOf(value);
        }
    }
    // The command line's one judge (config/lpe_verdict.h): what render refuses under this integrator
    // is refused here. A syntax error is left to the session, which reports its column.
    const IntegratorInfo* integrator = findIntegrator(settings.integrator);
    for (std::size_t i = 0; i < settings.lpes.size(); ++i) {
        const lpe::NamedExpression& aov = settings.lpes[i];
        std::optional<Judgement> judgement;
        try {
            judgement = judgeExpression(aov, integrator);
        } catch (const std::exception&) {
            continue;
        }
        if (judgement->verdict == Verdict::Refused)
            throw requestError(lpeError(aov.name, refusalMessage(aov, integrator, judgement->reason)), settings);
    }
    // The rasteriser samples each pixel once, at its centre (Integrator::samplesPixelCentres): any
    // other target is taken as 1, with a notice, so that switching to it from the page's default
    // 16 spp is not refused halfway.
    if (const IntegratorInfo* info = findIntegrator(settings.integrator);
        info && settings.samplesPerPixel != 1 && info->make()->samplesPixelCentres()) {
        if (notices)
            notices->push_back("spp: the " + settings.integrator + " integrator samples each pixel once, at its centre: "
                               "spp 1 instead of " + std::to_string(settings.samplesPerPixel));
        settings.samplesPerPixel = 1;
    }
    const std::int64_t pixelLayers =
        std::int64_t{settings.width} * settings.height * static_cast<std::int64_t>(settings.lpes.size() + 2);
    if (pixelLayers > kMaxPixelLayers)
        throw RequestError(400, "width,height",
                           "width,height: " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                               " pixels times " + std::to_string(settings.lpes.size() + 2) + " layers is " +
                               std::to_string(pixelLayers) + "; expected at most " + std::to_string(kMaxPixelLayers));
    return settings;
}

RenderConfig renderConfig(const Settings& settings, const std::string& scenePath) {
    RenderConfig config;
    config.scenePath = scenePath;
    config.integrator = settings.integrator;
    config.aovs = "none";
    for (const auto& e : settings.lpes) config.lpes.push_back(e.name + "=" + e.expression);
    config.samplesPerPixel = settings.samplesPerPixel;
    config.maxDepth = settings.maxDepth;
    config.integratorParameters = settings.parameters;
    config.quiet = true;
    return config;
}

RequestError requestError(const ConfigError& error, const Settings& settings) {
    const std::string& option = error.field();
    std::string field = option, label = option;
    if (option.rfind("lpe:", 0) == 0) {
        label = option.substr(4);
        field = "lpes";
        for (std::size_t i = 0; i < settings.lpes.size(); ++i)
            if (settings.lpes[i].name == label) field = "lpes[" + std::to_string(i) + "].expression";
    } else if (integratorParameter(option)) {
        field = label = "parameters." + option;
    } else {
        for (const Field& f : kFields)
            if (f.option == option) field = label = f.option == "resolution" ? "width,height" : std::string(f.json);
    }
    return RequestError(400, field, label.empty() ? error.message() : label + ": " + error.message());
}

nlohmann::json toJson(const Settings& settings) {
    json lpes = json::array();
    for (const auto& e : settings.lpes) lpes.push_back({{"name", e.name}, {"expression", e.expression}});
    json parameters = json::object();
    for (const auto& [name, text] : settings.parameters) parameters[name] = typedJson(name, text);
    return {{"integrator", settings.integrator}, {"spp", settings.samplesPerPixel}, {"width", settings.width},
            {"height", settings.height},         {"maxDepth", settings.maxDepth},   {"lpes", lpes},
            {"parameters", parameters}};
}

json integratorParametersJson() {
    json all = json::object();
    for (const IntegratorInfo& info : integrators()) {
        json list = json::array();
        for (const Parameter& p : info.schema.parameters) {
            json choices = json::array();
            for (const std::string& c : choicesOf(p)) choices.push_back(c);
            list.push_back({{"name", p.name},
                            {"type", typeName(p.type)},
                            {"unit", p.unit},
                            {"default", p.defaultText},
                            {"low", rangeBound(p.range.low)},
                            {"high", rangeBound(p.range.high)},
                            {"lowExclusive", p.range.lowExclusive},
                            {"highExclusive", p.range.highExclusive},
                            {"choices", choices},
                            {"doc", p.doc},
                            {"excludes", p.excludes}});
        }
        all[info.name] = list;
    }
    return all;
}

}  // namespace lightpath::serve
