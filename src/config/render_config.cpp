#include "config/render_config.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <type_traits>
#include <optional>
#include <stdexcept>
#include <variant>

#include "config/lpe_verdict.h"
#include "config/messages.h"
#include "config/render_options.h"
#include "film/aov_presets.h"
#include "lights/point_light.h"
#include "lpe/analysis.h"
#include "lpe/error.h"
#include "lpe/path_string.h"
#include "lpe/reading.h"
#include "render/memory_limit.h"
#include "schema/format.h"
#include "schema/schema_error.h"
#include "scene/emission.h"
#include "scene/framing.h"
#include "scene/scene_loader.h"

namespace lightpath {

namespace {

std::string commandLineText(const std::string& field, const std::string& message) {
    if (field.empty() || field == "scene") return message;
    if (field.rfind("lpe:", 0) == 0) return "--lpe " + field.substr(4) + ": " + message;
    return "--" + field + ": " + message;
}

}  // namespace

ConfigError::ConfigError(std::string field, std::string message)
    : std::runtime_error(commandLineText(field, message)), field_(std::move(field)), message_(std::move(message)) {}

ConfigError lpeError(const std::string& name, const std::string& message) { return {"lpe:" + name, message}; }

namespace {

// Where each render option of the schema lives in RenderConfig: the one table from names to fields.
using Member = std::variant<std::string RenderConfig::*, std::vector<std::string> RenderConfig::*, int RenderConfig::*,
                            std::uint64_t RenderConfig::*, double RenderConfig::*, float RenderConfig::*,
                            bool RenderConfig::*>;
struct Binding {
    std::string_view option;
    Member member;
};
const Binding kBindings[] = {
    {"scene", &RenderConfig::scenePath},
    {"integrator", &RenderConfig::integrator},
    {"lpe", &RenderConfig::lpes},
    {"aovs", &RenderConfig::aovs},
    {"spp", &RenderConfig::samplesPerPixel},
    {"sampler", &RenderConfig::sampler},
    {"filter", &RenderConfig::filter},
    {"target-error", &RenderConfig::targetError},
    {"max-depth", &RenderConfig::maxDepth},
    {"resolution", &RenderConfig::resolution},
    {"threads", &RenderConfig::threads},
    {"seed", &RenderConfig::seed},
    {"no-beauty", &RenderConfig::noBeauty},
    {"accel", &RenderConfig::accel},
    {"quiet", &RenderConfig::quiet},
    {"robust", &RenderConfig::robust},
    {"sphere-test", &RenderConfig::sphereTest},
    {"triangle-test", &RenderConfig::triangleTest},
    {"ray-offset", &RenderConfig::rayOffset},
    {"epsilon", &RenderConfig::epsilon},
    {"shadows", &RenderConfig::shadows},
    {"no-skip", &RenderConfig::noSkip},
    {"fit", &RenderConfig::fit},
};

const Member& memberOf(const Parameter& option) {
    for (const Binding& b : kBindings)
        if (b.option == option.name) return b.member;
    throw std::logic_error("render option \"" + std::string(option.name) + "\" has no field in RenderConfig");
}

// A value as typed on the command line, read as its parameter's type.
using Typed = std::variant<long long, double, bool, std::string>;

Typed parseTyped(const Parameter& p, const std::string& text) {
    const std::string field(p.name);
    switch (p.type) {
        case ParameterType::Integer: {
            long long value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc() || end != text.data() + text.size())
                throw ConfigError(field, "expected an integer, got \"" + text + "\"");
            return value;
        }
        case ParameterType::Number:
        case ParameterType::NumberOrTexture: {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
                throw ConfigError(field, "expected a number, got \"" + text + "\"");
            return value;
        }
        case ParameterType::Boolean:
            if (text == "true" || text == "on") return true;
            if (text == "false" || text == "off") return false;
            throw ConfigError(field, "expected true or false, got \"" + text + "\"");
        case ParameterType::Name:
        case ParameterType::Text: return text;
        default: throw ConfigError(field, "cannot be given as text");
    }
}

// CLI11's wording for an integer out of a closed range, which the command line has always printed.
std::string outOfRange(const Parameter& p, double value) {
    const Range& r = p.range;
    const auto integer = [](double v) { return std::to_string(static_cast<long long>(v)); };
    if (p.type == ParameterType::Integer && !std::isinf(r.low) && !std::isinf(r.high) && !r.lowExclusive && !r.highExclusive)
        return "Value " + integer(value) + " not in range " + integer(r.low) + " to " + integer(r.high);
    return "expected a " + std::string(typeName(p.type)) + " " + r.describe() + ", got " +
           (p.type == ParameterType::Integer ? integer(value) : formatNumber(value));
}

void checkNumber(const Parameter& p, double value) {
    if (!p.range.admits(value)) throw ConfigError(std::string(p.name), outOfRange(p, value));
}

// A word of an option with choices: empty is allowed where the option has no default (unset).
void checkWord(const Parameter& p, const std::string& value) {
    const std::vector<std::string> choices = optionChoices(p);
    if (choices.empty() || (value.empty() && p.defaultText.empty())) return;
    if (std::find(choices.begin(), choices.end(), value) == choices.end())
        throw ConfigError(std::string(p.name), choiceMessage(value, choices));
}

// One parameter of an integrator's schema, checked and set in `values`.
void assign(ParameterValues& values, const Parameter& p, const std::string& text) {
    const Typed typed = parseTyped(p, text);
    try {
        if (const auto* i = std::get_if<long long>(&typed)) {
            checkNumber(p, static_cast<double>(*i));
            values.set(p.name, static_cast<int>(*i));
        } else if (const auto* d = std::get_if<double>(&typed)) {
            checkNumber(p, *d);
            values.set(p.name, *d);
        } else if (const auto* b = std::get_if<bool>(&typed)) {
            values.set(p.name, *b);
        } else {
            checkWord(p, std::get<std::string>(typed));
            values.set(p.name, std::get<std::string>(typed));
        }
    } catch (const SchemaError& e) {
        throw ConfigError(std::string(p.name), e.what());
    }
}

struct Resolution {
    int width = 0, height = 0;
};

std::optional<Resolution> parseResolution(const std::string& text) {
    if (text.empty()) return std::nullopt;
    Resolution r;
    char x = 0, extra = 0;
    const int read = std::sscanf(text.c_str(), "%d%c%d%c", &r.width, &x, &r.height, &extra);
    if (read != 3 || (x != 'x' && x != 'X'))
        throw ConfigError("resolution", "expected WIDTHxHEIGHT such as 640x480, got \"" + text + "\"");
    if (r.width < 1 || r.height < 1 || r.width > kMaxResolution || r.height > kMaxResolution)
        throw ConfigError("resolution", "each side must be 1.." + std::to_string(kMaxResolution) + ", got " + text);
    return r;
}

// The integrators whose schema has the parameter `name`.
std::vector<const IntegratorInfo*> ownersOf(std::string_view name) {
    std::vector<const IntegratorInfo*> owners;
    for (const IntegratorInfo& info : integrators())
        if (info.schema.find(name)) owners.push_back(&info);
    return owners;
}

}  // namespace

