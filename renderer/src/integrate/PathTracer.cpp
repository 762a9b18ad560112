#include "integrate/PathTracer.h"

#include <cmath>

#include "integrate/BxdfScratch.h"
#include "integrate/DirectLighting.h"

namespace bxdflab {

void PathTracer::describeEffects(Scene const& scene, EffectReport& report) const {
    report.simulate("camera rays");
    report.simulate("emission (EmitLocal) at every path vertex");
    if (scene.lights.empty()) {
        report.skip("light sampling and shadow rays", "the scene has no lights");
    } else if (m_numLightSamples > 0) {
        report.simulate("light sampling (" + std::to_string(m_numLightSamples) + " per light per vertex)");
        report.simulate("shadow rays");
    } else {
        report.skip("light sampling", "numLightSamples is 0");
    }
    report.simulate("bxdf sampling (" + std::to_string(m_numBxdfSamples) + " per vertex, MIS)");
    if (m_maxPathLength > 1) {
        report.simulate("indirect rays (paths of up to " + std::to_string(m_maxPathLength) + " vertices)");
        report.simulate("Russian roulette from the fourth vertex");
    } else {
        report.skip("indirect rays", "maxPathLength is 1");
    }
    if (m_allowCaustics)
        report.simulate("caustics");
    else
        report.skip("caustics", "allowCaustics is 0");
}

void PathTracer::integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                           RtColorRGB* radiance) {
    int const n = ctx.numPts;
    RixShadingContext::Allocator pool(&ctx);
    RtColorRGB* throughput = pool.AllocFor<RtColorRGB>(n);
    bool* diffusePath = pool.AllocFor<bool>(n);
    for (int i = 0; i < n; ++i) {
        throughput[i] = RtColorRGB(1.0f);
        diffusePath[i] = false;
    }
    vertex(ctx, bxdf, rng, services, throughput, diffusePath, radiance, 1);
}

void PathTracer::vertex(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                        RtColorRGB const* throughput, bool const* diffusePath, RtColorRGB* radiance, int depth) {
    int const n = ctx.numPts;
    RixShadingContext::Allocator pool(&ctx);

    // 1. Emission. Emissive surfaces are not sampled as lights, so a path
    //    that reaches one simply adds what it emits.
    RtColorRGB* emitted = pool.AllocFor<RtColorRGB>(n);
    if (bxdf.EmitLocal(emitted))
        for (int i = 0; i < n; ++i) accumulate(services, radiance[i], throughput[i] * emitted[i]);
    if (!bxdf.GetAllLobeTraits().HasAny()) return;

    // 2. Next-event estimation.
    addLightSamples(ctx, bxdf, rng, services, m_numLightSamples, m_numBxdfSamples, throughput, radiance);

    // 3. Bxdf samples: light they reach directly, and where the path goes next.
    RtPoint3 const* P;
    RtNormal3 const* Ngn;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
    Vec3 const* pError = ctx.pError();
    BxdfScratch q(ctx);
    float const nL = static_cast<float>(services.lights().empty() ? 0 : m_numLightSamples);
    float const nB = static_cast<float>(m_numBxdfSamples);
    bool const continues = depth < m_maxPathLength;

    // The paths that go on, gathered for the next batch.
    HitRecord* nextHits = pool.AllocFor<HitRecord>(n);
    RixRNG::SampleCtx* nextSamples = pool.AllocFor<RixRNG::SampleCtx>(n);
    RtColorRGB* nextThroughput = pool.AllocFor<RtColorRGB>(n);
    bool* nextDiffuse = pool.AllocFor<bool>(n);
    int* parent = pool.AllocFor<int>(n);
    int numNext = 0;

    for (int s = 0; s < m_numBxdfSamples; ++s) {
        q.generate(bxdf, rng);
        for (int i = 0; i < n; ++i) {
            if (!q.lobeSampled[i].GetValid() || !(q.FPdf[i] > 0.0f)) continue;
            Vec3 dir = toVec3(q.Ln[i]);
            if (!isFinite(dir) || glm::length(dir) == 0.0f) {
                services.countNonFinite();
                continue;
            }
            dir = glm::normalize(dir);
            RtColorRGB f = q.W.SumAtPoint(i);
            if (f.IsBlack()) continue;
            bool specular = q.lobeSampled[i].GetSpecular();
            if (!m_allowCaustics && diffusePath[i] && specular) continue;  // a caustic path: dropped

            Vec3 Ng = toVec3(Ngn[i]);
            if (!continues || s != 0) {
                // This sample only looks for light: a shadow ray to the light it points at.
                LightHit light = services.visibleLight(toVec3(P[i]), pError[i], Ng, dir);
                if (!light.light) continue;
                float weight = q.lobeSampled[i].GetDiscrete() ? 1.0f : powerHeuristic(nB, q.FPdf[i], nL, light.pdf);
                accumulate(services, radiance[i], throughput[i] * f * light.radiance * (weight / (nB * q.FPdf[i])));
                continue;
            }
            HitRecord hit = services.traceIndirect(toVec3(P[i]), pError[i], Ng, dir);
            float surfaceDistance = hit.hit() ? hit.t : kInfinity;
            LightHit light = services.lightAlong(offsetRayOrigin(toVec3(P[i]), pError[i], Ng, dir), dir, surfaceDistance);
            if (light.light) {
                float weight = q.lobeSampled[i].GetDiscrete() ? 1.0f : powerHeuristic(nB, q.FPdf[i], nL, light.pdf);
                accumulate(services, radiance[i], throughput[i] * f * light.radiance * (weight / (nB * q.FPdf[i])));
                continue;  // lights do not reflect
            }
            if (!hit.hit()) continue;

            RtColorRGB next = throughput[i] * f / q.FPdf[i];
            if (depth >= 3) {
                // Russian roulette: end weak paths early, boost the survivors.
                float survive = std::fmin(0.95f, next.ChannelMax());
                if (!(rng.DrawSample1D(i) < survive)) continue;
                next /= survive;
            }
            if (!std::isfinite(next.r) || !std::isfinite(next.g) || !std::isfinite(next.b)) {
                services.countNonFinite();
                continue;
            }
            nextHits[numNext] = hit;
            nextSamples[numNext] = rng.sampleCtxArray[i];
            nextThroughput[numNext] = next;
            nextDiffuse[numNext] = diffusePath[i] || q.lobeSampled[i].GetDiffuse();
            parent[numNext] = i;
            ++numNext;
        }
    }
    if (numNext == 0) return;

    // 4. Shade where the continuing paths landed, batch by batch.
    services.shade(nextHits, nextSamples, numNext, [&](ShadeGroup& group) {
        int m = group.ctx.numPts;
        RixShadingContext::Allocator childPool(&group.ctx);
        RtColorRGB* childThroughput = childPool.AllocFor<RtColorRGB>(m);
        bool* childDiffuse = childPool.AllocFor<bool>(m);
        RtColorRGB* childRadiance = childPool.AllocFor<RtColorRGB>(m);
        for (int j = 0; j < m; ++j) {
            childThroughput[j] = nextThroughput[group.source[j]];
            childDiffuse[j] = nextDiffuse[group.source[j]];
            childRadiance[j] = RtColorRGB(0.0f);
        }
        vertex(group.ctx, group.bxdf, group.rng, services, childThroughput, childDiffuse, childRadiance, depth + 1);
        for (int j = 0; j < m; ++j) radiance[parent[group.source[j]]] += childRadiance[j];
    });
}

}  // namespace bxdflab
