// The HTTP API of `lightpath serve` (docs/serve.md): requests in, JSON and images out, every
// class of refused request, a cancelled render and concurrent requests.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <atomic>
#include <optional>
#include <cstring>
#include <regex>
#include <vector>

#include "config/render_config.h"
#include "film/aov_presets.h"
#include "integrators/registry.h"
#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "lpe/path_string.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "serve/scene_report.h"
#include "serve_fixture.h"

using namespace lightpath;
using namespace lightpath::serve;
using namespace lightpath::serve::test;

namespace {

// A float image decoded from bytes: channel names and interleaved values.
struct Decoded {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> values;
    float at(int x, int y, const std::string& channel) const {
        const auto c = std::find(channels.begin(), channels.end(), channel);
        REQUIRE(c != channels.end());
        return values[(static_cast<std::size_t>(y) * width + x) * channels.size() + (c - channels.begin())];
    }
};

Decoded decode(const std::string& bytes, const char* name) {
    OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::open(name, nullptr, &reader);
    REQUIRE(in);
    const OIIO::ImageSpec& spec = in->spec();
    Decoded d{spec.width, spec.height, spec.channelnames, {}};
    d.values.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, d.values.data()));
    return d;
}

json settingsFor(int width, int height, int spp, const std::string& integrator = "whitted") {
    return {{"width", width}, {"height", height}, {"spp", spp}, {"integrator", integrator}};
}

// Compares the served EXR's layers with a film rendered by the renderer itself.
void checkSameAsFilm(const Decoded& exr, const Film& film) {
    REQUIRE(exr.width == film.width());
    REQUIRE(exr.height == film.height());
    for (std::size_t l = 0; l < film.layerCount(); ++l) {
        const std::string prefix = l == 0 ? "" : film.layerNames()[l] + ".";
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x)
                for (int c = 0; c < 3; ++c) {
                    const float served = exr.at(x, y, prefix + "RGB"[c]);
                    const float expected = film.at(l, x, y)[c];
                    if (std::abs(served - expected) > 1e-6f * std::max(1.0f, std::abs(expected)))
                        FAIL("layer " << film.layerNames()[l] << " pixel " << x << "," << y << ": served " << served
                                      << ", rendered " << expected);
                }
    }
}

// The classes render the command line makes of `scene` with these settings (RenderConfig, as
// `lightpath render` reads its flags), `parameters` the integrator's own; with `seed`, rendered as
// serve's passes are, Renderer::render(seed, spp).
Film renderAsCommandLine(const std::string& scene, const std::string& integrator, const std::string& resolution,
                         int spp, const std::vector<std::pair<std::string, std::string>>& parameters,
                         std::optional<std::uint64_t> seed = std::nullopt) {
    RenderConfig config;
    config.scenePath = scenePath(scene);
    config.integrator = integrator;
    config.resolution = resolution;
    config.samplesPerPixel = spp;
    config.aovs = "classes";
    for (const auto& [name, value] : parameters) config.set(name, value);
    config.validate();
    const Scene loaded = config.loadScene();
    const AovSet aovs(config.expressions(&loaded));  // the renderer keeps references to both
    const Renderer renderer(loaded, aovs, config.renderOptions());
    return (seed ? renderer.render(*seed, spp) : renderer.render()).film;
}

}  // namespace

