#pragma once
// The tables of the two kinds a Scene holds as values (Scene::spheres, Scene::planes), declared
// here so that SceneGeometry (accel/, below shapes/) can turn them into records; each is defined,
// with its scene-file type, in its own file: shapes/sphere.cpp, shapes/plane.cpp.
#include "geometry/shape.h"

namespace lightpath {

extern const ShapeOps kSphereOps;
// The record of `sphere`: centre, radius.
ShapeRecord sphereRecord(const Sphere& sphere);
// The sphere a record of kSphereOps holds.
Sphere sphereOf(const ShapeRecord& record);

extern const ShapeOps kPlaneOps;
// The record of `plane`: a point, the unit normal.
ShapeRecord planeRecord(const Plane& plane);
// The plane a record of kPlaneOps holds.
Plane planeOf(const ShapeRecord& record);

}  // namespace lightpath
