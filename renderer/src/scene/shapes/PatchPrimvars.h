// The primvars of a Patch or PatchMesh that vary over it, as the RI
// specification lays them out: varying values at the patches' corners
// (interpolated bilinearly), vertex values at the control points (through the
// patches' basis), uniform values one per patch.
#pragma once

#include "parse/ParamList.h"
#include "scene/shapes/MeshBuilders.h"

namespace bxdflab {

/// How a patch mesh's control points make patches.
struct PatchLayout {
    int nu, nv;  ///< control points in u and v
    bool uPeriodic, vPeriodic;
    int patchesU, patchesV;
    bool bicubic;
    SplineBasis uBasis, vBasis;  ///< bicubic meshes only
};

/// Gives `mesh` (the tessellated patches, its uv running over [0, 1]^2 across
/// all of them) the primvars of `params` not taken yet, each read at a hit's
/// (u, v) (an "st" among them gives the mesh's s and t). Marks them used; a
/// count that does not fit the mesh is an error at the parameter.
void addPatchPrimvars(MeshData& mesh, ParamList const& params, PatchLayout const& layout);

}  // namespace bxdflab
