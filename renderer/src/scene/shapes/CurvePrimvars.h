// The primvars of a Curves request that vary along its curves, as the RI
// specification lays them out: uniform values one per curve, varying (and
// facevarying) ones at the ends of each curve's segments, blended linearly
// along them, vertex ones at the control vertices, through the curves' basis
// as the points are.
#pragma once

#include <vector>

#include "parse/ParamList.h"
#include "scene/shapes/MeshBuilders.h"
#include "scene/shapes/Primvars.h"

namespace bxdflab {

/// Where each segment the ray tracer draws came from.
struct CurveLayout {
    struct Segment {
        unsigned curve;         ///< which curve of the request
        unsigned index;         ///< which segment of that curve
        unsigned firstVertex;   ///< the curve's first control vertex in "P"
        unsigned vertices;      ///< the curve's control vertices
        unsigned firstVarying;  ///< the curve's first varying value
        unsigned varyings;      ///< the curve's varying values: its segments, plus one unless periodic
    };
    std::vector<Segment> segments;  ///< in the order the segments are drawn (a hit's primID)
    size_t curves = 0, vertices = 0, varyings = 0;
    bool cubic = false, periodic = false;
    SplineBasis basis = SplineBasis::bezier();  ///< cubic curves' basis (the v basis)
};

/// Adds to `primvars` the parameters of `params` that vary along the curves
/// (neither geometry, nor constant, nor taken yet), each read at a hit's
/// segment and its parameter along it. Marks them used; a count that does not
/// fit the curves is an error at the parameter.
void addCurvePrimvars(PrimvarSet& primvars, ParamList const& params, CurveLayout layout);

}  // namespace bxdflab
