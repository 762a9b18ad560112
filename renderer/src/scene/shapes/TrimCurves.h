// TrimCurve: closed loops of NURBS curves in a NuPatch's (u, v) parameter
// space that cut parts of the patch away. Each loop is kept as the polyline
// through its curves; a point of the patch is kept where a ray from it
// crosses the loops an odd number of times (the RI specification's odd
// winding rule), or, under Attribute "trimcurve" "sense" "outside", where it
// crosses them an even number of times.
#pragma once

#include <memory>
#include <vector>

#include "core/Math.h"

namespace bxdflab {

/// One trim curve as TrimCurve gives it: a NURBS curve in homogeneous (u, v, w).
struct TrimCurveDesc {
    int order = 0;
    std::vector<float> knots;  ///< n + order values, non-decreasing
    float min = 0.0f, max = 1.0f;
    std::vector<Vec3> uvw;  ///< n control points (u w, v w, w)
};

class TrimLoops {
public:
    /// Throws std::invalid_argument naming what is wrong with a curve.
    explicit TrimLoops(std::vector<std::vector<TrimCurveDesc>> const& loops);

    /// Whether (u, v) lies inside the loops (crossed an odd number of times).
    bool inside(Vec2 uv) const;
    size_t loopCount() const { return m_loops.size(); }

private:
    struct Loop {
        std::vector<Vec2> points;  ///< closed: the last joins the first
        Vec2 lo, hi;               ///< bounds, to pass over a loop a point is not near
    };
    std::vector<Loop> m_loops;
};

/// What a trimmed patch keeps: the inside of its loops, or the outside.
struct Trim {
    std::shared_ptr<TrimLoops const> loops;
    bool keepOutside = false;
    bool keeps(Vec2 uv) const { return loops->inside(uv) != keepOutside; }
};

}  // namespace bxdflab
