// The primvars of a NuPatch that vary over it, as the RI specification lays
// them out: vertex values at the control points (through the surface's
// rational basis, as its points are), varying and facevarying values at the
// corners of its segments (interpolated bilinearly), uniform values one per
// segment.
#pragma once

#include "parse/ParamList.h"
#include "scene/shapes/MeshBuilders.h"
#include "scene/shapes/NurbsSurface.h"

namespace bxdflab {

/// Gives `mesh` (the tessellated patch, its uv the patch's own (u, v)) the
/// primvars of `params` that are neither geometry nor constant nor taken yet,
/// each read at a hit's (u, v) (an "st" among them gives the mesh's s and t).
/// Marks them used; a count that does not fit the patch is an error at the
/// parameter.
void addNurbsPrimvars(MeshData& mesh, ParamList const& params, NurbsDesc const& nurbs);

}  // namespace bxdflab
