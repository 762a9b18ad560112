#include "LightSampling.h"

void sampleLights(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                  int numLightSamples, int numBxdfSamples, RtColorRGB const* throughput, RtColorRGB* radiance) {
    int const n = ctx.numPts;
    if (numLightSamples <= 0) return;
    RtPoint3 const* P;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    RixShadingContext::Allocator pool(&ctx);
    RtFloat2* xi = pool.AllocFor<RtFloat2>(n);
    RixLightSample* light = pool.AllocFor<RixLightSample>(n);
    RixBxdfScratch q(ctx);
    float const nL = static_cast<float>(numLightSamples), nB = static_cast<float>(numBxdfSamples);

    for (int l = 0; l < ictx.GetNumLights(); ++l) {
        for (int s = 0; s < numLightSamples; ++s) {
            // Every point picks a point on light l; the Bxdf evaluates all the directions at once.
            rng.DrawSamples2D(xi);
            for (int i = 0; i < n; ++i) {
                light[i] = ictx.SampleLight(l, P[i], xi[i]);
                // Light linking: a light the file turned off for this point's shape sends it nothing.
                if (!ictx.Illuminates(l, ctx, i)) light[i].radiance = RtColorRGB(0.0f);
                q.Ln[i] = light[i].wi;
            }
            q.evaluate(bxdf, rng, ictx);
            for (int i = 0; i < n; ++i) {
                if (!(light[i].pdf > 0.0f) || light[i].radiance.IsBlack()) continue;
                RtColorRGB W = q.W.SumAtPoint(i);  // f cos(theta_L), summed over the lobes
                if (W.IsBlack()) continue;
                if (!ictx.Unoccluded(ctx, i, light[i].wi, light[i].distance)) continue;  // the shadow ray
                // The power heuristic against the chance that a Bxdf sample finds the same point;
                // a delta light (a point) can never be found that way.
                float mis = light[i].delta ? 1.0f : RixPowerHeuristic(nL, light[i].pdf, nB, RixMax(0.0f, q.FPdf[i]));
                RtColorRGB contribution = W * light[i].radiance * (mis / (nL * light[i].pdf));
                addContribution(ictx, radiance[i], throughput[i] * contribution);
            }
        }
    }
}
