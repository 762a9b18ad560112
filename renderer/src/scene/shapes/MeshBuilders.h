// Turn RIB primitives that are not quadrics into world-space triangle meshes.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/Diagnostics.h"
#include "parse/ParamList.h"
#include "scene/shapes/TriangleMesh.h"

namespace bxdflab {

/// Polygon, PointsPolygons and PointsGeneralPolygons. `loopsPerFace` has one
/// entry per face (1 for simple polygons; more means holes: the first loop is
/// the outline, the others holes). Concave faces and holes are triangulated
/// by ear clipping (scene/shapes/Triangulation). Primvars read from `params`: P (required),
/// N and st (or s and t) with class vertex/varying/facevarying/uniform/constant.
MeshData buildPolygonMesh(std::vector<int> const& loopsPerFace, std::vector<int> const& verticesPerLoop,
                          std::vector<int> const& vertexIndices, ParamList const& params, Mat4 const& toWorld,
                          SourceLocation const& where);

/// Patch "bilinear": four corners in the order (0,0) (1,0) (0,1) (1,1). With
/// `normals` (the corners' "N", in object space) the shading normal is their
/// bilinear blend, as RenderMan interpolates a varying N; without, the surface's.
MeshData buildBilinearPatch(std::array<Vec3, 4> const& corners, Mat4 const& toWorld, bool flip,
                            std::array<Vec3, 4> const* normals = nullptr);

/// A RenderMan spline basis (Basis request): a 4x4 matrix and the step
/// between successive patches of a patch mesh.
struct SplineBasis {
    float matrix[4][4];
    int step;
    /// "bezier", "b-spline", "catmull-rom", "hermite" or "power"; false if unknown.
    static bool named(std::string const& name, SplineBasis& out);
    static SplineBasis bezier();
    /// The four control points' weights [t^3 t^2 t 1] M at t, and their derivatives.
    void weights(float t, float w[4], float dw[4]) const;
};

/// Patch "bicubic" / PatchMesh "bicubic": nu x nv control points (u varies
/// fastest), periodic or not in each direction, tessellated with exact
/// derivatives. Throws RibError when the counts do not fit the basis.
/// As in RenderMan, (u, v) run from 0 to 1 over the whole mesh. With
/// `primvars`, its primvars that vary over the mesh are taken (PatchPrimvars.h).
MeshData buildBicubicPatchMesh(std::vector<Vec3> const& points, int nu, bool uPeriodic, int nv, bool vPeriodic,
                               SplineBasis const& uBasis, SplineBasis const& vBasis, Mat4 const& toWorld, bool flip,
                               SourceLocation const& where, ParamList const* primvars = nullptr);

/// PatchMesh "bilinear" (and Patch "bilinear", a mesh of 2 x 2 points): a grid
/// of nu x nv points, and optionally a normal at each; (u, v) and primvars as
/// for the bicubic mesh.
MeshData buildBilinearPatchMesh(std::vector<Vec3> const& points, int nu, bool uPeriodic, int nv, bool vPeriodic,
                                Mat4 const& toWorld, bool flip, SourceLocation const& where,
                                std::vector<Vec3> const* normals = nullptr, ParamList const* primvars = nullptr);

/// Torus majorrad minorrad phimin phimax thetamax, tessellated finely with
/// exact derivatives of the RenderMan parameterisation.
MeshData buildTorus(float majorRadius, float minorRadius, float phiMinDegrees, float phiMaxDegrees,
                    float thetaMaxDegrees, Mat4 const& toWorld, bool flip);

/// Geometry "teapot": the Newell teapot, tessellated finely, with smooth
/// normals and exact dPdu/dPdv from its Bezier patches.
MeshData buildTeapot(Mat4 const& toWorld, bool flip);

}  // namespace bxdflab
