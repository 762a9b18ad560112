// Triangulation of polygons with holes (GeneralPolygon, PointsGeneralPolygons,
// and concave Polygons), by ear clipping in the plane of the polygon.
//
// The holes are first joined to the outer loop by bridges (each hole, from the
// one reaching farthest right, to a vertex of the outer loop that sees its
// rightmost point), which leaves one loop. Ears are then cut from that loop;
// whether a candidate ear holds another vertex is answered by a grid of the
// reflex vertices only (no other vertex can be inside an ear), so a face of a
// million vertices takes about as many steps, not a million squared.
#pragma once

#include <vector>

#include "core/Math.h"

namespace bxdflab {

/// The most vertices one face may have; more is refused as absurd input.
constexpr size_t kMaxFaceVertices = 4'000'000;

/// `loops[0]` is the outer loop, the others holes, as indices into `points`
/// (3-D, projected on the plane the outer loop faces most). Returns triples
/// of indices into `points`, wound like the outer loop. A degenerate or
/// self-intersecting face still yields triangles (a best effort, never a hang).
std::vector<int> triangulatePolygon(std::vector<Vec3> const& points, std::vector<std::vector<int>> const& loops);

}  // namespace bxdflab
