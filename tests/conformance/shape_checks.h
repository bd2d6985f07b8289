#pragma once
// The standard checks every registered shape kind gets (docs/extending.md), on shapes drawn
// within its schema (cases.h, forEachShapeCase): intersect against area by the Cauchy-Crofton
// formula (isotropic uniform lines through a ball of radius R cross a surface of area A on average
// A / (2 pi R^2) times), area samples uniform (the share of samples in a half-space against the
// share of crossings there), samples and hits on the surface with unit normals, and the
// tessellation's area converging to the area. Statistical checks use fixed seeds and allow 5
// standard errors. An unbounded kind (a plane: ShapeOps::bounded false) has infinite area: those
// checks ask only that area() be infinite and bounds() all of space; its hits are checked on
// lines through a ball of radius 100 at the origin.
#include "check_result.h"
#include "geometry/shape.h"

namespace lightpath::conformance {

// intersect() against area(): crossings counted along many lines, and every hit inside bounds().
CheckResult checkShapeCrossings(const ShapeRecord& shape);
// sampleArea() against intersect(): the share of samples in random half-spaces is the share of
// the surface there (by crossings), and a ray aimed at a sample from outside meets the surface there.
CheckResult checkShapeSampling(const ShapeRecord& shape);
// describe(): unit normals, the point on the surface (a short ray along the normal finds it).
CheckResult checkShapeHits(const ShapeRecord& shape);
// tessellate(): its area within 1% of area() at a fine edge length, closer than at a coarse one.
CheckResult checkShapeTessellation(const ShapeRecord& shape);

// The optional entries radiosity and the rasteriser read (shape.h); a kind without one passes.
// patchGrid: the cells' areas sum to area(); uniform area samples fall into each cell (locate) in
// proportion to its area, so the cells cover the surface; a cell's centre and samples locate to that
// cell, lie on the surface with unit normals; corners are numbered 0 .. corners - 1, each used.
CheckResult checkShapePatchGrid(const ShapeRecord& shape);
// tessellateRegion: every hit of a line inside the region lies on one of the triangles, which lie on
// the surface, wound with its normal.
CheckResult checkShapeRegionTessellation(const ShapeRecord& shape);
// depthAlong: s |d| is intersect's t along the unit ray (1e-4 relative, plus the float rounding of
// the eye's and the point's coordinates over the cosine), for directions d of any length; no depth
// where intersect finds no hit.
CheckResult checkShapeDepthAlong(const ShapeRecord& shape);

}  // namespace lightpath::conformance
