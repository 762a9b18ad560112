// NuPatch: a rational B-spline surface of any order, tessellated into a
// triangle mesh with exact derivatives (the RI specification's NURBS: knot
// vectors, parameter ranges [umin, umax] x [vmin, vmax], control points P
// or homogeneous Pw).
#pragma once

#include <vector>

#include "core/Diagnostics.h"
#include "scene/shapes/TriangleMesh.h"

namespace bxdflab {

struct NurbsDesc {
    int nu = 0, uorder = 0, nv = 0, vorder = 0;
    std::vector<float> uknot, vknot;  ///< nu + uorder and nv + vorder values, non-decreasing
    float umin = 0, umax = 1, vmin = 0, vmax = 1;
    std::vector<Vec4> Pw;  ///< nu x nv homogeneous control points (x w, y w, z w, w), u fastest
};

/// The B-spline basis functions of one order over `knots` and their first
/// derivatives at t: N[i] and dN[i] for each of the `count` control points
/// (Cox-de Boor recursion; t at the end of the last span belongs to it).
void bsplineBasis(std::vector<float> const& knots, int count, int order, float t, std::vector<float>& N,
                  std::vector<float>& dN);

/// Checks the description (throws a RibError at `where` naming the problem)
/// and tessellates it in world space.
MeshData buildNurbsPatch(NurbsDesc const& nurbs, Mat4 const& toWorld, bool flip, SourceLocation const& where);

}  // namespace bxdflab
