#include "LightSampling.h"

#include "Todo.h"

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
                // TODO (exercise 1a): this light sample's share of the estimate, times throughput[i]:
                //   the estimator of chapter 11 for one of nL samples, with density light[i].pdf,
                //   weighted by the power heuristic against the nB Bxdf samples the caller takes
                //   (whose density for this direction is q.FPdf[i]). A delta light (light[i].delta)
                //   cannot be found by a Bxdf sample. Add it with addContribution(ictx, radiance[i], ...).
                RIX_TODO(&ctx, "sampleLights (the light sample's contribution)");
                PIXAR_ARGUSED(nL);
                PIXAR_ARGUSED(nB);
                PIXAR_ARGUSED(throughput);
                PIXAR_ARGUSED(radiance);
            }
        }
    }
}
