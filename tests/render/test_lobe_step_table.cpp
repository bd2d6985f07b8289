// The per-render table of direct light's automaton answers (integrators/lobe_step_table.h) against
// the automaton stepped event by event, as EventSymbols names each event: for every state, every
// object's every smooth lobe and every light (and the ambient term), on shipped scenes under real
// LPE sets. Through PathState::acceptsThrough, both as the renderer builds it (tabled) and with
// the table refused (maxMasks 0: PathState steps itself); and which lobes' terms are wanted.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "film/aov_presets.h"
#include "render_world.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

// Sets of the lecture and of the command line, and one naming this scene's labels (and `lights`,
// its lights'), so label classes other than 0 are in the symbols.
std::vector<std::vector<lpe::NamedExpression>> lpeSets(const Scene& scene) {
    std::vector<std::vector<lpe::NamedExpression>> sets{classesSet(), taxonomySet(), bouncesSet(),
                                                        {{"diffuse", "E<RD>L"}}};
    sets.push_back(findAovPreset("lights")->expressions(&scene));
    sets.push_back({{"seen", "E<R.'" + scene.labelOf(0) + "'>L"},
                    {"through", "E.*<T.>.*L"},
                    {"glossyThenLabel",
                     "E<RG>.*<R.'" + scene.labelOf(std::uint32_t(scene.objects.size() - 1)) + "'>L"}});
    return sets;
}

// What the table must answer, from the automaton and EventSymbols alone.
lpe::OutputMask stepped(const test::RenderWorld& world, lpe::Automaton::State state, const PathEvent& surface,
                        const PathEvent& light) {
    const lpe::Automaton& automaton = world.aovs.automaton();
    return automaton.accepts(automaton.step(automaton.step(state, world.symbols(surface)), world.symbols(light)));
}

void checkAgainstStepping(const test::RenderWorld& world, const PathState& path, const LobeStepTable& table,
                          bool tabled) {
    const Scene& scene = world.scene;
    const lpe::Automaton& automaton = world.aovs.automaton();
    CHECK(table.tabled() == tabled);
    std::vector<PathEvent> lights{{lpe::EventType::Emitter, lpe::Scatter::None, Subject::Ambient, 0}};
    for (const std::unique_ptr<Light>& light : world.lights.all()) lights.push_back(light->event());
    int compared = 0, wrong = 0;
    for (std::uint32_t object = 0; object < scene.objects.size(); ++object) {
        const Lobes all = scene.materials[scene.objects[object].material]->lobes();
        const SmoothLobes& smooth = table.lobes(table.classOf(object));
        int slot = 0;
        for (int l = 0; l < int(all.size()); ++l) {
            if (all[l].delta()) continue;
            REQUIRE(slot < smooth.count);
            CHECK(smooth.lobe[slot] == l);
            CHECK(smooth.glossy[slot] == (all[l].event.scatter == lpe::Scatter::Glossy));
            ++slot;
        }
        CHECK(smooth.count == slot);
        for (lpe::Automaton::State state = 0; state < automaton.stateCount(); ++state) {
            const PathState::SurfaceLobes at{smooth, state, table.classOf(object)};
            for (std::size_t i = 0; i < lights.size(); ++i) {
                const LightColumn column = i == 0 ? path.ambientColumn() : path.lightColumn(lights[i]);
                CHECK((column.column >= 0) == tabled);
                lpe::OutputMask scratch[kMaxLobes];
                const lpe::OutputMask* accepted = path.acceptsThrough(at, column, scratch);
                const unsigned wanted = path.wantedLobes(accepted, smooth.count);
                for (int s = 0; s < smooth.count; ++s)
                    if (((wanted >> s & 1u) != 0) != path.wanted(accepted[s])) ++wrong;
                for (int s = 0; s < smooth.count; ++s) {
                    const LobeInfo& lobe = all[smooth.lobe[s]];
                    const PathEvent surface{lobe.event.type, lobe.event.scatter, Subject::Object, object};
                    ++compared;
                    if (accepted[s] != stepped(world, state, surface, lights[i])) ++wrong;
                }
            }
        }
    }
    CHECK(compared > 0);
    CHECK(wrong == 0);
}

TEST_CASE("the lobe step table answers as the automaton stepped per lobe and light, every state") {
    for (const char* name : {"cornell-mirror", "szymczak-three-lights", "taxonomy", "glass-sphere", "fog-shafts",
                             "frosted-glass"}) {
        const Scene scene = loadScene(std::string(LIGHTPATH_SOURCE_DIR "/scenes/") + name + ".toml");
        for (const std::vector<lpe::NamedExpression>& set : lpeSets(scene)) {
            CAPTURE(name);
            CAPTURE(set.front().expression);
            const test::RenderWorld world(scene, set);
            std::vector<Rgb> layers(world.aovs.layerCount());
            ContributionSink sink(layers);
            RayCounters counters;
            const PathState tabledPath(world.context, sink, counters);
            checkAgainstStepping(world, tabledPath, world.lobeSteps, true);
            // The same with no table: PathState steps the automaton itself.
            const LobeStepTable refused(world.scene, world.aovs.automaton(), world.symbols, world.lights, 0);
            const RenderContext& c = world.context;
            // Only the first output requested, no path kept for the beauty: wantedLobes looks.
            RenderContext steppingContext{c.scene,    c.geometry, c.automaton, c.symbols,
                                          c.analysis, c.lights,   refused,     c.camera};
            steppingContext.requested = 1;
            steppingContext.keepAllPaths = false;
            const PathState steppingPath(steppingContext, sink, counters);
            checkAgainstStepping(world, steppingPath, refused, false);
        }
    }
}

}  // namespace
}  // namespace lightpath
