// The RenderMan quadrics (Sphere, Cylinder, Disk, ...) as analytic Embree user
// geometry. Each is defined in its own object space, parameterised as in the
// RenderMan Interface Specification (u = phi / phimax, v along the sweep), and
// intersected exactly (in double precision) rather than tessellated, so
// normals and dPdu/dPdv are the true ones.
#pragma once

#include <initializer_list>
#include <optional>

#include "scene/shapes/Shape.h"

namespace bxdflab {

class Quadric : public Shape {
public:
    /// thetaMaxDegrees: the sweep about z (RenderMan's thetamax), clamped to 0..360.
    Quadric(Mat4 const& objectToWorld, bool reverseOrientation, float thetaMaxDegrees);

    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basicsUnmoved(HitRecord const& hit) const override;
    SurfaceTangents tangentsUnmoved(HitRecord const& hit) const override;

    /// Object-space hit: distance and surface parameters.
    struct LocalHit {
        double t;
        float u, v;
    };
    /// Nearest hit with t in (tnear, tfar) of an object-space ray.
    virtual std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear,
                                                   double tfar) const = 0;
    /// Whether an object-space ray hits with t in (tnear, tfar): what a shadow ray
    /// asks. By default intersectLocal's answer; a shape may answer without
    /// working out the hit's (u, v).
    virtual bool hitsLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const {
        return intersectLocal(org, dir, tnear, tfar).has_value();
    }
    /// Object-space surface point, outward normal (unit) and derivatives at (u, v).
    struct LocalSurface {
        Vec3 P, N, dPdu, dPdv;
    };
    virtual LocalSurface surfaceLocal(float u, float v) const = 0;
    /// The same at a hit (whose point is org + t dir, at parameters u, v). By
    /// default from (u, v); a quadric may instead work from the hit point and
    /// spare the trigonometry of its parameterisation.
    virtual LocalSurface surfaceAtHit(HitRecord const& hit) const { return surfaceLocal(hit.u, hit.v); }
    /// Object-space bounding box.
    virtual void boundsLocal(Vec3& lower, Vec3& upper) const = 0;

    /// This quadric as one ball (centre and radius, in the space it is placed
    /// in) when it is a whole sphere placed by rotation, translation and
    /// uniform scale, so that Embree's own sphere primitive can intersect it
    /// (its hits carry no (u, v): the shape works them out in parameters());
    /// nothing otherwise.
    virtual std::optional<Vec4> placedSphere() const { return std::nullopt; }

    Mat4 const& objectToWorld() const { return m_objectToWorld; }
    Mat4 const& worldToObject() const { return m_worldToObject; }
    /// worldToObject in double precision, for intersecting rays.
    glm::dmat4 const& worldToObjectExact() const { return m_worldToObjectExact; }

protected:
    /// Angle of a point in [0, 2 pi).
    static double azimuth(double x, double y);
    /// The hit point org + t dir in object space.
    DVec3 hitPointLocal(HitRecord const& hit) const {
        glm::dvec3 world = glm::dvec3(hit.org) + static_cast<double>(hit.t) * glm::dvec3(hit.dir);
        return DVec3(m_worldToObjectExact * glm::dvec4(world, 1.0));
    }
    /// The sweep angle in radians.
    double phiMax() const { return m_phiMax; }
    /// dP/du of a surface of revolution at its point p: u sweeps phi over phiMax.
    Vec3 sweepTangent(DVec3 const& p) const { return Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0); }

    /// Surface parameters of a hit.
    struct Uv {
        float u, v;
    };
    /// (u, v) of a point at azimuth phi (radians, in [0, 2 pi)) and parameter v, or
    /// nothing where phi lies past the sweep.
    std::optional<Uv> swept(double phi, double v) const {
        if (phi > m_phiMax) return std::nullopt;
        return Uv{static_cast<float>(phi / m_phiMax), static_cast<float>(v)};
    }
    /// Where z lies from zMin (0) to zMax (1); 0 for a surface of no height.
    static double heightFraction(double z, double zMin, double zMax) {
        double height = zMax - zMin;
        return height > 0.0 ? (z - zMin) / height : 0.0;
    }
    /// The nearer of the roots t0 <= t1 in (tnear, tfar) whose point is on the
    /// surface: onSurface(t) gives that point's (u, v), or nothing where it lies
    /// outside the surface's range or sweep.
    template <class OnSurface>
    static std::optional<LocalHit> firstRoot(double t0, double t1, double tnear, double tfar, OnSurface onSurface) {
        for (double t : {t0, t1}) {
            if (t <= tnear || t >= tfar) continue;
            if (std::optional<Uv> uv = onSurface(t)) return LocalHit{t, uv->u, uv->v};
        }
        return std::nullopt;
    }
    /// firstRoot for a surface of revolution cut at the heights zMin..zMax (a
    /// cylinder, a paraboloid): v is the hit's height fraction.
    std::optional<LocalHit> firstRootBetweenHeights(double t0, double t1, double tnear, double tfar, DVec3 const& org,
                                                    DVec3 const& dir, double zMin, double zMax) const {
        return firstRoot(t0, t1, tnear, tfar, [&](double t) -> std::optional<Uv> {
            DVec3 p = org + t * dir;
            if (p.z < zMin || p.z > zMax) return std::nullopt;
            return swept(azimuth(p.x, p.y), heightFraction(p.z, zMin, zMax));
        });
    }
    /// The box around a surface of revolution of radius at most r between zMin and zMax.
    static void boundsOfRevolution(double r, double zMin, double zMax, Vec3& lower, Vec3& upper) {
        float const radius = static_cast<float>(r);
        lower = Vec3(-radius, -radius, static_cast<float>(zMin));
        upper = Vec3(radius, radius, static_cast<float>(zMax));
    }

private:
    Mat4 m_objectToWorld;
    Mat4 m_worldToObject;
    glm::dmat4 m_worldToObjectExact;
    Mat3 m_normalToWorld;     ///< the inverse transpose of the linear part
    Mat3 m_absoluteLinear;    ///< |objectToWorld|, element by element, for error bounds
    float m_orientation;  ///< +1, or -1 under ReverseOrientation
    double m_phiMax;
};

}  // namespace bxdflab
