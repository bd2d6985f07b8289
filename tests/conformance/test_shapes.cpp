// Every registered shape kind's cases (cases.cpp) through every shape check (shape_checks.h). The
// light checks run the same cases as emitting objects (test_lights.cpp).
#include <doctest/doctest.h>

#include <set>
#include <string_view>

#include "cases.h"
#include "shape_checks.h"
#include "scene/shape_type.h"

namespace lightpath::conformance {
namespace {

template <typename Check>
void forEveryShape(Check&& check) {
    int shapes = 0;
    std::set<std::string_view> kinds;
    forEachShapeCase([&](const ShapeCase& c) {
        ++shapes;
        kinds.insert(c.shape().ops->name);
        const CheckResult result = check(c.shape());
        INFO(c.name << ":\n" << result.failures);
        CHECK(result.passed);
    });
    CHECK(shapes >= int(ShapeRegistry::instance().entries().size()));
    CHECK(ShapeRegistry::instance().find("disk") != nullptr);
    // Every kind stored as records is checked, whoever registered it: spheres and planes (records
    // of the one table too), the disk, and the example plugin's cylinder this suite links
    // (triangles and meshes are not: ShapeStorage::triangles).
    std::set<std::string_view> registered;
    for (const ShapeType* type : ShapeRegistry::instance().entries())
        if (type->storage == ShapeStorage::records) registered.insert(type->schema.name);
    CHECK(kinds == registered);
    CHECK(kinds.count("sphere") + kinds.count("plane") + kinds.count("disk") + kinds.count("cylinder") == 4);
}

TEST_CASE("shapes: lines cross each as often as its area says (Cauchy-Crofton), hits within bounds") {
    forEveryShape(checkShapeCrossings);
}

TEST_CASE("shapes: area samples are uniform by area and lie on the surface") { forEveryShape(checkShapeSampling); }

TEST_CASE("shapes: hits have unit normals and lie on the surface") { forEveryShape(checkShapeHits); }

TEST_CASE("shapes: the tessellation's area converges to the area") { forEveryShape(checkShapeTessellation); }

TEST_CASE("shapes: a patch grid's cells cover the surface by area, and each point locates to its cell") {
    forEveryShape(checkShapePatchGrid);
}

TEST_CASE("shapes: an unbounded kind's tessellation over a region covers its hits there") {
    forEveryShape(checkShapeRegionTessellation);
}

TEST_CASE("shapes: the rasteriser's depthAlong is intersect's distance") { forEveryShape(checkShapeDepthAlong); }

}  // namespace
}  // namespace lightpath::conformance