TEST_CASE("serve: the page's files and the scene description") {
    ServerFixture fixture("mirror-sphere.toml");
    auto c = fixture.client();
    const auto page = c->Get("/");
    REQUIRE(page);
    CHECK(page->status == 200);
    CHECK(page->get_header_value("Content-Type").find("text/html") == 0);
    CHECK(page->body.find("<script src=\"/app.js\"></script>") != std::string::npos);
    for (const char* asset : {"/app.js", "/style.css"}) {
        const auto r = c->Get(asset);
        REQUIRE(r);
        CHECK(r->status == 200);
        CHECK(r->body.size() > 1000);
    }
    const auto scene = c->Get("/api/scene");
    REQUIRE(scene);
    REQUIRE(scene->status == 200);
    const json s = json::parse(scene->body);
    // The registry's table, whatever integrators it holds (raycast, whitted and path at least).
    CHECK(s["integrators"] == json(integratorNames()));
    CHECK(s["integrators"][0] == "raycast");
    CHECK(s["camera"]["width"] == 640);
    CHECK(s["lights"][0]["name"] == "lamp");
    // The mirror ball: centre (0, 1.1, 0), radius 1.1 in the scene file.
    bool found = false;
    for (const json& o : s["objects"])
        if (o["name"] == "mirror-ball") {
            found = true;
            CHECK(o["bounds"][0] == json::array({-1.1f, 0.0f, -1.1f}));
            CHECK(o["bounds"][1] == json::array({1.1f, 2.2f, 1.1f}));
        }
    CHECK(found);
    std::vector<std::string> presets;
    for (const json& p : s["presets"]) presets.push_back(p["name"]);
    CHECK(presets == std::vector<std::string>{"classes", "taxonomy", "bounces", "lights"});
    // The light groups: the ambient term, the lamp and the background, each its own AOV.
    CHECK(s["presets"][3]["lpes"] == json::parse(R"([{"name":"ambient","expression":"E.*<L.'ambient'>"},
        {"name":"lamp","expression":"E.*<L.'lamp'>"},{"name":"background","expression":"E.*B"}])"));
}

TEST_CASE("serve: the bounce preset is a partition, so its AOVs sum to the beauty") {
    const Scene scene = loadScene(scenePath("mirror-sphere.toml"));
    for (const auto& preset : presets(scene)) {
        const auto& name = preset.first;
        const auto& set = preset.second;
        if (name != "bounces" && name != "classes") continue;
        CAPTURE(name);
        CHECK(lpe::analyse(set, name == "classes" ? "E(<[RT][DGS]>|<Vx>)*L" : "E.*L").partition());
    }
}

