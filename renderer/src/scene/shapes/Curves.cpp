#include "scene/shapes/Curves.h"

#include <cmath>

namespace bxdflab {
namespace {

/// P and its error bound where a ray met a surface that has no parameterisation of its own to evaluate.
void pointOnRay(HitRecord const& hit, SurfaceBasics& out) {
    out.P = hit.org + hit.t * hit.dir;
    out.pError = 3e-5f * (glm::abs(hit.org) + glm::abs(hit.t * hit.dir)) + Vec3(1e-7f);
    Vec3 n = safeNormalize(hit.Ng);
    out.Ng = out.N = n == Vec3(0.0f) ? -hit.dir : n;
}

}  // namespace

Curves::Curves(CurveData data, PrimvarSet curvePrimvars) : m_data(std::move(data)) {
    primvars = std::move(curvePrimvars);
    takeSTFromPrimvars();
}

SurfaceBasics Curves::basicsUnmoved(HitRecord const& hit) const {
    SurfaceBasics out;
    pointOnRay(hit, out);
    // Embree's curve intersection is approximate near the surface: keep new
    // rays a small fraction of the radius away, or they can hit the same tube.
    float P[4];
    m_evaluator->evaluate(hit.primID, hit.u, hit.v, 0.0f, P, nullptr, nullptr, 4);
    out.pError = glm::max(out.pError, Vec3(0.02f * std::abs(P[3])));
    return out;  // (u along the segment: the hit's own parameters)
}

SurfaceTangents Curves::tangentsUnmoved(HitRecord const& hit) const {
    float P[4], dPdu[4];
    m_evaluator->evaluate(hit.primID, hit.u, hit.v, 0.0f, P, dPdu, nullptr, 4);
    Vec3 along(dPdu[0], dPdu[1], dPdu[2]);
    Vec3 N = safeNormalize(hit.Ng);
    return {along, glm::cross(N, along)};
}

SurfaceBasics Points::basicsUnmoved(HitRecord const& hit) const {
    SurfaceBasics out;
    pointOnRay(hit, out);
    if (!m_normals.empty()) {  // a disk: flat, facing its normal
        out.Ng = out.N = m_normals[hit.primID];
        return out;
    }
    // The exact sphere normal, from the centre (Embree's is the same up to rounding).
    Vec4 const& s = m_particles[hit.primID];
    Vec3 n = safeNormalize(out.P - Vec3(s));
    if (n != Vec3(0.0f)) out.Ng = out.N = n;
    return out;
}

void Points::primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const {
    size_t const c = static_cast<size_t>(var.components);
    size_t const first = var.detail == Primvar::Detail::Uniform && var.values.size() >= (hit.primID + 1) * c ? hit.primID * c : 0;
    for (size_t k = 0; k < c; ++k) out[k] = var.values[first + k];
}

SurfaceTangents Points::tangentsUnmoved(HitRecord const&) const {
    return {};  // a particle has no parameterisation: plugins build a frame from N alone
}

}  // namespace bxdflab
