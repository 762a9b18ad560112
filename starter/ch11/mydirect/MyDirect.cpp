// mydirect — direct lighting with multiple importance sampling (chapter 11,
// exercise 1). For each shade point, the light leaving toward the viewer is
//   Lo(V) = Le(V) + integral over L of f(V, L) Li(L) cos(theta_L) dL,
// estimated from light samples (sampleLights, LightSampling.cpp) and Bxdf
// samples (below), each weighted by the power heuristic so that the two
// together count every direction once.
//
// Parameters
//   int numLightSamples [1]   samples per light per camera sample
//   int numBxdfSamples  [1]   Bxdf samples per camera sample
// RIB
//   Integrator "mydirect" "direct" "int numLightSamples" [1] "int numBxdfSamples" [1]
#include "LightSampling.h"
#include "Todo.h"

namespace {

class MyDirect : public RixIntegrator {
public:
    MyDirect(int numLightSamples, int numBxdfSamples)
        : m_numLightSamples(numLightSamples), m_numBxdfSamples(numBxdfSamples) {}

    void DescribeEffects(int numLights, RixEffects& effects) const override {
        effects.Simulate("camera rays");
        effects.Simulate("emission (EmitLocal)");
        if (numLights == 0) {
            effects.Skip("light and bxdf sampling", "the scene has no lights");
            return;
        }
        effects.Simulate("light sampling, shadow rays and bxdf sampling, combined by MIS");
        effects.Skip("indirect rays", "direct lighting only");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);

        // 1. What the surface emits itself.
        RtColorRGB* emitted = pool.AllocFor<RtColorRGB>(n);
        if (bxdf.EmitLocal(emitted))
            for (int i = 0; i < n; ++i) addContribution(ictx, radiance[i], emitted[i]);
        if (!bxdf.GetAllLobeTraits().HasAny() || ictx.GetNumLights() == 0) return;

        // 2. Light sampling (exercise 1a).
        RtColorRGB* one = pool.AllocFor<RtColorRGB>(n);
        for (int i = 0; i < n; ++i) one[i] = RtColorRGB(1.0f);
        sampleLights(ctx, bxdf, rng, ictx, m_numLightSamples, m_numBxdfSamples, one, radiance);

        // 3. Bxdf sampling (exercise 1b): directions the Bxdf picks, and the light they reach.
        RixBxdfScratch q(ctx);
        float const nL = static_cast<float>(m_numLightSamples), nB = static_cast<float>(m_numBxdfSamples);
        for (int s = 0; s < m_numBxdfSamples; ++s) {
            q.generate(bxdf, rng, ictx);
            for (int i = 0; i < n; ++i) {
                if (!q.lobeSampled[i].GetValid()) continue;
                RtColorRGB W = q.W.SumAtPoint(i);
                if (W.IsBlack()) continue;
                RixLightHit hit = ictx.VisibleLight(ctx, i, Normalize(q.Ln[i]));  // a shadow ray toward a light, if any
                if (!hit.hit) continue;
                // TODO (exercise 1b): this Bxdf sample's share: one of nB samples with density q.FPdf[i],
                //   reaching hit.radiance, weighted against light sampling (hit.pdf is the density the
                //   light's own sampling gives this direction). A discrete (mirror) lobe
                //   (q.lobeSampled[i].GetDiscrete()) has no density a light sample could match.
                RIX_TODO(&ctx, "MyDirect::Integrate (the Bxdf sample's contribution)");
                PIXAR_ARGUSED(nL);
                PIXAR_ARGUSED(nB);
            }
        }
    }

private:
    int m_numLightSamples;
    int m_numBxdfSamples;
};

}  // namespace

RIX_INTEGRATORCREATE {
    int lightSamples = readInt(params, "numLightSamples", 1), bxdfSamples = readInt(params, "numBxdfSamples", 1);
    if (lightSamples < 0 || bxdfSamples < 0 || lightSamples + bxdfSamples == 0) {
        messages->Error("numLightSamples and numBxdfSamples must be >= 0, and not both 0");
        return nullptr;
    }
    return new MyDirect(lightSamples, bxdfSamples);
}

RIX_INTEGRATORDESTROY { delete integrator; }