RenderConfig::RenderConfig() {
    for (const Parameter& p : renderOptionsSchema().parameters) {
        memberOf(p);  // every option has its field
        if (!p.defaultText.empty()) set(p.name, std::string(p.defaultText));
    }
}

void RenderConfig::set(std::string_view name, const std::string& text) {
    const Parameter* p = renderOptionsSchema().find(name);
    if (!p) {
        if (ownersOf(name).empty()) throw ConfigError(std::string(name), "no render option or integrator parameter of this name");
        integratorParameters[std::string(name)] = text;
        return;
    }
    const Typed typed = parseTyped(*p, text);
    const auto integerInto = [&](auto RenderConfig::*member) {
        using Field = std::remove_reference_t<decltype(this->*member)>;
        const long long value = std::get<long long>(typed);
        if (value < static_cast<long long>(std::numeric_limits<Field>::min()) ||
            static_cast<unsigned long long>(value) > static_cast<unsigned long long>(std::numeric_limits<Field>::max()))
            throw ConfigError(std::string(p->name), outOfRange(*p, static_cast<double>(value)));
        this->*member = static_cast<Field>(value);
    };
    std::visit(
        [&](auto member) {
            using Field = std::remove_reference_t<decltype(this->*member)>;
            if constexpr (std::is_same_v<Field, std::vector<std::string>>) (this->*member).push_back(std::get<std::string>(typed));
            else if constexpr (std::is_same_v<Field, std::string>) this->*member = std::get<std::string>(typed);
            else if constexpr (std::is_same_v<Field, bool>) this->*member = std::get<bool>(typed);
            else if constexpr (std::is_floating_point_v<Field>) this->*member = static_cast<Field>(std::get<double>(typed));
            else integerInto(member);
        },
        memberOf(*p));
}

