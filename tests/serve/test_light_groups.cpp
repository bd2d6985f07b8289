// serve's `lights` preset, the command line's refusal of AOVs that can never be filled and
// `lpe check`'s overlaps agree on every shipped scene: one AOV per light, each filled where its
// light reaches the image, together a partition of the beauty. And when the command line refuses
// a label in the wrong place, the events it suggests instead are themselves accepted.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "config/lpe_feasibility.h"
#include "film/aov_set.h"
#include "lpe/analysis.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "serve/scene_report.h"

#include "../support/shipped_scenes.h"

using namespace lightpath;

namespace {

using test::shippedScenes;

std::vector<lpe::NamedExpression> lightsPreset(const Scene& scene) {
    for (const auto& [name, set] : serve::presets(scene))
        if (name == "lights") return set;
    FAIL("serve offers no `lights` preset");
    return {};
}

}  // namespace

TEST_CASE("serve's lights preset: every AOV accepted by the command line, filled, and together a partition") {
    const IntegratorInfo& whitted = *findIntegrator("whitted");
    for (const auto& file : shippedScenes()) {
        CAPTURE(file.filename().string());
        Scene scene = loadScene(file);
        const auto set = lightsPreset(scene);
        REQUIRE(!set.empty());
        for (const auto& e : set) {
            CAPTURE(e.expression);
            const auto why = whyNeverFilled(e.expression, whitted, &scene);
            CHECK_MESSAGE(!why, (why ? *why : std::string()));
        }
        // `lpe check`: no two groups accept the same path.
        CHECK(lpe::analyse(set, "E.*L").overlaps.empty());

        // Rendered under Whitted, which sees every emitter directly or on a diffuse surface.
        scene.camera.width = 32;
        scene.camera.height = 24;
        const AovSet aovs(set);
        RenderOptions options;
        options.integrator = "whitted";
        options.samplesPerPixel = 4;
        options.threads = 1;
        const Film film = Renderer(scene, aovs, options).render().film;
        const auto names = aovs.layerNames();
        const std::size_t restLayer = names.size() - 1;
        REQUIRE(names[restLayer] == "rest");
        for (std::size_t aov = 1; aov < restLayer; ++aov) {
            CAPTURE(names[aov]);
            // Emitting surfaces, the ambient term and the background are seen in every shipped
            // scene. A shapeless light may light nothing in view (cornell-sphere's point light sits
            // above the mesh's ceiling): its group is held to the partition below.
            const std::string& expression = set[aov - 1].expression;
            const bool shapeless = std::any_of(scene.lights.begin(), scene.lights.end(), [&](const LightSlot& light) {
                return expression == "E.*<L.'" + light->name + "'>";
            });
            if (shapeless) continue;
            bool filled = false;
            for (int y = 0; y < film.height(); ++y)
                for (int x = 0; x < film.width(); ++x) filled |= !isBlack(film.at(aov, x, y));
            CHECK(filled);
        }
        // A partition: nothing left over, and the groups sum to the beauty.
        double rest = 0.0, worst = 0.0;
        for (int y = 0; y < film.height(); ++y) {
            for (int x = 0; x < film.width(); ++x) {
                Rgb sum{0.0f};
                for (std::size_t aov = 1; aov < restLayer; ++aov) sum += film.at(aov, x, y);
                const Rgb beauty = film.at(0, x, y);
                rest += maxComponent(film.at(restLayer, x, y));
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, double(std::abs(sum[c] - beauty[c])) / (1e-3 + std::abs(beauty[c])));
            }
        }
        CHECK(rest == 0.0);
        CHECK(worst < 1e-4);
    }
}

TEST_CASE("the command line's fix for a label on the wrong events is itself accepted") {
    const std::regex fragment("<[^<>]*>");
    int refusals = 0;
    for (const auto& file : shippedScenes()) {
        CAPTURE(file.filename().string());
        const Scene scene = loadScene(file);
        for (std::uint32_t object = 0; object < scene.objects.size(); ++object) {
            const std::string& label = scene.labelOf(object);
            if (label.find('\'') != std::string::npos) continue;
            for (const char* type : {"L", "O"}) {
                const std::string expression = std::string("E.*<") + type + ".'" + label + "'>";
                CAPTURE(expression);
                const auto why = whyNeverFilled(expression, *findIntegrator("whitted"), &scene);
                if (!why) continue;
                ++refusals;
                CAPTURE(*why);
                for (auto it = std::sregex_iterator(why->begin(), why->end(), fragment); it != std::sregex_iterator(); ++it) {
                    const std::string suggestion = "E.*" + it->str() + ".*";
                    CAPTURE(suggestion);
                    CHECK_FALSE(whyNeverFilled(suggestion, *findIntegrator("whitted"), &scene));
                }
            }
        }
    }
    CHECK(refusals > 0);
}
