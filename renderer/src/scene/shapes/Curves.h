// Curves (hair, grass, strokes): round tubes along linear or cubic curves,
// intersected by Embree's curve geometry. Every cubic basis RenderMan allows
// (Basis: bezier, b-spline, catmull-rom, hermite, power or a matrix) is turned
// into Bezier segments, so one Embree type draws them all.
#pragma once

#include <vector>

#include "scene/shapes/Shape.h"

namespace bxdflab {

/// Control points with their radius (x, y, z, r), world space.
struct CurveData {
    bool cubic = false;               ///< Bezier segments of 4 points; else linear segments of 2
    std::vector<Vec4> points;
    std::vector<unsigned> segments;   ///< index of each segment's first point
};

class Curves final : public Shape {
public:
    /// `primvars`: those that vary along the curves (CurvePrimvars); an "st"
    /// among them gives the curves' s and t.
    Curves(CurveData data, PrimvarSet primvars);

    const char* kind() const override { return "Curves"; }
    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basicsUnmoved(HitRecord const& hit) const override;
    SurfaceTangents tangentsUnmoved(HitRecord const& hit) const override;
    CurveData const& data() const { return m_data; }
    /// The tubes' centre lines and radii as the ray tracer built them.
    void attach(std::shared_ptr<SurfaceEvaluator const> evaluator) const { m_evaluator = std::move(evaluator); }

private:
    CurveData m_data;
    mutable std::shared_ptr<SurfaceEvaluator const> m_evaluator;
};

/// Points (particles): spheres of a radius each, intersected by Embree's point geometry.
class Points final : public Shape {
public:
    explicit Points(std::vector<Vec4> spheres) : m_spheres(std::move(spheres)) {}
    const char* kind() const override { return "Points"; }
    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basicsUnmoved(HitRecord const& hit) const override;
    SurfaceTangents tangentsUnmoved(HitRecord const& hit) const override;
    std::vector<Vec4> const& spheres() const { return m_spheres; }
    /// A particle's own value (uniform: one per point), else the constant one.
    void primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const override;

private:
    std::vector<Vec4> m_spheres;  ///< centre and radius, world space
};

}  // namespace bxdflab
