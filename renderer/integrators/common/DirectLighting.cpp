// How PxrDirectLighting shades a batch of points (the course's reference integrator).
//
// The reflected radiance toward the viewer is
//     Lo(V) = Le(V) + integral over directions L of  f(V, L) Li(L) |cos theta_L| dL.
// A Bxdf returns W = f |cos theta_L| (rix-api convention), so one Monte Carlo
// sample of the integral is   W * Li / pdf.
//
// Two ways to pick directions:
//   light sampling  pick a point on a light (pdf from the light); great for
//                   small lights and rough surfaces;
//   Bxdf sampling   let the Bxdf pick (GenerateSample; pdf = FPdf); great for
//                   shiny surfaces and big lights.
// Each alone fails somewhere; multiple importance sampling (Veach 1997) keeps
// both and weights each sample by the power heuristic, so the combination is
// never much worse than the better of the two.
#include "DirectLighting.h"

#include <cmath>
#include <string>

#include "RixBxdfScratch.h"

namespace bxdflab {
namespace {

bool isFinite(RtColorRGB const& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }
bool isFinite(RtVector3 const& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void accumulate(RixIntegratorContext& ictx, RtColorRGB& radiance, RtColorRGB const& contribution) {
    if (isFinite(contribution))
        radiance += contribution;
    else
        ictx.CountNonFinite();
}

bool addEmission(RixShadingContext const& ctx, RixBxdf& bxdf, RixIntegratorContext& ictx,
                 RtColorRGB const* throughput, RtColorRGB* radiance) {
    int const n = ctx.numPts;
    RtColorRGB* emitted = RixShadingContext::Allocator(&ctx).AllocFor<RtColorRGB>(n);
    if (bxdf.EmitLocal(emitted))
        for (int i = 0; i < n; ++i) accumulate(ictx, radiance[i], throughput[i] * emitted[i]);
    return bxdf.GetAllLobeTraits().HasAny();
}

void sampleLight(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx, int light,
                 RtPoint3 const* P, RtFloat2* xi, RixLightSample* sample, RixBxdfScratch& q, ShadowRays& shadow) {
    int const n = ctx.numPts;
    rng.DrawSamples2D(xi);
    for (int i = 0; i < n; ++i) {
        sample[i] = ictx.SampleLight(light, P[i], xi[i]);
        if (!ictx.Illuminates(light, ctx, i)) sample[i].radiance = RtColorRGB(0.0f);  // light linking
        q.Ln[i] = sample[i].wi;
    }
    q.evaluate(bxdf, rng, ictx);
    shadow.count = 0;
    for (int i = 0; i < n; ++i) {
        RixLightSample const& ls = sample[i];
        if (!(ls.pdf > 0.0f) || ls.radiance.IsBlack()) continue;
        LobeWeight const f = LobeWeight::at(q.W, i);
        if (f.litBy(ls.diffuse, ls.specular).IsBlack()) continue;
        shadow.add(i, ls.wi, ls.shadows ? ls.distance : 0.0f, f);
    }
}

void addLightSamples(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                     int numLightSamples, int numBxdfSamples, RtColorRGB const* throughput, RtColorRGB* radiance) {
    int const n = ctx.numPts;
    if (numLightSamples <= 0 || ictx.GetNumLights() == 0) return;
    RtPoint3 const* P;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    RixShadingContext::Allocator pool(&ctx);
    RtFloat2* xi = pool.AllocFor<RtFloat2>(n);
    RixLightSample* lightSample = pool.AllocFor<RixLightSample>(n);
    ShadowRays shadow(pool, n);
    RixBxdfScratch q(ctx);
    float const nL = static_cast<float>(numLightSamples), nB = static_cast<float>(numBxdfSamples);

    // For each light, pick points on it and ask the Bxdf how much of that
    // light it reflects toward the viewer.
    for (int light = 0; light < ictx.GetNumLights(); ++light) {
        for (int s = 0; s < numLightSamples; ++s) {
            sampleLight(ctx, bxdf, rng, ictx, light, P, xi, lightSample, q, shadow);
            // The shadow rays of all points at once.
            ictx.Unoccluded(ctx, shadow.count, shadow.point, shadow.dir, shadow.distance, shadow.clear);
            for (int k = 0; k < shadow.count; ++k) {
                if (!shadow.clear[k]) continue;
                int const i = shadow.point[k];
                RixLightSample const& ls = lightSample[i];
                // Weighted against the chance that Bxdf sampling finds the same light (MIS).
                float weight = ls.delta ? 1.0f : RixPowerHeuristic(nL, ls.pdf, nB, RixMax(0.0f, q.FPdf[i]));
                RtColorRGB contribution =
                    shadow.weight[k].litBy(ls.diffuse, ls.specular) * ls.radiance * (weight / (nL * ls.pdf));
                if (throughput) contribution *= throughput[i];
                accumulate(ictx, radiance[i], contribution);
            }
        }
    }
}

void addLightsFound(RixShadingContext const& ctx, RixIntegratorContext& ictx, RixBxdfScratch const& q,
                    ShadowRays const& rays, RixLightHit* hit, int numLightSamples, int numBxdfSamples,
                    RtColorRGB* radiance) {
    float const nL = static_cast<float>(numLightSamples), nB = static_cast<float>(numBxdfSamples);
    // A shadow ray toward each light a sampled direction meets, all traced at once.
    ictx.VisibleLights(ctx, rays.count, rays.point, rays.dir, hit);
    for (int k = 0; k < rays.count; ++k) {
        if (!hit[k].hit) continue;
        int const i = rays.point[k];
        float weight = q.lobeSampled[i].GetDiscrete() ? 1.0f : RixPowerHeuristic(nB, q.FPdf[i], nL, hit[k].pdf);
        RtColorRGB const f = rays.weight[k].litBy(hit[k].diffuse, hit[k].specular);
        accumulate(ictx, radiance[i], f * hit[k].radiance * (weight / (nB * q.FPdf[i])));
    }
}

void DirectLighting::DescribeEffects(int numLights, RixEffects& effects) const {
    effects.Simulate("camera rays");
    effects.Simulate("emission (EmitLocal)");
    if (m_headlight) effects.Simulate("headlight at the camera");
    if (numLights == 0) {
        effects.Skip("light sampling", "the scene has no lights");
        effects.Skip("shadow rays", "the scene has no lights");
        effects.Skip("bxdf sampling", "there is no light for a sampled direction to reach");
    } else {
        if (m_numLightSamples > 0)
            effects.Simulate(("light sampling (" + std::to_string(m_numLightSamples) + " per light per camera sample)").c_str());
        else
            effects.Skip("light sampling", "numLightSamples is 0");
        effects.Simulate("shadow rays");
        if (m_numBxdfSamples > 0)
            effects.Simulate(("bxdf sampling (" + std::to_string(m_numBxdfSamples) + " per camera sample, MIS)").c_str());
        else
            effects.Skip("bxdf sampling", m_headlight ? "the headlight is a point light no sample can hit"
                                                      : "numBxdfSamples is 0");
    }
    effects.Skip("indirect rays", "direct lighting only");
}

void DirectLighting::Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                               RtColorRGB* radiance) {
    int const n = ctx.numPts;

    // 1. Light the surface emits itself (e.g. the emissive plugin).
    RtColorRGB* emitted = RixShadingContext::Allocator(&ctx).AllocFor<RtColorRGB>(n);
    if (bxdf.EmitLocal(emitted))
        for (int i = 0; i < n; ++i) radiance[i] += emitted[i];

    // 2. A Bxdf with no lobes (purely emissive) reflects nothing: no rays at all.
    if (!bxdf.GetAllLobeTraits().HasAny() || ictx.GetNumLights() == 0) return;

    // 3. Light sampling (next-event estimation).
    addLightSamples(ctx, bxdf, rng, ictx, m_numLightSamples, m_numBxdfSamples, nullptr, radiance);

    // 4. Bxdf sampling: let the Bxdf choose directions, and see which reach a light.
    RixBxdfScratch q(ctx);
    RixShadingContext::Allocator pool(&ctx);
    ShadowRays shadow(pool, n);
    RixLightHit* hit = pool.AllocFor<RixLightHit>(n);
    for (int s = 0; s < m_numBxdfSamples; ++s) {
        q.generate(bxdf, rng, ictx);
        shadow.count = 0;
        for (int i = 0; i < n; ++i) {
            if (!q.lobeSampled[i].GetValid() || !(q.FPdf[i] > 0.0f)) continue;
            if (!isFinite(q.Ln[i]) || q.Ln[i].IsZero()) {
                ictx.CountNonFinite();
                continue;
            }
            LobeWeight const f = LobeWeight::at(q.W, i);
            if (f.all.IsBlack()) continue;
            shadow.add(i, Normalize(q.Ln[i]), 0.0f, f);  // no distance yet: the light is found along the ray
        }
        addLightsFound(ctx, ictx, q, shadow, hit, m_numLightSamples, m_numBxdfSamples, radiance);
    }
}

}  // namespace bxdflab
