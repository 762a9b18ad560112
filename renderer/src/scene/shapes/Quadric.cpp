#include "scene/shapes/Quadric.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

Quadric::Quadric(Mat4 const& objectToWorld, bool reverseOrientation, float thetaMaxDegrees)
    : m_objectToWorld(objectToWorld),
      m_worldToObject(glm::inverse(objectToWorld)),
      m_worldToObjectExact(glm::inverse(glm::dmat4(objectToWorld))),
      m_normalToWorld(glm::transpose(Mat3(m_worldToObject))),
      m_orientation(reverseOrientation ? -1.0f : 1.0f),
      m_phiMax(quadric::sweepRadians(thetaMaxDegrees)) {
    Mat3 linear(m_objectToWorld);
    m_absoluteLinear = Mat3(glm::abs(linear[0]), glm::abs(linear[1]), glm::abs(linear[2]));
}

double Quadric::azimuth(double x, double y) {
    double phi = std::atan2(y, x);
    return phi < 0.0 ? phi + quadric::kTwoPi : phi;
}

SurfaceBasics Quadric::basicsUnmoved(HitRecord const& hit) const {
    LocalSurface local = surfaceAtHit(hit);
    SurfaceBasics out;
    out.P = transformPoint(m_objectToWorld, local.P);
    out.Ng = m_orientation * safeNormalize(m_normalToWorld * local.N);
    out.N = out.Ng;
    // P is evaluated on the exact surface; its error is a few ulps of the
    // magnitudes involved in the transform. Bound it generously.
    Vec3 magnitude = m_absoluteLinear * glm::abs(local.P) + glm::abs(Vec3(m_objectToWorld[3]));
    out.pError = 4e-6f * magnitude + Vec3(1e-7f);
    return out;
}

SurfaceTangents Quadric::tangentsUnmoved(HitRecord const& hit) const {
    LocalSurface local = surfaceAtHit(hit);
    return {transformVector(m_objectToWorld, local.dPdu), transformVector(m_objectToWorld, local.dPdv)};
}

}  // namespace bxdflab
