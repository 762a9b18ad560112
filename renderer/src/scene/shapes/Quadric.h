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

    RTCGeometry build(RTCDevice device) const override;
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

class Sphere final : public Quadric {
public:
    Sphere(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Sphere"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_radius, m_zMin, m_zMax, m_thetaZMin, m_thetaZMax, m_phiMax;
};

class Cylinder final : public Quadric {
public:
    Cylinder(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Cylinder"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_radius, m_zMin, m_zMax, m_phiMax;
};

class Disk final : public Quadric {
public:
    Disk(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Disk"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_height, m_radius, m_phiMax;
};

/// Cone height radius thetamax: apex at z = height, base circle at z = 0.
class Cone final : public Quadric {
public:
    Cone(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Cone"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_height, m_radius, m_phiMax;
};

/// Paraboloid rmax zmin zmax thetamax: x^2 + y^2 = rmax^2 z / zmax.
class Paraboloid final : public Quadric {
public:
    Paraboloid(float rmax, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Paraboloid"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_rmax, m_zMin, m_zMax, m_phiMax;
};

/// Hyperboloid point1 point2 thetamax: the line from point1 to point2 swept
/// about the z axis (point1.z must differ from point2.z).
class Hyperboloid final : public Quadric {
public:
    Hyperboloid(Vec3 const& p1, Vec3 const& p2, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Hyperboloid"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    DVec3 m_p1, m_p2;
    double m_phiMax;
};

}  // namespace bxdflab
