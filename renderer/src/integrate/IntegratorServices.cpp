#include "integrate/Integrator.h"

namespace bxdflab {

bool IntegratorServices::unoccluded(Vec3 const& P, Vec3 const& pError, Vec3 const& Ng, Vec3 const& wi, float distance) {
    Vec3 origin = offsetRayOrigin(P, pError, Ng, wi);
    // Stop just short of the light so a surface touching it does not count.
    float tfar = std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f);
    return !m_tracer.occluded(origin, wi, 0.0f, tfar, m_counts);
}

LightHit IntegratorServices::lightAlong(Vec3 const& origin, Vec3 const& dir, float maxDistance) const {
    LightHit nearest;
    for (Light const* light : m_lights) {
        if (light->isDelta()) continue;
        LightHit candidate;
        if (light->intersect(origin, dir, candidate.distance, candidate.radiance, candidate.pdf) &&
            (!nearest.light || candidate.distance < nearest.distance) &&
            (candidate.distance < maxDistance || (std::isinf(maxDistance) && light->isInfinite()))) {
            candidate.light = light;
            nearest = candidate;
        }
    }
    return nearest;
}

HitRecord IntegratorServices::traceIndirect(Vec3 const& P, Vec3 const& pError, Vec3 const& Ng, Vec3 const& dir) {
    return m_tracer.intersect(offsetRayOrigin(P, pError, Ng, dir), dir, 0.0f, kInfinity, RayKind::Indirect, m_counts);
}

LightHit IntegratorServices::visibleLight(Vec3 const& P, Vec3 const& pError, Vec3 const& Ng, Vec3 const& dir) {
    Vec3 origin = offsetRayOrigin(P, pError, Ng, dir);
    LightHit nearest = lightAlong(origin, dir, kInfinity);
    if (!nearest.light || nearest.radiance.IsBlack()) return LightHit{};
    float tfar = std::isinf(nearest.distance) ? kInfinity : nearest.distance * (1.0f - 1e-4f);
    if (m_tracer.occluded(origin, dir, 0.0f, tfar, m_counts)) return LightHit{};
    return nearest;
}

}  // namespace bxdflab
