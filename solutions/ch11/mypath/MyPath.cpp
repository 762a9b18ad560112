// mypath — a path tracer (chapter 11, exercise 2). At every surface a path
// reaches it adds what the surface emits, samples the lights (sampleLights,
// from exercise 1), and samples the Bxdf once: if that direction reaches a
// light, the light is added (MIS-weighted against the light samples);
// otherwise the path continues to the surface it hits, carrying
//   throughput *= W / FPdf.
// From the third surface on, Russian roulette ends a path with probability
// 1 - min(0.95, its largest throughput channel) and divides the survivors'
// throughput by the probability they survived, so the estimate stays unbiased.
//
// Parameters
//   int maxPathLength    [5]   surfaces a path may visit (1: direct lighting only)
//   int numLightSamples  [1]   light samples per light at every surface
// RIB
//   Integrator "mypath" "paths" "int maxPathLength" [5]
#include "../mydirect/LightSampling.h"

namespace {

class MyPath : public RixIntegrator {
public:
    MyPath(int maxPathLength, int numLightSamples) : m_maxPathLength(maxPathLength), m_numLightSamples(numLightSamples) {}

    void DescribeEffects(int numLights, RixEffects& effects) const override {
        effects.Simulate("camera rays");
        effects.Simulate("emission (EmitLocal) at every path vertex");
        if (numLights > 0) effects.Simulate("light sampling and shadow rays at every vertex, MIS with bxdf sampling");
        if (m_maxPathLength > 1)
            effects.Simulate("indirect rays, Russian roulette from the third vertex");
        else
            effects.Skip("indirect rays", "maxPathLength is 1");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        RtColorRGB* throughput = RixShadingContext::Allocator(&ctx).AllocFor<RtColorRGB>(ctx.numPts);
        for (int i = 0; i < ctx.numPts; ++i) throughput[i] = RtColorRGB(1.0f);
        shadeVertex(ctx, bxdf, rng, ictx, throughput, radiance, 1);
    }

private:
    /// One bounce for a batch of path vertices at depth `depth`: adds to
    /// radiance[i] the light this vertex and the rest of its path bring,
    /// times throughput[i], the path's weight from the camera to here.
    void shadeVertex(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                     RtColorRGB const* throughput, RtColorRGB* radiance, int depth) {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);

        // 1. Emission: emissive surfaces are not lights, so nothing else counts their light.
        RtColorRGB* emitted = pool.AllocFor<RtColorRGB>(n);
        if (bxdf.EmitLocal(emitted))
            for (int i = 0; i < n; ++i) addContribution(ictx, radiance[i], throughput[i] * emitted[i]);
        if (!bxdf.GetAllLobeTraits().HasAny()) return;

        // 2. Next-event estimation, weighted against the one Bxdf sample below.
        sampleLights(ctx, bxdf, rng, ictx, m_numLightSamples, 1, throughput, radiance);

        // 3. One Bxdf sample per point: it finds a light, or it continues the path.
        RixBxdfScratch q(ctx);
        q.generate(bxdf, rng, ictx);
        float const nL = static_cast<float>(ictx.GetNumLights() == 0 ? 0 : m_numLightSamples);
        int* from = pool.AllocFor<int>(n);                      // ray k leaves point from[k]
        RtVector3* direction = pool.AllocFor<RtVector3>(n);
        bool* continues = pool.AllocFor<bool>(n);
        RixRNG::SampleCtx* samples = pool.AllocFor<RixRNG::SampleCtx>(n);
        RtColorRGB* nextThroughput = pool.AllocFor<RtColorRGB>(n);
        int rays = 0;
        for (int i = 0; i < n; ++i) {
            if (!q.lobeSampled[i].GetValid()) continue;
            RtColorRGB W = q.W.SumAtPoint(i);
            if (W.IsBlack()) continue;
            RtColorRGB carried = throughput[i] * W / q.FPdf[i];
            bool alive = depth < m_maxPathLength;
            if (alive && depth >= 3) {
                // Russian roulette: weak paths end early, survivors carry more.
                float survive = RixMin(0.95f, carried.ChannelMax());
                alive = rng.DrawSample1D(i) < survive;
                if (alive) carried /= survive;
            }
            from[rays] = i;
            direction[rays] = Normalize(q.Ln[i]);
            continues[rays] = alive;
            samples[rays] = rng.sampleCtxArray[i];
            nextThroughput[rays] = carried;
            ++rays;
        }
        if (rays == 0) return;

        // 4. Trace: a ray that reaches a light adds it; one that reaches a surface is
        //    shaded there (batches of such points come back to shadeVertex, one level deeper).
        RixLightHit* lightHit = pool.AllocFor<RixLightHit>(rays);
        ictx.TraceIndirect(ctx, rays, from, direction, continues, samples, lightHit, [&](RixShadeBatch& batch) {
            int const m = batch.ctx.numPts;
            RixShadingContext::Allocator childPool(&batch.ctx);
            RtColorRGB* childThroughput = childPool.AllocFor<RtColorRGB>(m);
            RtColorRGB* childRadiance = childPool.AllocFor<RtColorRGB>(m);
            for (int j = 0; j < m; ++j) {
                childThroughput[j] = nextThroughput[batch.source[j]];
                childRadiance[j] = RtColorRGB(0.0f);
            }
            shadeVertex(batch.ctx, batch.bxdf, batch.rng, ictx, childThroughput, childRadiance, depth + 1);
            for (int j = 0; j < m; ++j) radiance[from[batch.source[j]]] += childRadiance[j];
        });
        for (int k = 0; k < rays; ++k) {
            if (!lightHit[k].hit) continue;
            int i = from[k];
            float mis = q.lobeSampled[i].GetDiscrete() ? 1.0f : RixPowerHeuristic(1.0f, q.FPdf[i], nL, lightHit[k].pdf);
            RtColorRGB W = q.W.SumAtPoint(i);
            addContribution(ictx, radiance[i], throughput[i] * W * lightHit[k].radiance * (mis / q.FPdf[i]));
        }
    }

    int m_maxPathLength;
    int m_numLightSamples;
};

}  // namespace

RIX_INTEGRATORCREATE {
    int maxPathLength = readInt(params, "maxPathLength", 5), lightSamples = readInt(params, "numLightSamples", 1);
    if (maxPathLength < 1 || lightSamples < 0) {
        messages->Error("maxPathLength must be >= 1 and numLightSamples >= 0");
        return nullptr;
    }
    return new MyPath(maxPathLength, lightSamples);
}

RIX_INTEGRATORDESTROY { delete integrator; }