TEST_CASE("serve: a render at 1 spp is the renderer's own image, its layers summing to the beauty") {
    ServerFixture fixture("mirror-sphere.toml");
    const auto put = fixture.put(settingsFor(48, 36, 1));
    REQUIRE(put);
    REQUIRE(put->status == 200);
    const auto generation = json::parse(put->body)["generation"].get<std::uint64_t>();
    const json done = fixture.waitUntilDone(generation);
    CHECK(done["passes"] == 1);
    CHECK(done["samples"] == 1);
    CHECK(done["sumError"].get<double>() < 1e-5);
    CHECK(done["layers"] == json::array({"beauty", "raycast", "raytrace", "mirror", "emission", "indirect", "volume", "rest"}));

    auto c = fixture.client();
    const auto exr = c->Get("/api/render.exr");
    REQUIRE(exr);
    REQUIRE(exr->status == 200);
    const Decoded image = decode(exr->body, "render.exr");
    // The sum of the layers is the beauty, pixel by pixel (DESIGN.md's promise).
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (const char* channel : {"R", "G", "B"}) {
                float sum = 0.0f;
                for (const char* layer : {"raycast.", "raytrace.", "mirror.", "emission.", "indirect.", "rest."})
                    sum += image.at(x, y, std::string(layer) + channel);
                CHECK(sum == doctest::Approx(image.at(x, y, channel)).epsilon(1e-5));
            }
    // The same settings given to the renderer directly.
    Scene scene = loadScene(scenePath("mirror-sphere.toml"));
    scene.camera.width = 48;
    scene.camera.height = 36;
    const AovSet aovs(classesSet());
    const RenderResult direct = Renderer(scene, aovs, RenderOptions{}).render();
    checkSameAsFilm(image, direct.film);

    // A PNG of a layer: the PNG signature and the size in its IHDR chunk (PNG spec, 11.2.2).
    const auto png = c->Get("/api/image/mirror.png?exposure=1");
    REQUIRE(png);
    REQUIRE(png->status == 200);
    CHECK(png->get_header_value("Content-Type") == "image/png");
    REQUIRE(png->body.size() > 24);
    CHECK(png->body.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
    const auto be32 = [&](std::size_t at) {
        const auto* b = reinterpret_cast<const unsigned char*>(png->body.data() + at);
        return (b[0] << 24) | (b[1] << 16) | (b[2] << 8) | b[3];
    };
    CHECK(be32(16) == 48);
    CHECK(be32(20) == 36);
}

TEST_CASE("serve: passes refine: the image is the mean of independent jittered passes") {
    ServerFixture fixture("mirror-sphere.toml");
    const auto put = fixture.put(settingsFor(40, 30, 8, "path"));
    REQUIRE(put);
    REQUIRE(put->status == 200);
    const json done = fixture.waitUntilDone(json::parse(put->body)["generation"].get<std::uint64_t>());
    // Pass 0 (one centre sample), then two passes of 4 jittered samples.
    CHECK(done["passes"] == 3);
    CHECK(done["samples"] == 8);
    const auto exr = fixture.client()->Get("/api/render.exr");
    REQUIRE(exr);
    const Decoded image = decode(exr->body, "render.exr");

    Scene scene = loadScene(scenePath("mirror-sphere.toml"));
    scene.camera.width = 40;
    scene.camera.height = 30;
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = 4;
    const Renderer renderer(scene, aovs, options);
    const RenderResult first = renderer.render(1), second = renderer.render(2);
    Film mean = first.film;
    for (int y = 0; y < mean.height(); ++y)
        for (int x = 0; x < mean.width(); ++x)
            for (std::size_t l = 0; l < mean.layerCount(); ++l) mean.pixel(x, y)[l] = (first.film.at(l, x, y) + second.film.at(l, x, y)) * 0.5f;
    checkSameAsFilm(image, mean);
    // Independent passes differ (a path tracer's noise), so averaging them refines the image.
    int differing = 0;
    for (int y = 0; y < mean.height(); ++y)
        for (int x = 0; x < mean.width(); ++x) differing += first.film.at(0, x, y) != second.film.at(0, x, y);
    CHECK(differing > mean.width() * mean.height() / 4);
}

// sppm's passes refine one state (each pixel's radius shrinks with the photons it finds): serve
// continues one render of the whole target, so its image is the command line's sppm render of
// that many samples, not a mean of short renders each starting at the first radius.
TEST_CASE("serve: under sppm the passes continue one progressive render, the image is sppm's render of the whole target") {
    ServerFixture fixture("glass-sphere.toml");
    json settings = settingsFor(32, 24, 8, "sppm");
    settings["parameters"] = {{"photons", 2000}};
    const auto put = fixture.put(settings);
    REQUIRE(put);
    REQUIRE(put->status == 200);
    const json done = fixture.waitUntilDone(json::parse(put->body)["generation"].get<std::uint64_t>());
    CHECK(done["passes"] == 3);
    CHECK(done["samples"] == 8);
    CHECK(done["sumError"].get<double>() < 1e-4);
    const auto exr = fixture.client()->Get("/api/render.exr");
    REQUIRE(exr);
    const Decoded image = decode(exr->body, "render.exr");

    // The same configuration given to the renderer directly.
    checkSameAsFilm(image, renderAsCommandLine("glass-sphere.toml", "sppm", "32x24", 8, {{"photons", "2000"}}, 1));
}

TEST_CASE("serve: explain a mirror pixel: paths, pasteable LPEs, automaton states") {
    ServerFixture fixture("mirror-sphere.toml");
    const auto put = fixture.put(settingsFor(64, 48, 1));
    REQUIRE(put);
    REQUIRE(put->status == 200);
    // The pixel where the mirror ball's centre appears.
    Scene scene = loadScene(scenePath("mirror-sphere.toml"));
    scene.camera.width = 64;
    scene.camera.height = 48;
    const auto centre = Camera(scene.camera).project({0.0f, 1.1f, 0.0f});
    REQUIRE(centre);
    const int x = static_cast<int>(centre->x), y = static_cast<int>(centre->y);
    const auto r = fixture.client()->Get(("/api/explain?x=" + std::to_string(x) + "&y=" + std::to_string(y)).c_str());
    REQUIRE(r);
    REQUIRE(r->status == 200);
    const json e = json::parse(r->body);
    REQUIRE(e["contributions"].size() > 1);

    const lpe::Automaton classes = lpe::Automaton::compile(classesSet());
    const std::regex mirrorEvent("RS'mirror-ball'");
    bool sawMirror = false;
    Rgb beauty{0.0f};
    for (const json& c : e["contributions"]) {
        const std::string tuple = c["tuple"];
        const lpe::Path path = lpe::parsePath(tuple);
        sawMirror = sawMirror || std::regex_search(tuple, mirrorEvent);
        CHECK(c["compact"] == lpe::toCompactString(path));
        // The AOVs named are the ones whose expressions accept the path (compiled here anew).
        std::vector<std::string> accepting;
        for (std::size_t o = 0; o < classesSet().size(); ++o)
            if (classes.matches(path, o)) accepting.push_back(classesSet()[o].name);
        if (accepting.empty()) accepting.push_back("rest");
        CHECK(c["aovs"] == json(accepting));
        // The pasteable LPE accepts this path and not the same path ending at another light.
        const lpe::Automaton exact = lpe::Automaton::compile({{"exact", c["lpe"].get<std::string>()}});
        CHECK(exact.matches(path, 0));
        lpe::Path other = path;
        other.back().label = "elsewhere";
        CHECK_FALSE(exact.matches(other, 0));
        // One state before the path and one after each event.
        CHECK(c["states"].size() == path.size() + 1);
        CHECK(c["vertices"].size() == path.size());
        CHECK(c["segments"].size() == path.size() - 1);
        CHECK(c["vertices"][0]["event"] == "E");
        beauty += Rgb{c["rgb"][0].get<float>(), c["rgb"][1].get<float>(), c["rgb"][2].get<float>()};
        // The value is the product of its factors (the terms of the illumination formula).
        REQUIRE(!c["factors"].empty());
        for (int channel = 0; channel < 3; ++channel) {
            double product = 1.0;
            for (const json& f : c["factors"])
                if (f["inProduct"].get<bool>()) product *= f["rgb"][channel].get<double>();
            CHECK(product == doctest::Approx(c["rgb"][channel].get<double>()).epsilon(1e-4));
        }
    }
    CHECK(sawMirror);
    CHECK(e["rejected"].is_array());
    CHECK(e["sums"][0]["layer"] == "beauty");
    CHECK(e["sums"][0]["rgb"][1].get<float>() == doctest::Approx(beauty.g));

    // The automaton, drawn by Graphviz, with one node per live state titled by its number.
    const auto svg = fixture.client()->Get("/api/automaton.svg");
    REQUIRE(svg);
    REQUIRE(svg->status == 200);
    CHECK(svg->get_header_value("Content-Type") == "image/svg+xml");
    CHECK(std::regex_search(svg->body, std::regex("<g id=\"node\\d+\" class=\"node\">\\s*<title>0</title>")));
}

TEST_CASE("serve: every refused request gets a 4xx naming what was wrong, and nothing is lost") {
    ServerFixture fixture("lecture-room.toml");
    const auto put = fixture.put(settingsFor(32, 24, 1));
    REQUIRE(put);
    REQUIRE(put->status == 200);
    const json before = json::parse(fixture.client()->Get("/api/settings")->body)["settings"];

    struct Case {
        std::string body;
        int status;
        std::string field;
        std::string message;  // a regex the error must contain
    };
    const std::vector<Case> cases{
        {"{\"spp\": 4", 400, "", "malformed JSON"},
        {"[1, 2]", 400, "", "expected a JSON object"},
        {"{\"colour\": 1}", 400, "colour", "unknown field; expected one of integrator, spp"},
        {"{\"width\": 0}", 400, "width", "width: expected an integer 1\\.\\.4096, got 0"},
        {"{\"width\": 1000000000}", 400, "width", "expected an integer 1\\.\\.4096, got 1000000000"},
        {"{\"height\": 1e9}", 400, "height", "expected an integer 1\\.\\.4096"},
        {"{\"width\": 4096, \"height\": 4096}", 400, "width,height", "4096x4096 pixels times 8 layers is 134217728; expected at most 16777216"},
        {"{\"spp\": \"many\"}", 400, "spp", "spp: expected an integer 1\\.\\.4096, got \"many\""},
        {"{\"spp\": -3}", 400, "spp", "got -3"},
        {"{\"maxDepth\": 65}", 400, "maxDepth", "0\\.\\.64"},
        {"{\"integrator\": \"magic\"}", 400, "integrator", "unknown integrator \"magic\"; expected one of raycast, raster, whitted, path"},
        {"{\"lpes\": {}}", 400, "lpes", "expected an array"},
        {"{\"lpes\": [{\"name\": \"a\", \"expression\": \"EL\", \"extra\": 1}]}", 400, "lpes[0].extra", "unknown field"},
        {"{\"lpes\": [{\"name\": \"a\", \"expression\": \"E(D|G L\"}]}", 400, "lpes[0].expression",
         "a: LPE syntax error at column 8: expected '\\)'"},
        // Refused as the command line refuses it (config/lpe_verdict.h): ED never reaches a light.
        {"{\"lpes\": [{\"name\": \"ok\", \"expression\": \"EL\"}, {\"name\": \"never\", \"expression\": \"ED\"}]}", 400,
         "lpes[1].expression", "^never: 'ED' can never match under --integrator whitted: never reaches a light"},
        {"{\"integrator\": \"raycast\", \"lpes\": [{\"name\": \"s\", \"expression\": \"ES+(D|G)L\"}]}", 400,
         "lpes[0].expression", "ray casting follows no specular bounce"},
        {"{\"lpes\": [{\"name\": \"rest\", \"expression\": \"EL\"}]}", 400, "lpes", "reserved"},
        {"{\"lpes\": [{\"name\": \"a\", \"expression\": \"E{2000000}L\"}]}", 400, "lpes", ""},
        // An integrator's own parameters, checked against its schema as the command line's --NAME.
        {"{\"parameters\": [64]}", 400, "parameters", "expected an object of integrator parameters"},
        {"{\"parameters\": {\"colour\": 1}}", 400, "parameters.colour",
         "no integrator has a parameter of this name; expected one of patch-size \\(radiosity\\), patches"},
        {"{\"parameters\": {\"patches\": [1]}}", 400, "parameters.patches", "expected a number, a string or a boolean"},
        {"{\"parameters\": {\"patches\": 0}}", 400, "parameters.patches", "^parameters.patches: Value 0 not in range 1 to"},
        {"{\"parameters\": {\"patches\": 2.5}}", 400, "parameters.patches", "integer"},
        {"{\"parameters\": {\"patches\": 64, \"patch-size\": 0.5}}", 400, "parameters.patch-size", "excludes"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.body);
        const auto r = fixture.client()->Put("/api/settings", c.body, "application/json");
        REQUIRE(r);
        CHECK(r->status == c.status);
        const json error = json::parse(r->body);
        CHECK(error["error"].is_string());
        CHECK(error.value("field", std::string()) == c.field);
        CHECK(std::regex_search(error["error"].get<std::string>(), std::regex(c.message)));
    }
    // The syntax error's column: the end of "E(D|G L", where ')' was expected (0-based offset 7).
    const auto syntax = fixture.put({{"lpes", {{{"name", "a"}, {"expression", "E(D|G L"}}}}});
    REQUIRE(syntax);
    const json error = json::parse(syntax->body);
    CHECK(error["column"] == 7);
    CHECK(error["expression"] == "E(D|G L");

    auto c = fixture.client();
    // A body over the limit.
    const auto huge = c->Put("/api/settings", std::string(200 * 1024, ' '), "application/json");
    REQUIRE(huge);
    CHECK(huge->status == 413);
    // Paths are never file paths.
    for (const char* path : {"/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/etc/passwd", "/api/../../etc/passwd",
                             "/index.html", "/api/image/../../etc/passwd.png"}) {
        CAPTURE(path);
        const auto r = c->Get(path);
        REQUIRE(r);
        CHECK(r->status == 404);
        CHECK(r->body.find("root:") == std::string::npos);
    }
    const std::vector<std::pair<std::string, int>> gets{
        {"/api/image/nosuchlayer.png", 404},     {"/api/image/beauty.png?exposure=bright", 400},
        {"/api/image/beauty.png?exposure=1e9", 400}, {"/api/image/beauty.png?size=2", 400},
        {"/api/explain?x=32&y=0", 400},           {"/api/explain?x=-1&y=0", 400},
        {"/api/explain?x=1", 400},                {"/api/explain?x=1.5&y=2", 400},
        {"/api/progress?wait=100", 400},          {"/api/scene?verbose=1", 400},
    };
    for (const auto& get : gets) {
        const auto& path = get.first;
        const auto status = get.second;
        CAPTURE(path);
        const auto r = c->Get(path.c_str());
        REQUIRE(r);
        CHECK(r->status == status);
        CHECK(json::parse(r->body)["error"].is_string());
    }
    // Still serving, with the settings it held.
    const auto after = c->Get("/api/settings");
    REQUIRE(after);
    CHECK(after->status == 200);
    CHECK(json::parse(after->body)["settings"] == before);
}

TEST_CASE("serve: warnings for an expression black in this scene and for overlapping ones") {
    ServerFixture fixture("lecture-room.toml");
    const auto r = fixture.put({{"lpes", json::parse(R"([{"name": "key", "expression": "E.*<L'kee'>"},
        {"name": "all", "expression": "E.*L"}, {"name": "direct", "expression": "E(D|G)L"}])")}});
    REQUIRE(r);
    REQUIRE(r->status == 200);
    const json warnings = json::parse(r->body)["warnings"];
    CAPTURE(warnings.dump());
    // The scene has no label kee: black here, rendered, as the command line does;
    // "E.*L" and "E(D|G)L" share EDL.
    REQUIRE(warnings.size() == 2);
    CHECK(std::regex_search(warnings[0].get<std::string>(),
                            std::regex("^AOV key \\(E\\.\\*<L'kee'>\\) stays black: this scene has no label \"kee\"; did you mean \"key\"")));
    CHECK(warnings[1] == "AOVs all and direct overlap: both accept EDL (E <RD> <L>); their sum counts such light twice");
}

TEST_CASE("serve: the rasteriser at 16 spp renders at 1 spp with a notice, and bdpt explains with (s, t)") {
    ServerFixture fixture("mirror-sphere.toml");
    // The page's default is 16 spp; switching to raster must not be refused halfway.
    const auto raster = fixture.put({{"integrator", "raster"}, {"spp", 16}});
    REQUIRE(raster);
    REQUIRE(raster->status == 200);
    const json answer = json::parse(raster->body);
    CHECK(answer["settings"]["integrator"] == "raster");
    CHECK(answer["settings"]["spp"] == 1);
    REQUIRE(answer["notices"].size() == 1);
    CHECK(answer["notices"][0] == "spp: the raster integrator samples each pixel once, at its centre: spp 1 instead of 16");
    // Back to a sampling integrator, the page's 16 spp is taken as sent, with no notice.
    const auto path = fixture.put({{"integrator", "path"}, {"spp", 16}});
    REQUIRE(path);
    REQUIRE(path->status == 200);
    CHECK(json::parse(path->body)["settings"]["spp"] == 16);
    CHECK(json::parse(path->body)["notices"].empty());

    const auto bdpt = fixture.put(settingsFor(32, 24, 1, "bdpt"));
    REQUIRE(bdpt);
    REQUIRE(bdpt->status == 200);
    const auto explained = fixture.client()->Get("/api/explain?x=16&y=12");
    REQUIRE(explained);
    REQUIRE(explained->status == 200);
    const json contributions = json::parse(explained->body)["contributions"];
    REQUIRE(!contributions.empty());
    for (const json& c : contributions) {
        CAPTURE(c["compact"]);
        // A bdpt path of n vertices (eye and light included) is made by s + t = n.
        REQUIRE(c["strategy"].is_object());
        CHECK(c["strategy"]["s"].get<int>() + c["strategy"]["t"].get<int>() == static_cast<int>(c["vertices"].size()));
    }
}

TEST_CASE("serve: a change of settings cancels the render in flight") {
    ServerFixture fixture("lecture-room.toml");
    // Hours of work at this size and sample count: it can only finish by being cancelled.
    const auto heavy = fixture.session.update(applySettings(fixture.session.job()->settings,
                                                            settingsFor(1024, 768, 4096, "path").dump()));
    // The worker has taken it (its empty progress is published just before its first pass): what
    // follows cancels a render under way. Not waiting for that pass itself, 786,432 paths (most
    // of this test's time under the sanitizers), which would only let the cancel land in a later one.
    const Progress started = fixture.session.waitForProgress(heavy->generation, -1, 60.0);
    CHECK(started.job->generation == heavy->generation);
    const auto light = fixture.session.update(applySettings(heavy->settings, settingsFor(16, 12, 1).dump()));
    CHECK(heavy->cancelled());
    CHECK_FALSE(light->cancelled());
    const json done = fixture.waitUntilDone(light->generation, 60.0);
    CHECK(done["settings"]["width"] == 16);
    CHECK(fixture.session.progress().job == light);
}

TEST_CASE("serve: concurrent requests") {
    ServerFixture fixture("mirror-sphere.toml");
    const auto put = fixture.put(settingsFor(32, 24, 4));
    REQUIRE(put);
    fixture.waitUntilDone(json::parse(put->body)["generation"].get<std::uint64_t>());
    std::atomic<int> unexpected{0}, answered{0};
    std::vector<std::thread> clients;
    for (int t = 0; t < 6; ++t) {
        clients.emplace_back([&, t] {
            auto c = fixture.client();
            for (int i = 0; i < 15; ++i) {
                const int kind = (t + i) % 5;
                const int expected = kind == 4 ? 400 : 200;
                const httplib::Result r =
                    kind == 0   ? c->Get("/api/explain?x=16&y=12")
                    : kind == 1 ? c->Get("/api/image/beauty.png")
                    : kind == 2 ? c->Get("/api/progress")
                    : kind == 3 ? c->Put("/api/settings", settingsFor(32, 24, 1 + (t + i) % 3).dump(), "application/json")
                                : c->Put("/api/settings", "{\"width\": 0}", "application/json");
                // Images may be briefly missing while a new render has no pass yet.
                if (!r || (r->status != expected && !(r->status == 503 && kind == 1))) ++unexpected;
                ++answered;
            }
        });
    }
    for (auto& thread : clients) thread.join();
    CHECK(unexpected == 0);
    CHECK(answered == 90);
    const auto last = fixture.client()->Get("/api/settings");
    REQUIRE(last);
    CHECK(last->status == 200);
}

TEST_CASE("serve: a change of settings runs the integrator's preprocess once: one radiosity solve for every pass") {
    ServerFixture fixture("cornell-original.toml");
    // The worker renders one job after another: once this one is done no other renderer is built.
    const auto small = fixture.session.update(applySettings(fixture.session.job()->settings, settingsFor(16, 12, 1).dump()));
    fixture.waitUntilDone(small->generation);
    const std::uint64_t before = Renderer::preprocessesRun();
    // Pass 0 at the pixel centres, then jittered passes of kSamplesPerPass samples.
    // A small budget without refinement: this checks serve's passes, not the solve (the default
    // 4096 patches were most of this test's time under the sanitizers, refined rounds minutes).
    json settings = settingsFor(16, 12, 2 * kSamplesPerPass, "radiosity");
    settings["parameters"] = {{"patches", 24}, {"refine", 0}};
    const auto job = fixture.session.update(applySettings(fixture.session.job()->settings, settings.dump()));
    const json done = fixture.waitUntilDone(job->generation);
    CHECK(done["passes"] == 3);
    CHECK(Renderer::preprocessesRun() - before == 1);
}

TEST_CASE("serve: progress reports the preparation (radiosity's solve) with its steps and time, apart from the passes") {
    ServerFixture fixture("cornell-original.toml");
    const auto started = std::chrono::steady_clock::now();
    json settings = settingsFor(16, 12, 1, "radiosity");
    settings["parameters"] = {{"patches", 24}, {"refine", 0}};  // as above: serve's report, not the solve
    const auto job = fixture.session.update(applySettings(fixture.session.job()->settings, settings.dump()));
    const json done = fixture.waitUntilDone(job->generation);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const json& preparation = done["preparation"];
    CHECK(preparation["state"] == "done");
    // The solve counts its steps (form factors, direct light, bounces) as it runs; its tolerance
    // may end it before the last.
    CHECK(preparation["of"].get<int>() > 0);
    CHECK(preparation["steps"].get<int>() > 0);
    CHECK(preparation["steps"].get<int>() <= preparation["of"].get<int>());
    // Measured apart from the passes' time, and both within the wall time the test waited.
    CHECK(preparation["seconds"].get<double>() > 0.0);
    CHECK(preparation["seconds"].get<double>() + done["seconds"].get<double>() <= wall);

    // An integrator without a counted preprocess: done, no steps.
    const auto whitted = fixture.session.update(applySettings(fixture.session.job()->settings,
                                                              settingsFor(16, 12, 1, "whitted").dump()));
    const json plain = fixture.waitUntilDone(whitted->generation);
    CHECK(plain["preparation"]["state"] == "done");
    CHECK(plain["preparation"]["of"] == 0);
    CHECK(plain["preparation"]["steps"] == 0);
}

TEST_CASE("serve: an integrator's own parameters reach it, as the command line's --NAME does") {
    ServerFixture fixture("cornell-original.toml");
    const auto scene = json::parse(fixture.client()->Get("/api/scene")->body);
    const json& patches = scene["integratorParameters"]["radiosity"][1];
    CHECK(patches["name"] == "patches");
    CHECK(patches["type"] == "integer");
    CHECK(patches["default"] == "8192");
    CHECK(patches["low"] == 1.0);
    CHECK(scene["integratorParameters"]["path"] == json::array());

    json settings = settingsFor(16, 12, 1, "radiosity");
    settings["parameters"] = {{"patches", 24}};
    const auto put = fixture.put(settings);
    REQUIRE(put);
    REQUIRE(put->status == 200);
    const json answer = json::parse(put->body);
    CHECK(answer["settings"]["parameters"] == json({{"patches", 24}}));
    fixture.waitUntilDone(answer["generation"].get<std::uint64_t>());
    const Decoded image = decode(fixture.client()->Get("/api/render.exr")->body, "render.exr");

    // The same configuration given to the renderer directly, and the control: another budget
    // changes the image, so the comparison above sees whether the parameter arrived. Not the
    // default budget: its 4096 patches, refined, were nearly all of this test's time (16 s in
    // Release, 128 s under the sanitizers); a server that drops the parameter renders those and
    // fails the comparison with 24 patches all the same.
    checkSameAsFilm(image, renderAsCommandLine("cornell-original.toml", "radiosity", "16x12", 1, {{"patches", "24"}}));
    const Film other = renderAsCommandLine("cornell-original.toml", "radiosity", "16x12", 1, {{"patches", "48"}});
    bool differs = false;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) differs |= image.at(x, y, "R") != other.at(0, x, y).r;
    CHECK(differs);
}

TEST_CASE("serve: only the newest explanation runs: a newer one, a change of settings and shutdown cancel it") {
    ServerFixture fixture("mirror-sphere.toml");
    const auto first = fixture.session.startExplaining();
    CHECK_FALSE(first->load());
    const auto second = fixture.session.startExplaining();
    CHECK(first->load());
    CHECK_FALSE(second->load());
    fixture.session.update(applySettings(fixture.session.job()->settings, settingsFor(16, 12, 1).dump()));
    CHECK(second->load());
    const auto third = fixture.session.startExplaining();
    CHECK_FALSE(third->load());
    fixture.session.stop();
    CHECK(third->load());
    CHECK(fixture.session.startExplaining()->load());  // after shutdown none starts
    CHECK(fixture.session.stopping());
}

TEST_CASE("serve: a server stopped before its listening loop begins still stops") {
    // httplib's stop() is a no-op until the loop runs: the thread below may not have started when
    // stop() comes, and run() must then return rather than wait in accept() for good.
    Session session(loadScene(scenePath("mirror-sphere.toml")), scenePath("mirror-sphere.toml"));
    for (int i = 0; i < 100; ++i) {
        Server server(session);
        server.bind("127.0.0.1", 0);
        std::thread thread([&server] { server.run(); });
        server.stop();
        thread.join();
    }
    session.stop();
    CHECK(session.stopping());
}
