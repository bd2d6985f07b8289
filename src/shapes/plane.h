#pragma once
// The plane kind's table (shapes/plane.cpp) and its record, for code that is handed planes as
// values (SceneGeometry's constructor, radiosity's clipped rectangles).
#include "geometry/shape.h"

namespace lightpath {

extern const ShapeOps kPlaneOps;
// The record of `plane`: a point, the unit normal.
ShapeRecord planeRecord(const Plane& plane);
// The plane a record of kPlaneOps holds.
Plane planeOf(const ShapeRecord& record);

}  // namespace lightpath
