// The schema library (src/schema/) by hand-written cases, and the registration of every shipped
// material and light type in this binary (schema.md: registrars survive static linking).
#include <doctest/doctest.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/light_type.h"
#include "scene/shape_type.h"
#include "materials/material_type.h"
#include "media/medium_type.h"
#include "schema/markdown.h"
#include "schema/parameter_values.h"
#include "schema/registry.h"
#include "schema/schema_error.h"

namespace lightpath {
namespace {

const TypeSchema& exampleSchema() {
    static const TypeSchema schema{
        "material", "example", "a test type",
        {{"k", ParameterType::Colour, "", "0.5", kNonNegative, "a reflectance"},
         {"n", ParameterType::Number, "", "20", kNonNegative, "an exponent"},
         {"fov", ParameterType::Number, "degrees", "45", Range{0.0, 180.0, true, true}, "an angle"},
         {"at", ParameterType::Point, "m", "[1, 2, 3]", {}, "a place", false},
         {"up", ParameterType::Vector, "", "[0, 1, 0]", {}, "a direction"},
         {"label", ParameterType::Name, "", "", {}, "a label"},
         {"count", ParameterType::Integer, "", "3", Range{1.0, 10.0}, "how many"},
         {"on", ParameterType::Boolean, "", "true", {}, "a switch"},
         {"where", ParameterType::Point, "m", "", {}, "required", true}},
        "<RD>"};
    return schema;
}

TEST_CASE("a range says what it admits") {
    CHECK(kNonNegative.describe() == ">= 0");
    CHECK(kPositive.describe() == "> 0");
    CHECK(Range{0.0, 180.0, true, true}.describe() == "0 < x < 180");
    CHECK(kAnyValue.describe() == "any");
    CHECK(kNonNegative.admits(0.0));
    CHECK_FALSE(kPositive.admits(0.0));
    CHECK_FALSE(Range{0.0, 180.0, true, true}.admits(180.0));
}

TEST_CASE("values start at the schema's defaults, not given") {
    const ParameterValues values(exampleSchema());
    CHECK(values.colour("k") == Rgb(0.5f));
    CHECK(values.number("n") == 20.0f);
    CHECK(values.vec3("at") == Vec3(1.0f, 2.0f, 3.0f));
    CHECK(values.integer("count") == 3);
    CHECK(values.boolean("on"));
    CHECK(values.text("label").empty());
    CHECK_FALSE(values.has("n"));
}

TEST_CASE("set checks the type and the range") {
    ParameterValues values(exampleSchema());
    values.set("n", 3.5);
    CHECK(values.has("n"));
    CHECK(values.number("n") == 3.5f);
    values.set("n", 7);  // an integer for a number
    CHECK(values.number("n") == 7.0f);
    values.set("label", "key_light");
    CHECK(values.text("label") == "key_light");
    CHECK_THROWS_WITH_AS(values.set("n", -1.0), "n: expected a number >= 0, got -1", SchemaError);
    CHECK_THROWS_WITH_AS(values.set("fov", 180.0), "fov: expected a number 0 < x < 180, got 180", SchemaError);
    CHECK_THROWS_AS(values.set("k", Rgb(0.5f, -0.1f, 0.0f)), SchemaError);
    CHECK_THROWS_WITH_AS(values.set("up", Vec3(0.0f)), "up: expected a non-zero vector, got [0, 0, 0]", SchemaError);
    CHECK_THROWS_AS(values.set("label", "my light"), SchemaError);
    CHECK_THROWS_AS(values.set("count", 11), SchemaError);
    CHECK_THROWS_AS(values.set("n", true), SchemaError);      // wrong type
    CHECK_THROWS_AS(values.set("nope", 1.0), SchemaError);    // no such parameter
    CHECK_THROWS_AS(static_cast<void>(values.number("k")), SchemaError);  // a colour is not a number
}

TEST_CASE("fail is located at the value, or at the declaration when it was not given") {
    ParameterValues values(exampleSchema());
    values.locateDeclaration("scene.toml:4:1", "lights[0]");
    values.set("n", 2.0);
    values.locate("n", "scene.toml:5:5", "lights[0].n");
    CHECK_THROWS_WITH_AS(values.fail("n", "too small"), "scene.toml:5:5: lights[0].n: too small", SchemaError);
    CHECK_THROWS_WITH_AS(values.fail("k", "too dark"), "scene.toml:4:1: lights[0].k: too dark", SchemaError);
    const ParameterValues unlocated(exampleSchema());
    CHECK_THROWS_WITH_AS(unlocated.fail("k", "too dark"), "k: too dark", SchemaError);
}

TEST_CASE("a markdown row per parameter") {
    const TypeSchema schema{"light", "t", "", {{"n", ParameterType::Number, "", "20", kNonNegative, "an exponent"},
                                               {"at", ParameterType::Point, "m", "", {}, "a place", true}}, ""};
    CHECK(markdownTable(schema) ==
          "| key | type | unit | default | allowed | meaning |\n"
          "| --- | --- | --- | --- | --- | --- |\n"
          "| `n` | number | – | `20` | `>= 0` | an exponent |\n"
          "| `at` | point | m | **required** | any | a place |\n");
}

// The two value types of the shape kinds that add triangles: a triangle's corners, a mesh's scale.
TEST_CASE("3 points and per-axis values: defaults, checks, markdown") {
    const TypeSchema schema{
        "shape", "t", "",
        {{"corners", ParameterType::ThreePoints, "m", "[[0, 0, 0], [1, 0, 0], [0, 2, 0]]", {}, "a triangle"},
         {"box", ParameterType::ThreePoints, "m", "", Range{-1.0, 1.0}, "within the unit box"},
         {"scale", ParameterType::PerAxis, "", "2", kPositive, "a factor per axis"}},
        ""};
    ParameterValues values(schema);
    CHECK(values.points("corners") == std::array<Vec3, 3>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 2, 0)});
    CHECK(values.vec3("scale") == Vec3(2.0f));
    values.set("scale", Vec3(1.0f, 2.0f, 3.0f));
    CHECK(values.vec3("scale") == Vec3(1.0f, 2.0f, 3.0f));
    CHECK_THROWS_WITH_AS(values.set("scale", Vec3(1.0f, 0.0f, 1.0f)),
                         "scale: expected each of 3 numbers > 0, got [1, 0, 1]", SchemaError);
    values.set("box", std::array<Vec3, 3>{Vec3(0.5f), Vec3(-1.0f), Vec3(1.0f)});
    CHECK(values.points("box")[1] == Vec3(-1.0f));
    CHECK_THROWS_WITH_AS(values.set("box", std::array<Vec3, 3>{Vec3(0.0f), Vec3(0.0f, 2.0f, 0.0f), Vec3(0.0f)}),
                         "box: expected 3 points, each coordinate -1 <= x <= 1, got [0, 2, 0]", SchemaError);
    CHECK_THROWS_AS(values.set("corners", Vec3(0.0f)), SchemaError);  // 3 points, not one
    CHECK_THROWS_AS(static_cast<void>(values.vec3("corners")), SchemaError);
    CHECK(markdownTable(schema) ==
          "| key | type | unit | default | allowed | meaning |\n"
          "| --- | --- | --- | --- | --- | --- |\n"
          "| `corners` | 3 points | m | `[[0, 0, 0], [1, 0, 0], [0, 2, 0]]` | any | a triangle |\n"
          "| `box` | 3 points | m | none | each coordinate `-1 <= x <= 1` | within the unit box |\n"
          "| `scale` | number or [x, y, z] | – | `2` | each `> 0` | a factor per axis |\n");
}

