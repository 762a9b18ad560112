// Blobby: RenderMan's implicit surfaces (Blinn's blobs, Wyvill's soft
// objects), polygonised into a triangle mesh.
//
// Each primitive field is 1 at its centre and falls to 0 with the distance r
// from it (in the unit space its matrix maps to the ellipsoid or segment):
//   f(r) = (1 - r^2 / R^2)^3 for r < R, else 0,
// with R = 1 / sqrt(1 - 0.5^(1/3)) so that f(1) = 0.5. The surface is where the
// combined field equals 0.5: a lone ellipsoid is exactly its unit sphere, and
// nearby ones blend. The code array combines the primitives (add, multiply,
// maximum, minimum, subtract, divide, negate, identity), as the RI
// specification describes.
#pragma once

#include <string>
#include <vector>

#include "core/Diagnostics.h"
#include "scene/shapes/TriangleMesh.h"

namespace bxdflab {

/// Builds the mesh (throws a RibError at `where` for a malformed code array).
/// `skipped` receives a description of primitives that cannot be evaluated
/// (repelling planes and plugin fields, which count as 0), or stays empty.
MeshData buildBlobby(int leaves, std::vector<int> const& code, std::vector<float> const& floats,
                     Mat4 const& toWorld, bool flip, SourceLocation const& where, std::string& skipped);

}  // namespace bxdflab