void RenderConfig::validate() const {
    for (const Parameter& p : renderOptionsSchema().parameters) {
        std::visit(
            [&](auto member) {
                using Field = std::remove_cvref_t<decltype(this->*member)>;
                const Field& value = this->*member;
                if constexpr (std::is_same_v<Field, std::string>) checkWord(p, value);
                else if constexpr (std::is_arithmetic_v<Field> && !std::is_same_v<Field, bool>)
                    checkNumber(p, static_cast<double>(value));
            },
            memberOf(p));
    }
    parseResolution(resolution);
    for (const auto& [name, text] : integratorParameters) {
        const auto owners = ownersOf(name);
        if (owners.empty()) throw ConfigError(name, "no integrator has a parameter of this name");
        for (const IntegratorInfo* owner : owners) {
            ParameterValues values(owner->schema);
            const Parameter& p = *owner->schema.find(name);
            assign(values, p, text);
            if (!p.excludes.empty() && integratorParameters.contains(p.excludes))
                throw ConfigError(name, "excludes --" + std::string(p.excludes));
        }
    }
}

ParameterValues RenderConfig::integratorValues() const {
    const IntegratorInfo* info = findIntegrator(integrator);
    if (!info) throw ConfigError("integrator", choiceMessage(integrator, integratorNames()));
    ParameterValues values(info->schema);
    for (const Parameter& p : info->schema.parameters)
        if (const auto given = integratorParameters.find(p.name); given != integratorParameters.end())
            assign(values, p, given->second);
    return values;
}

namespace {

// Whether anything in `scene` gives light: a light of [[lights]] or an emitting surface
// (scene/emission.h). A bright background is not counted: only the path tracer and bdpt gather it.
bool hasLight(const Scene& scene) {
    if (!scene.lights.empty()) return true;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        if (emissionEventOf(scene, i)) return true;
    return false;
}

// Gives a scene without any light kDefaultLightName, a point light above and to the left of its
// camera's eye; says so.
std::string addDefaultLight(Scene& scene) {
    const Camera view(scene.camera);
    const Vec3 right = glm::normalize(glm::cross(view.forward(), scene.camera.up));
    const Vec3 up = glm::cross(right, view.forward());
    const float distance = glm::length(scene.camera.lookAt - scene.camera.eye);
    const Vec3 position = scene.camera.eye + kDefaultLightOffset * distance * (up - right);
    scene.lights.emplace_back(PointLight(std::string(kDefaultLightName), position, Rgb(1.0f), Vec3(1.0f, 0.0f, 0.0f)));
    return "it has no light: a point light \"" + std::string(kDefaultLightName) + "\" of intensity 1 at " +
           formatVec3(position) + ", above and left of the eye";
}

// A scene seen by a camera chosen for it (scene/framing.h): one without [camera] from the front,
// a little above and to the right; under --fit along its own camera's view. Without any light it
// gets kDefaultLightName, a point light above and to the left of the eye (scenes/README.md,
// "Framing"). A warning says what was chosen.
void frameScene(Scene& scene, const Warnings& warn) {
    if (!scene.cameraGiven) {
        scene.camera.eye = kFramingDirection;
        scene.camera.lookAt = Vec3(0.0f);
    }
    const Bounds bounds = sceneBounds(scene);
    scene.camera = framingCamera(bounds, scene.camera);
    std::string chosen = (scene.cameraGiven ? "--fit: the camera" : "the scene has no [camera]: a camera") +
                         std::string(" at ") + formatVec3(scene.camera.eye) + " looks at " +
                         formatVec3(scene.camera.lookAt) + (bounds.empty() ? " (the scene has no bounded shape)" : " and sees all of it");
    if (!hasLight(scene)) chosen += "; " + addDefaultLight(scene);
    warn(chosen);
}

}  // namespace

Scene RenderConfig::loadScene() const {
    Scene scene;
    try {
        scene = lightpath::loadScene(scenePath);
    } catch (const SceneError& e) {
        throw ConfigError("scene", e.what());
    }
    const Warnings warn(quiet);
    for (const std::string& warning : scene.warnings) warn(warning);
    if (const auto size = parseResolution(resolution)) {
        scene.camera.width = size->width;
        scene.camera.height = size->height;
    }
    if (fit || !scene.cameraGiven) {
        frameScene(scene, warn);
    } else if (isGltfFile(scenePath) && !hasLight(scene)) {
        // A glTF file given as the scene brings its camera but may bring no light: lit as a
        // framed model is (scenes/README.md, "Framing").
        warn(std::filesystem::path(scenePath).filename().string() + ": " + addDefaultLight(scene));
    }
    return scene;
}

