#pragma once
// A camera for a scene or model whose size and place are unknown (an OBJ given as the scene, a
// scene without [camera], `--fit`): it sees the whole bounding sphere of the scene's bounded
// shapes, whatever the image's aspect ratio.
#include "geometry/bounds.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace lightpath {

// The box around every bounded shape: spheres, triangles and the registered kinds' records.
// Planes have none. Empty when the scene has no bounded shape.
Bounds sceneBounds(const Scene& scene);

// Where a camera without a given view looks from, relative to what it frames: in front (+z),
// a little above and to the right, so that three faces of a box show.
inline constexpr Vec3 kFramingDirection{0.5f, 0.4f, 1.0f};

// The framing camera stands this much further than where the sphere touches the image's edges:
// room around the object, and no corner of its box exactly on an edge.
inline constexpr double kFramingMargin = 1.1;

// `camera` moved to see the bounding sphere of `bounds` whole: it looks at the sphere's centre
// along its own viewing direction (from eye to look_at) and up, keeps its field of view and
// resolution, and stands at distance kFramingMargin r / sin(a), a the smaller of the vertical and horizontal
// half-angles, so the cone of half-angle a that touches the sphere lies inside the image's
// frustum. An orthographic camera stands outside the sphere, its height set to see all of it.
// An empty box frames the unit sphere at the origin.
CameraDescription framingCamera(const Bounds& bounds, CameraDescription camera);

}  // namespace lightpath
