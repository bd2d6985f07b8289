// One render configuration (issue #30, item 2): the command line and serve read the same options
// through RenderConfig, so the same bad value is refused with the same field and message by both;
// an integrator's parameter declared only in its own file becomes a flag, with --help, accepted by
// render and reaching the integrator. The references are the messages as the command line has
// always printed them and values written here by hand.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <memory>
#include <string>
#include <vector>

#include "cli/render_flags.h"
#include "config/render_config.h"
#include "integrators/radiosity.h"
#include "integrators/registry.h"
#include "serve/request_error.h"
#include "serve/settings.h"

using namespace lightpath;

namespace {

// An integrator only this test binary registers, with one parameter of its own: nothing else in
// the code knows of it.
class KnobIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray&, PathState&) const override {}
};

}  // namespace

LIGHTPATH_REGISTER_INTEGRATOR(lightpath::integratorRow(
    "test-knob", "an integrator of the config tests", "E<RD>L", "the test integrator follows one diffuse bounce",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<KnobIntegrator>()); },
    lightpath::ShadowRays::Always, 90,
    {{.name = "knob", .type = lightpath::ParameterType::Integer, .unit = "turns", .defaultText = "3", .range = {1.0, 9.0},
      .doc = "how far the test knob is turned"}}))

namespace {

const std::string kScene = std::string(LIGHTPATH_SOURCE_DIR) + "/scenes/mirror-sphere.toml";

// `lightpath render SCENE ARGS...` parsed by the command line's own flags: the configuration, or
// the ConfigError its one validate() throws.
struct Parsed {
    std::unique_ptr<RenderFlags> flags = std::make_unique<RenderFlags>();
    std::string help;
};

Parsed parse(std::vector<std::string> args) {
    Parsed parsed;
    CLI::App app{"render"};
    parsed.flags->addOptions(app);
    parsed.help = app.help();
    args.insert(args.begin(), kScene);
    std::vector<const char*> argv{"render"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    app.parse(static_cast<int>(argv.size()), argv.data());
    parsed.flags->apply();
    return parsed;
}

// What `render` refuses before rendering: its flags (validate) and its AOVs on the scene.
ConfigError commandLineError(const std::vector<std::string>& args) {
    try {
        const Parsed parsed = parse(args);
        const RenderConfig& config = parsed.flags->config();
        config.buildAovSet(config.loadScene());
    } catch (const ConfigError& e) {
        return e;
    }
    FAIL("the command line accepted what it should refuse");
    return {"", ""};
}

serve::RequestError serveError(const nlohmann::json& body) {
    RenderConfig config;
    config.scenePath = kScene;
    const serve::Settings start = serve::defaultSettings(config.loadScene());
    try {
        serve::applySettings(start, body.dump());
    } catch (const serve::RequestError& e) {
        return e;
    }
    FAIL("serve accepted what it should refuse");
    return {0, "", ""};
}

}  // namespace

TEST_CASE("an expression no path of the integrator can match: one field and one message for render and serve") {
    const ConfigError cli = commandLineError({"--integrator", "raycast", "--lpe", "s=ES+(D|G)L"});
    CHECK(cli.field() == "lpe:s");
    CHECK(std::string(cli.what()) == "--lpe s: " + cli.message());
    CHECK(cli.message().find("'ES+(D|G)L' can never match under --integrator raycast") == 0);

    const serve::RequestError served = serveError(
        {{"integrator", "raycast"}, {"lpes", {{{"name", "s"}, {"expression", "ES+(D|G)L"}}}}});
    CHECK(served.field() == "lpes[0].expression");
    CHECK(std::string(served.what()) == "s: " + cli.message());
}

TEST_CASE("a value out of its option's range: the same field and message from the flag and from code") {
    const ConfigError cli = commandLineError({"--spp", "0"});
    CHECK(cli.field() == "spp");
    CHECK(std::string(cli.what()) == "--spp: Value 0 not in range 1 to 1048576");

    RenderConfig config;  // as serve fills it: plain values, the same one check
    config.scenePath = kScene;
    config.samplesPerPixel = 0;
    try {
        config.validate();
        FAIL("validate accepted spp 0");
    } catch (const ConfigError& e) {
        CHECK(e.field() == cli.field());
        CHECK(e.message() == cli.message());
        const serve::RequestError served = serve::requestError(e, serve::Settings{});
        CHECK(served.field() == "spp");
        CHECK(std::string(served.what()) == "spp: " + cli.message());
    }
}

TEST_CASE("a misspelt integrator is named with a did-you-mean, field integrator") {
    const ConfigError e = commandLineError({"--integrator", "Whitted"});
    CHECK(e.field() == "integrator");
    CHECK(std::string(e.what()).find("--integrator: Whitted is not one of raycast") == 0);
    CHECK(std::string(e.what()).find("did you mean whitted?") != std::string::npos);
}

TEST_CASE("an integrator's parameter declared only in its own file is a flag of render, with --help") {
    const Parsed parsed = parse({"--integrator", "test-knob", "--knob", "7"});
    CHECK(parsed.help.find("--knob") != std::string::npos);
    CHECK(parsed.help.find("test-knob: how far the test knob is turned (turns)") != std::string::npos);
    const RenderConfig& config = parsed.flags->config();
    CHECK(config.integratorValues().integer("knob") == 7);
    const RenderOptions options = config.renderOptions();
    REQUIRE(options.integratorParameters.has_value());
    CHECK(options.integratorParameters->integer("knob") == 7);
    CHECK(parse({"--integrator", "test-knob"}).flags->config().integratorValues().integer("knob") == 3);

    const ConfigError e = commandLineError({"--integrator", "test-knob", "--knob", "10"});
    CHECK(e.field() == "knob");
    CHECK(std::string(e.what()) == "--knob: Value 10 not in range 1 to 9");
}

TEST_CASE("another integrator's parameter is checked and left unused, as before") {
    const Parsed parsed = parse({"--integrator", "path", "--patches", "64"});
    CHECK(parsed.flags->config().renderOptions().integrator == "path");
    CHECK(commandLineError({"--integrator", "path", "--patches", "0"}).field() == "patches");
}

TEST_CASE("radiosity's parameters are its schema's, their defaults those of RadiosityOptions") {
    const IntegratorInfo* radiosity = findIntegrator("radiosity");
    REQUIRE(radiosity != nullptr);
    for (const char* name : {"patch-size", "patches", "form-factor-rays", "light-samples", "radiosity-display"})
        CHECK_MESSAGE(radiosity->schema.find(name) != nullptr, name);
    const RadiosityOptions defaults;
    const RadiosityOptions read = radiosityOptions(ParameterValues(radiosity->schema));
    CHECK(read.patchSize == defaults.patchSize);
    CHECK(read.patchBudget == defaults.patchBudget);
    CHECK(read.formFactorRays == defaults.formFactorRays);
    CHECK(read.lightSamples == defaults.lightSamples);
    CHECK(read.display == defaults.display);

    const RenderOptions options =
        parse({"--integrator", "radiosity", "--patches", "512", "--radiosity-display", "flat"}).flags->config().renderOptions();
    REQUIRE(options.integratorParameters.has_value());
    const RadiosityOptions given = radiosityOptions(*options.integratorParameters);
    CHECK(given.patchBudget == 512);
    CHECK(given.display == RadiosityDisplay::Flat);
    CHECK(commandLineError({"--integrator", "radiosity", "--radiosity-display", "round"}).field() == "radiosity-display");

    RenderConfig both;  // what the parser refuses at once (CLI11's excludes) validate refuses too
    both.scenePath = kScene;
    both.integratorParameters = {{"patch-size", "0.5"}, {"patches", "64"}};
    CHECK_THROWS_WITH_AS(both.validate(), "--patch-size: excludes --patches", ConfigError);
}

// Framing (issue #26 item 5): an OBJ given as the scene has no camera and no light; the render
// gets a camera that sees the whole model and the default light, and says so. The reference: the
// box of assimp's box.obj is [-0.5, 0.5]^3 (its 8 vertices), its corners all in the image, its
// centre pixel lit (grey kd 0.5 facing a light from the camera's side) and the corner pixels the
// black background.
TEST_CASE("an OBJ file without camera or light renders framed and lit, and says what was chosen") {
    RenderConfig config;
    config.scenePath = LIGHTPATH_SOURCE_DIR "/tests/scene/data/assimp-obj/box.obj";
    config.resolution = "40x20";
    config.quiet = true;
    const Scene scene = config.loadScene();
    CHECK(!scene.cameraGiven);
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0]->name == kDefaultLightName);
    CHECK(scene.camera.width == 40);
    CHECK(scene.camera.lookAt == Vec3(0.0f));
    const Camera camera(scene.camera);
    for (int k = 0; k < 8; ++k) CHECK(camera.project(Vec3(k & 1 ? 0.5f : -0.5f, k & 2 ? 0.5f : -0.5f, k & 4 ? 0.5f : -0.5f)));

    RenderOptions options;
    options.integrator = "raycast";
    options.samplesPerPixel = 1;
    const AovSet aovs(config.expressions(&scene));
    const Film film = Renderer(scene, aovs, options).render().film;
    CHECK(film.at(0, 20, 10).r > 0.05f);
    CHECK(isBlack(film.at(0, 0, 0)));
    CHECK(isBlack(film.at(0, 39, 19)));

    // A scene with a camera and a light is left as it is, unless --fit.
    RenderConfig lit;
    lit.scenePath = LIGHTPATH_SOURCE_DIR "/scenes/bunny.toml";
    lit.quiet = true;
    const Scene asWritten = lit.loadScene();
    CHECK(asWritten.camera.eye == Vec3(0.0f, 1.5f, 4.2f));
    lit.fit = true;
    const Scene fitted = lit.loadScene();
    CHECK(fitted.camera.eye != asWritten.camera.eye);
    CHECK(fitted.lights.size() == asWritten.lights.size());
}