std::vector<lpe::NamedExpression> RenderConfig::expressions(const Scene* scene) const {
    std::vector<lpe::NamedExpression> set;
    const std::string preset = aovs.empty() ? (lpes.empty() ? "classes" : "none") : aovs;
    if (const AovPreset* found = findAovPreset(preset)) set = found->expressions(scene);
    for (std::size_t i = 0; i < lpes.size(); ++i) set.push_back(parseNamedExpression(lpes[i], i + 1));
    return set;
}

namespace {

// The one judge (config/lpe_verdict.h) decides: an AOV no path of this integrator can match in any
// scene is refused before the render, with the reason; one only black in this scene (a label it
// lacks, a volume) is rendered with one short warning; a preset's AOV the integrator cannot fill is
// written black and said in --stats, not warned about.
void refuseNeverFilled(const std::vector<lpe::NamedExpression>& set, const Judge& judge,
                       const std::function<void(const std::string&)>& warn) {
    for (const auto& e : set) {
        const Judgement& judgement = judge(e);
        if (judgement.verdict == Verdict::Refused)
            throw lpeError(e.name, refusalMessage(e, judge.integrator(), judgement.reason));
        if (judgement.verdict != Verdict::PresetBlack && !judgement.reason.empty()) warn(warningMessage(e, judgement));
    }
}

}  // namespace

namespace {

// A scene with media under an integrator that ignores them would render as in vacuum, silently
// wrong: refused, naming the media and the integrators that render them.
void refuseMedia(const IntegratorInfo& info, const Scene& scene) {
    if (info.rendersMedia) return;
    if (scene.media.empty()) {
        // An interface material is a medium boundary: an integrator that ignores media would shade
        // it as a black surface.
        if (!scene.interfaces) return;
        throw ConfigError("integrator", std::string(info.name) + " does not cross index-matched boundaries, and " +
                                            scene.source.filename().string() +
                                            " has an `interface` material: render it with " + mediaRenderers());
    }
    std::string media;
    for (const MediumSlot& medium : scene.media) media += (media.empty() ? "'" : ", '") + medium->name + "'";
    const std::string renderers = mediaRenderers();
    throw ConfigError("integrator", std::string(info.name) + " does not render participating media, and " +
                                        scene.source.filename().string() + " declares " + media + ": " +
                                        (renderers.empty() ? "no integrator renders them yet"
                                                           : "render it with " + renderers));
}

}  // namespace

Judge RenderConfig::judge(const Scene& scene) const {
    const IntegratorInfo* info = findIntegrator(integrator);
    if (!info) throw ConfigError("integrator", choiceMessage(integrator, integratorNames()));
    refuseMedia(*info, scene);
    return Judge(info, &scene);
}

AovSet RenderConfig::buildAovSet(const Scene& scene, std::vector<std::string>* warnings) const {
    return buildAovSet(scene, judge(scene), warnings);
}

AovSet RenderConfig::buildAovSet(const Scene& scene, const Judge& judge, std::vector<std::string>* warnings) const {
    const auto set = expressions(&scene);
    std::optional<AovSet> built;
    try {
        built.emplace(set);
    } catch (const lpe::SyntaxError& e) {
        for (const auto& expression : set)
            if (expression.expression == e.text()) throw lpeError(expression.name, e.what());
        throw ConfigError("lpe", e.what());
    } catch (const std::exception& e) {
        throw ConfigError("lpe", e.what());
    }
    const Warnings printed(quiet);
    const auto warn = [&](const std::string& message) {
        if (warnings != nullptr) warnings->push_back(message);
        else printed(message);
    };
    refuseNeverFilled(set, judge, warn);
    // Presets never warn about themselves: the taxonomy's AOVs overlap on purpose.
    for (const auto& e : set)
        if (!isPresetMember(e))
            for (const std::string& warning : lpe::readExpression(e.expression).warnings) warn("--lpe " + e.name + ": " + warning);
    if (set.size() > 1) {
        // Overlapping AOVs count the same light twice; say so with a path both accept. Not among a
        // preset's own AOVs, nor for an AOV black in this scene (it counts nothing).
        const auto blackHere = [&](const lpe::NamedExpression& e) { return judge(e).verdict == Verdict::BlackHere; };
        for (const lpe::Overlap& o : lpe::analyse(set, "E.*L").overlaps) {
            const auto& a = set[o.first];
            const auto& b = set[o.second];
            if ((isPresetMember(a) && isPresetMember(b)) || blackHere(a) || blackHere(b)) continue;
            warn("AOVs " + a.name + " and " + b.name + " overlap: both accept " + lpe::toCompactString(o.example) + " (" +
                 lpe::toExpressionString(o.example) + "); their sum counts such light twice");
        }
    }
    return std::move(*built);
}

