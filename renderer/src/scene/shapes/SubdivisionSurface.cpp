#include "scene/shapes/SubdivisionSurface.h"

namespace bxdflab {
SubdivisionSurface::SubdivisionSurface(SubdivisionData data, bool flipNormals)
    : m_data(std::move(data)), m_orientation(flipNormals ? -1.0f : 1.0f) {}

SurfaceBasics SubdivisionSurface::basics(HitRecord const& hit) const {
    SurfaceTangents t = tangents(hit);
    SurfaceBasics out;
    // The hit is on Embree's tessellation: P where the ray met it keeps
    // secondary rays off that same surface.
    out.P = hit.org + hit.t * hit.dir;
    out.pError = 3e-5f * (glm::abs(hit.org) + glm::abs(hit.t * hit.dir)) + Vec3(1e-7f);
    Vec3 limitNormal = safeNormalize(glm::cross(t.dPdu, t.dPdv));
    Vec3 facet = safeNormalize(hit.Ng);
    if (facet == Vec3(0.0f)) facet = limitNormal;
    out.Ng = m_orientation * facet;
    out.N = limitNormal == Vec3(0.0f) ? out.Ng : m_orientation * limitNormal;
    if (glm::dot(out.Ng, out.N) < 0.0f) out.Ng = -out.Ng;
    return out;
}

SurfaceTangents SubdivisionSurface::tangents(HitRecord const& hit) const {
    float P[3], dPdu[3], dPdv[3];
    m_evaluator->evaluate(hit.primID, hit.u, hit.v, P, dPdu, dPdv, 3);
    return {Vec3(dPdu[0], dPdu[1], dPdu[2]), Vec3(dPdv[0], dPdv[1], dPdv[2])};
}

}  // namespace bxdflab
