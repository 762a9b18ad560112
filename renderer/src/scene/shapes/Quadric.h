// The RenderMan quadrics (Sphere, Cylinder, Disk, ...) as analytic Embree user
// geometry. Each is defined in its own object space, parameterised as in the
// RenderMan Interface Specification (u = phi / phimax, v along the sweep), and
// intersected exactly (in double precision) rather than tessellated, so
// normals and dPdu/dPdv are the true ones.
#pragma once

#include <optional>

#include "scene/shapes/Shape.h"

namespace bxdflab {

class Quadric : public Shape {
public:
    Quadric(Mat4 const& objectToWorld, bool reverseOrientation);

    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basics(HitRecord const& hit) const override;
    SurfaceTangents tangents(HitRecord const& hit) const override;

    /// Object-space hit: distance and surface parameters.
    struct LocalHit {
        double t;
        float u, v;
    };
    /// Nearest hit with t in (tnear, tfar) of an object-space ray.
    virtual std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear,
                                                   double tfar) const = 0;
    /// Object-space surface point, outward normal (unit) and derivatives at (u, v).
    struct LocalSurface {
        Vec3 P, N, dPdu, dPdv;
    };
    virtual LocalSurface surfaceLocal(float u, float v) const = 0;
    /// Object-space bounding box.
    virtual void boundsLocal(Vec3& lower, Vec3& upper) const = 0;

    Mat4 const& objectToWorld() const { return m_objectToWorld; }
    Mat4 const& worldToObject() const { return m_worldToObject; }

protected:
    /// Angle of a point in [0, 2 pi).
    static double azimuth(double x, double y);

private:
    Mat4 m_objectToWorld;
    Mat4 m_worldToObject;
    float m_orientation;  ///< +1, or -1 under ReverseOrientation
};

}  // namespace bxdflab
