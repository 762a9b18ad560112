#include "integrate/IntegratorServices.h"

#include <cmath>

#include "accel/RayTracer.h"

namespace bxdflab {
namespace {

/// Shadow rays stop just short of the light, so a surface touching it does not count.
float shadowReach(float distance) { return std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f); }

}  // namespace

RixLightSample IntegratorServices::SampleLight(int light, RtPoint3 const& P, RtFloat2 const& xi) const {
    LightSample s = m_lights[static_cast<size_t>(light)]->sample(toVec3(P), Vec2(xi.x, xi.y));
    RixLightSample out;
    out.wi = toRt(s.wi);
    out.distance = s.distance;
    out.radiance = s.radiance;
    out.pdf = s.pdf;
    out.delta = s.delta;
    return out;
}

Vec3 IntegratorServices::origin(RixShadingContext const& ctx, int i, Vec3 const& dir) const {
    RtPoint3 const* P;
    RtNormal3 const* Ngn;
    RtFloat const* biasR;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
    ctx.GetBuiltinVar(RixShadingContext::k_biasR, &biasR);
    return offsetRayOrigin(toVec3(P[i]), biasR[i], toVec3(Ngn[i]), dir);
}

bool IntegratorServices::Unoccluded(RixShadingContext const& ctx, int i, RtVector3 const& dir, float distance) {
    Vec3 d = toVec3(dir);
    return !m_tracer.occluded(origin(ctx, i, d), d, 0.0f, shadowReach(distance), m_counts);
}

RixLightHit IntegratorServices::lightAlong(Vec3 const& from, Vec3 const& dir, float maxDistance) const {
    LightAlongRay seen = nearestLightAlong(m_lights, from, dir, maxDistance);
    // A light that sends nothing this way (the back of a rect light) is no hit for MIS.
    if (!seen.light || seen.radiance.IsBlack()) return {};
    return {true, seen.distance, seen.radiance, seen.pdf};
}

RixLightHit IntegratorServices::VisibleLight(RixShadingContext const& ctx, int i, RtVector3 const& dir) {
    Vec3 d = toVec3(dir), from = origin(ctx, i, d);
    RixLightHit light = lightAlong(from, d, kInfinity);
    if (light.hit && m_tracer.occluded(from, d, 0.0f, shadowReach(light.distance), m_counts)) light.hit = false;
    return light;
}

void IntegratorServices::TraceIndirect(RixShadingContext const& ctx, int count, int const* indices,
                                       RtVector3 const* dirs, bool const* shade, RixRNG::SampleCtx const* samples,
                                       RixLightHit* lightHits, std::function<void(RixShadeBatch&)> const& visit) {
    MemoryArena::Mark mark = m_arena.mark();
    HitRecord* hits = m_arena.allocArray<HitRecord>(static_cast<size_t>(std::max(1, count)));
    for (int k = 0; k < count; ++k) {
        Vec3 d = glm::normalize(toVec3(dirs[k]));
        Vec3 from = origin(ctx, indices[k], d);
        HitRecord hit = m_tracer.intersect(from, d, 0.0f, kInfinity, RayKind::Indirect, m_counts);
        lightHits[k] = lightAlong(from, d, hit.hit() ? hit.t : kInfinity);
        // Rays that reach a light first, or that the integrator does not want shaded, end here.
        if (lightHits[k].hit || !shade[k]) hit.forget();
        hits[k] = hit;
    }
    m_shader.shade(hits, samples, count, m_arena, [&](ShadeGroup& group) {
        RixShadeBatch batch{group.ctx, group.bxdf, group.rng, group.source};
        visit(batch);
    });
    m_arena.release(mark);
}

}  // namespace bxdflab
