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
#include "integrate/DirectLighting.h"

#include "integrate/BxdfScratch.h"

#include <cmath>

namespace bxdflab {
namespace {

bool isFinite(RtColorRGB const& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

}  // namespace

void accumulate(IntegratorServices& services, RtColorRGB& radiance, RtColorRGB const& contribution) {
    if (isFinite(contribution))
        radiance += contribution;
    else
        services.countNonFinite();
}

DirectLighting::DirectLighting(int numLightSamples, int numBxdfSamples, std::unique_ptr<Light> ownLight)
    : m_numLightSamples(numLightSamples), m_numBxdfSamples(numBxdfSamples), m_ownLight(std::move(ownLight)) {}

std::vector<Light const*> DirectLighting::extraLights() const {
    if (m_ownLight) return {m_ownLight.get()};
    return {};
}

void DirectLighting::describeEffects(Scene const& scene, EffectReport& report) const {
    report.simulate("camera rays");
    report.simulate("emission (EmitLocal)");
    bool lit = m_ownLight || !scene.lights.empty();
    if (m_ownLight) report.simulate("headlight at the camera");
    if (!lit) {
        report.skip("light sampling", "the scene has no lights");
        report.skip("shadow rays", "the scene has no lights");
        report.skip("bxdf sampling", "there is no light for a sampled direction to reach");
    } else {
        if (m_numLightSamples > 0)
            report.simulate("light sampling (" + std::to_string(m_numLightSamples) + " per light per camera sample)");
        else
            report.skip("light sampling", "numLightSamples is 0");
        report.simulate("shadow rays");
        if (m_numBxdfSamples > 0 && !m_ownLight)
            report.simulate("bxdf sampling (" + std::to_string(m_numBxdfSamples) + " per camera sample, MIS)");
        else
            report.skip("bxdf sampling", m_ownLight ? "the headlight is a point light no sample can hit" : "numBxdfSamples is 0");
    }
    report.skip("indirect rays", name() + " computes direct lighting only");
}

void addLightSamples(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                     int numLightSamples, int numBxdfSamples, RtColorRGB const* throughput, RtColorRGB* radiance) {
    int const n = ctx.numPts;
    std::vector<Light const*> const& lights = services.lights();
    if (numLightSamples <= 0 || lights.empty()) return;
    RtPoint3 const* P;
    RtNormal3 const* Ngn;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
    Vec3 const* pError = ctx.pError();
    RixShadingContext::Allocator pool(&ctx);
    RtFloat2* xi = pool.AllocFor<RtFloat2>(n);
    LightSample* lightSample = pool.AllocFor<LightSample>(n);
    BxdfScratch q(ctx);
    float const nL = static_cast<float>(numLightSamples), nB = static_cast<float>(numBxdfSamples);

    // For each light, pick points on it and ask the Bxdf how much of that
    // light it reflects toward the viewer.
    for (Light const* light : lights) {
        for (int s = 0; s < numLightSamples; ++s) {
            rng.DrawSamples2D(xi);
            for (int i = 0; i < n; ++i) {
                lightSample[i] = light->sample(toVec3(P[i]), Vec2(xi[i].x, xi[i].y));
                q.Ln[i] = toRt(lightSample[i].wi);
            }
            q.evaluate(bxdf, rng);
            for (int i = 0; i < n; ++i) {
                LightSample const& ls = lightSample[i];
                if (!(ls.pdf > 0.0f) || ls.radiance.IsBlack()) continue;
                RtColorRGB f = q.W.SumAtPoint(i);
                if (f.IsBlack()) continue;
                if (!services.unoccluded(toVec3(P[i]), pError[i], toVec3(Ngn[i]), ls.wi, ls.distance)) continue;
                // Weighted against the chance that Bxdf sampling finds the same light (MIS).
                float weight = ls.delta ? 1.0f : powerHeuristic(nL, ls.pdf, nB, std::max(0.0f, q.FPdf[i]));
                RtColorRGB contribution = f * ls.radiance * (weight / (nL * ls.pdf));
                if (throughput) contribution *= throughput[i];
                accumulate(services, radiance[i], contribution);
            }
        }
    }
}

void DirectLighting::integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng,
                               IntegratorServices& services, RtColorRGB* radiance) {
    int const n = ctx.numPts;

    // 1. Light the surface emits itself (e.g. the emissive plugin).
    RtColorRGB* emitted = RixShadingContext::Allocator(&ctx).AllocFor<RtColorRGB>(n);
    if (bxdf.EmitLocal(emitted))
        for (int i = 0; i < n; ++i) radiance[i] += emitted[i];

    // 2. A Bxdf with no lobes (purely emissive) reflects nothing: no rays at all.
    if (!bxdf.GetAllLobeTraits().HasAny() || services.lights().empty()) return;

    // 3. Light sampling (next-event estimation).
    int const bxdfSamples = m_ownLight ? 0 : m_numBxdfSamples;
    addLightSamples(ctx, bxdf, rng, services, m_numLightSamples, bxdfSamples, nullptr, radiance);

    // 4. Bxdf sampling: let the Bxdf choose directions, and see which reach a light.
    RtPoint3 const* P;
    RtNormal3 const* Ngn;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
    Vec3 const* pError = ctx.pError();
    BxdfScratch q(ctx);
    float const nL = static_cast<float>(m_numLightSamples), nB = static_cast<float>(bxdfSamples);
    for (int s = 0; s < bxdfSamples; ++s) {
        q.generate(bxdf, rng);
        for (int i = 0; i < n; ++i) {
            if (!q.lobeSampled[i].GetValid() || !(q.FPdf[i] > 0.0f)) continue;
            Vec3 dir = toVec3(q.Ln[i]);
            if (!isFinite(dir) || glm::length(dir) == 0.0f) {
                services.countNonFinite();
                continue;
            }
            RtColorRGB f = q.W.SumAtPoint(i);
            if (f.IsBlack()) continue;
            LightHit hit = services.visibleLight(toVec3(P[i]), pError[i], toVec3(Ngn[i]), glm::normalize(dir));
            if (!hit.light) continue;
            float weight = q.lobeSampled[i].GetDiscrete() ? 1.0f : powerHeuristic(nB, q.FPdf[i], nL, hit.pdf);
            accumulate(services, radiance[i], f * hit.radiance * (weight / (nB * q.FPdf[i])));
        }
    }
}

}  // namespace bxdflab
