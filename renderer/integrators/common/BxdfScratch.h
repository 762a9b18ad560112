// The per-point arrays an integrator passes to a Bxdf's GenerateSample and
// EvaluateSample, allocated from the batch's memory pool.
#pragma once

#include "RixBxdf.h"
#include "RixIntegrator.h"

namespace bxdflab {

struct BxdfScratch {
    RixBXLobeTraits* lobesWanted;     ///< all lobes, for every point
    RixBXLobeTraits* lobesEvaluated;
    RixBXLobeSampled* lobeSampled;
    RtVector3* Ln;
    float* FPdf;
    float* RPdf;
    RixBXLobeWeights W;

    explicit BxdfScratch(RixShadingContext const& ctx)
        : lobesWanted(RixShadingContext::Allocator(&ctx).AllocFor<RixBXLobeTraits>(ctx.numPts)),
          lobesEvaluated(RixShadingContext::Allocator(&ctx).AllocFor<RixBXLobeTraits>(ctx.numPts)),
          lobeSampled(RixShadingContext::Allocator(&ctx).AllocFor<RixBXLobeSampled>(ctx.numPts)),
          Ln(RixShadingContext::Allocator(&ctx).AllocFor<RtVector3>(ctx.numPts)),
          FPdf(RixShadingContext::Allocator(&ctx).AllocFor<float>(ctx.numPts)),
          RPdf(RixShadingContext::Allocator(&ctx).AllocFor<float>(ctx.numPts)),
          W(ctx.numPts, RixShadingContext::Allocator(&ctx).AllocFor<RtColorRGB>(ctx.numPts * RixBXLobeWeights::k_numSlots)) {
        for (int i = 0; i < ctx.numPts; ++i) lobesWanted[i] = RixBXLobeTraits::All();
    }

    void generate(RixBxdf& bxdf, RixRNG& rng) {
        W.ClearActiveLobes();
        bxdf.GenerateSample(k_RixBXDirectLighting, lobesWanted, &rng, lobeSampled, Ln, W, FPdf, RPdf);
    }
    /// Evaluates the directions currently in Ln.
    void evaluate(RixBxdf& bxdf, RixRNG& rng) {
        W.ClearActiveLobes();
        bxdf.EvaluateSample(k_RixBXDirectLighting, lobesWanted, &rng, lobesEvaluated, Ln, W, FPdf, RPdf);
    }
};

}  // namespace bxdflab