struct TestEntry {
    TypeSchema schema;
    int rank = 0;
};

TEST_CASE("a registry lists by rank then name and refuses a duplicate") {
    TypeRegistry<TestEntry>& registry = TypeRegistry<TestEntry>::instance();
    registry.add({{"test", "b", "", {}, ""}, 1});
    registry.add({{"test", "c", "", {}, ""}, 0});
    registry.add({{"test", "a", "", {}, ""}, 1});
    CHECK(registry.names() == std::vector<std::string>{"c", "a", "b"});
    CHECK(registry.find("a")->rank == 1);
    CHECK(registry.find("z") == nullptr);
    CHECK_THROWS_AS(registry.add({{"test", "a", "", {}, ""}, 2}), std::logic_error);
}

TEST_CASE("every shipped material, medium, light and shape type is registered in this binary") {
    CHECK(MaterialRegistry::instance().names() == std::vector<std::string>{"phong", "modified-phong", "microfacet", "interface", "conductor", "dielectric"});
    CHECK(LightRegistry::instance().names() == std::vector<std::string>{"point", "quad", "sphere", "spot", "directional"});
    CHECK(MediumRegistry::instance().names() == std::vector<std::string>{"homogeneous"});
    CHECK(ShapeRegistry::instance().names() == std::vector<std::string>{"sphere", "plane", "disk", "triangle", "mesh", "gltf"});
}

}  // namespace
}  // namespace lightpath