void RenderConfig::warnEmptyAovs(const Film& film, const AovSet& aovs, const Judge& judge) const {
    const Warnings warn(quiet);
    for (std::size_t o = 0; o < aovs.expressions().size(); ++o) {
        const std::size_t layer = o + 1;  // after the beauty
        bool empty = true;
        for (int y = 0; y < film.height() && empty; ++y)
            for (int x = 0; x < film.width() && empty; ++x) empty = isBlack(film.at(layer, x, y));
        const auto& e = aovs.expressions()[o];
        // AOVs that can never be filled here were refused, warned about or noted before the render.
        if (!empty || judge(e).verdict != Verdict::Fillable) continue;
        warn("AOV " + e.name + " (" + e.expression + ") received nothing in this render: --integrator " + integrator +
             " can produce its paths, but none reached it at " + std::to_string(film.width()) + "x" +
             std::to_string(film.height()) + ", " + std::to_string(samplesPerPixel) + " spp, --max-depth " +
             std::to_string(maxDepth));
    }
}

void RenderConfig::refuseBeyondMemory(const PixelMemory& memory, std::uint64_t outputBytes) const {
    const std::uint64_t needed = memory.total() + outputBytes;
    const MemoryLimit limit = memoryLimit();
    if (needed <= limit.bytes) return;
    std::string parts;
    const auto part = [&](std::uint64_t bytes, const std::string& what) {
        if (bytes > 0) parts += (parts.empty() ? "" : ", ") + what + " " + formatBytes(bytes);
    };
    part(memory.film, "film");
    part(memory.splats, "splat film");
    part(memory.preprocess, integrator + "'s preprocess");
    part(outputBytes, "PNG encoding");
    // Every part grows with the pixels: scaling both sides by sqrt(limit / needed) fits.
    const double scale = std::sqrt(static_cast<double>(limit.bytes) / static_cast<double>(needed));
    const int width = std::max(1, static_cast<int>(memory.width * scale));
    const int height = std::max(1, static_cast<int>(memory.height * scale));
    std::string change = "render fewer pixels (--resolution " + std::to_string(width) + "x" + std::to_string(height) + " fits)";
    if (memory.film > 0)
        change = "render fewer layers (--aovs none keeps beauty and rest; fewer --lpe; --no-beauty) or " + change;
    throw ConfigError("", memory.describe() + " needs " + formatBytes(needed) + " of memory (" + parts + "), more than the " +
                              formatBytes(limit.bytes) + " that " + limit.bound + " leaves this process: " + change);
}

RenderOptions RenderConfig::renderOptions() const {
    RenderOptions options;
    options.integrator = integrator;
    options.maxDepth = maxDepth;
    options.samplesPerPixel = samplesPerPixel;
    options.threads = threads;
    options.seed = seed;
    parseSamplerKind(sampler, options.sampler);    // validated against the schema's choices
    parsePixelFilterKind(filter, options.filter);  // likewise
    options.targetError = targetError;
    options.writeBeauty = !noBeauty;
    options.skip = !noSkip;
    if (!shadows.empty()) options.shadows = shadows == "on";
    options.accelerator = accel == "embree" ? Accelerator::Embree
                          : accel == "none" ? Accelerator::BruteForce
                                            : Accelerator::Bvh;
    options.progress = !quiet;
    options.numerics = robust == "off" ? NumericsOptions::naive() : NumericsOptions{};
    if (!sphereTest.empty()) options.numerics.sphere = sphereTest == "naive" ? SphereTest::Naive : SphereTest::Stable;
    if (!triangleTest.empty())
        options.numerics.triangle = triangleTest == "watertight" ? TriangleTest::Watertight : TriangleTest::MollerTrumbore;
    if (!rayOffset.empty())
        options.numerics.offset = rayOffset == "robust"           ? RayOffset::Robust
                                  : rayOffset == "wachter-binder" ? RayOffset::WachterBinder
                                  : rayOffset == "epsilon"        ? RayOffset::FixedEpsilon
                                  : rayOffset == "none"           ? RayOffset::None
                                                                  : RayOffset::OwnPrimitive;
    options.numerics.epsilon = epsilon;
    options.integratorParameters = integratorValues();
    return options;
}

}  // namespace lightpath
