#include "scene/shapes/TrimCurves.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "scene/shapes/NurbsSurface.h"

namespace bxdflab {
namespace {

/// Points along each knot span of a trim curve: enough that the polyline
/// follows a curved trim closely at any size a patch is seen; fewer per span
/// for a curve of thousands of spans, whose spans are short already.
constexpr int kStepsPerSpan = 32;
constexpr int kStepsPerCurve = 8192;

void checkCurve(TrimCurveDesc const& c, size_t index) {
    std::string const which = "trim curve " + std::to_string(index);
    int const n = static_cast<int>(c.uvw.size());
    if (c.order < 1 || n < c.order)
        throw std::invalid_argument(which + ": its order must be at least 1 and at most its number of points");
    if (c.knots.size() != static_cast<size_t>(n + c.order))
        throw std::invalid_argument(which + ": needs " + std::to_string(n + c.order) + " knots, got " +
                                    std::to_string(c.knots.size()));
    for (size_t i = 0; i + 1 < c.knots.size(); ++i)
        if (!(c.knots[i] <= c.knots[i + 1])) throw std::invalid_argument(which + ": its knots must not decrease");
    if (!(c.min < c.max) || c.min < c.knots[static_cast<size_t>(c.order - 1)] ||
        c.max > c.knots[static_cast<size_t>(n)])
        throw std::invalid_argument(which + ": its range must lie within the knots where the curve is defined");
}

/// Appends the curve's points from min up to (not including) max: the next curve of the loop
/// starts where this one ends.
void appendCurve(TrimCurveDesc const& c, std::vector<Vec2>& out) {
    std::vector<float> breaks = {c.min};
    for (float k : c.knots)
        if (k > c.min && k < c.max && k != breaks.back()) breaks.push_back(k);
    breaks.push_back(c.max);
    std::vector<float> N, dN;
    int const n = static_cast<int>(c.uvw.size());
    int const spans = static_cast<int>(breaks.size()) - 1;
    int const steps = std::clamp(kStepsPerCurve / std::max(spans, 1), 1, kStepsPerSpan);
    for (size_t s = 0; s + 1 < breaks.size(); ++s)
        for (int j = 0; j < steps; ++j) {
            float const t = breaks[s] + (breaks[s + 1] - breaks[s]) * static_cast<float>(j) / static_cast<float>(steps);
            bsplineBasis(c.knots, n, c.order, t, N, dN);
            Vec3 h(0.0f);
            for (int i = 0; i < n; ++i) h += N[static_cast<size_t>(i)] * c.uvw[static_cast<size_t>(i)];
            if (h.z != 0.0f) out.emplace_back(h.x / h.z, h.y / h.z);
        }
}

}  // namespace

TrimLoops::TrimLoops(std::vector<std::vector<TrimCurveDesc>> const& loops) {
    size_t index = 0;
    for (auto const& curves : loops) {
        Loop loop;
        for (TrimCurveDesc const& c : curves) {
            checkCurve(c, index++);
            appendCurve(c, loop.points);
        }
        if (loop.points.size() < 3) continue;  // encloses nothing
        loop.lo = loop.hi = loop.points[0];
        for (Vec2 const& p : loop.points) {
            loop.lo = glm::min(loop.lo, p);
            loop.hi = glm::max(loop.hi, p);
        }
        m_loops.push_back(std::move(loop));
    }
}

bool TrimLoops::inside(Vec2 uv) const {
    // A ray toward +u: count the edges that span the point's v and cross it to its right.
    bool odd = false;
    for (Loop const& loop : m_loops) {
        if (uv.y < loop.lo.y || uv.y > loop.hi.y || uv.x > loop.hi.x) continue;
        std::vector<Vec2> const& p = loop.points;
        for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
            if ((p[i].y > uv.y) == (p[j].y > uv.y)) continue;
            float const crossU = p[j].x + (uv.y - p[j].y) / (p[i].y - p[j].y) * (p[i].x - p[j].x);
            if (crossU > uv.x) odd = !odd;
        }
    }
    return odd;
}

}  // namespace bxdflab
