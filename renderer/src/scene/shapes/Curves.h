// Curves (hair, grass, strokes): round tubes along linear or cubic curves, or
// flat ribbons facing the normals the RIB gives, intersected by Embree's curve
// geometry. Every cubic basis RenderMan allows (Basis: bezier, b-spline,
// catmull-rom, hermite, power or a matrix) is turned into Bezier segments, so
// one Embree type draws each kind.
#pragma once

#include <vector>

#include "scene/shapes/Shape.h"

namespace bxdflab {

/// Control points with their radius (x, y, z, r), world space.
struct CurveData {
    bool cubic = false;               ///< Bezier segments of 4 points; else linear segments of 2
    std::vector<Vec4> points;
    std::vector<unsigned> segments;   ///< index of each segment's first point
    /// Empty: round tubes. Else a ribbon: the normal it faces at each control point (Bezier
    /// segments only), world space.
    std::vector<Vec3> normals;
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

/// Points (particles), intersected by Embree's point geometry: spheres of a radius each, or,
/// when the RIB gives them normals, flat disks of that radius facing their normals.
class Points final : public Shape {
public:
    /// `normals`: empty (spheres) or one unit normal per particle, world space (disks).
    explicit Points(std::vector<Vec4> particles, std::vector<Vec3> normals = {})
        : m_particles(std::move(particles)), m_normals(std::move(normals)) {}
    const char* kind() const override { return "Points"; }
    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basicsUnmoved(HitRecord const& hit) const override;
    SurfaceTangents tangentsUnmoved(HitRecord const& hit) const override;
    /// Each particle's centre and radius, world space.
    std::vector<Vec4> const& particles() const { return m_particles; }
    /// The disks' normals (empty: the particles are spheres).
    std::vector<Vec3> const& normals() const { return m_normals; }
    /// A particle's own value (uniform: one per point), else the constant one.
    void primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const override;

private:
    std::vector<Vec4> m_particles;
    std::vector<Vec3> m_normals;
};

}  // namespace bxdflab
