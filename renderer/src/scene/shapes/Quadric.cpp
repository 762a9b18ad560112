#include "scene/shapes/Quadric.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

Quadric::Quadric(Mat4 const& objectToWorld, bool reverseOrientation, float thetaMaxDegrees)
    : m_objectToWorld(objectToWorld),
      m_worldToObject(glm::inverse(objectToWorld)),
      m_orientation(reverseOrientation ? -1.0f : 1.0f),
      m_phiMax(quadric::sweepRadians(thetaMaxDegrees)) {}

double Quadric::azimuth(double x, double y) {
    double phi = std::atan2(y, x);
    return phi < 0.0 ? phi + quadric::kTwoPi : phi;
}

SurfaceBasics Quadric::basics(HitRecord const& hit) const {
    LocalSurface local = surfaceLocal(hit.u, hit.v);
    SurfaceBasics out;
    out.P = transformPoint(m_objectToWorld, local.P);
    out.Ng = m_orientation * safeNormalize(transformNormal(m_worldToObject, local.N));
    out.N = out.Ng;
    // P is evaluated from (u, v) on the exact surface; its error is a few ulps
    // of the magnitudes involved in the transform. Bound it generously.
    Mat3 linear(m_objectToWorld);
    Mat3 absolute(glm::abs(linear[0]), glm::abs(linear[1]), glm::abs(linear[2]));
    Vec3 magnitude = absolute * glm::abs(local.P) + glm::abs(Vec3(m_objectToWorld[3]));
    out.pError = 4e-6f * magnitude + Vec3(1e-7f);
    out.u = hit.u;
    out.v = hit.v;
    out.s = hit.u;
    out.t = hit.v;
    return out;
}

SurfaceTangents Quadric::tangents(HitRecord const& hit) const {
    LocalSurface local = surfaceLocal(hit.u, hit.v);
    return {transformVector(m_objectToWorld, local.dPdu), transformVector(m_objectToWorld, local.dPdv)};
}

}  // namespace bxdflab
