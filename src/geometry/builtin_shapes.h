#pragma once
// The records of the two kinds a Scene holds as values (Scene::spheres, Scene::planes), declared
// here so that SceneGeometry (accel/, below shapes/) can turn them into records; each is defined,
// with its table and scene-file type, in its own file: shapes/sphere.cpp, shapes/plane.cpp.
// Radiosity and the rasteriser ask a record's table (shape.h), never for its kind.
#include "geometry/shape.h"

namespace lightpath {

// The record of `sphere`: centre, radius.
ShapeRecord sphereRecord(const Sphere& sphere);
// The sphere a record of sphereRecord holds (the stress scorecard's sphere rows read its centre).
Sphere sphereOf(const ShapeRecord& record);

// The record of `plane`: a point, the unit normal.
ShapeRecord planeRecord(const Plane& plane);

}  // namespace lightpath
