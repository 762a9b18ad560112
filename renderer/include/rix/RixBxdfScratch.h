// For integrator writers: the per-point arrays an integrator passes to a
// Bxdf's GenerateSample and EvaluateSample, allocated from the batch's memory
// pool, with the two calls made the way the renderer's own integrators make
// them (arrays cleared first, invalid pdfs reported and dropped).
//
//     RixBxdfScratch q(ctx);
//     q.generate(bxdf, rng, ictx);      // q.Ln[i], q.W.SumAtPoint(i), q.FPdf[i], q.lobeSampled[i]
//     q.Ln[i] = ...; q.evaluate(bxdf, rng, ictx);
#pragma once

#include "RixBxdf.h"
#include "RixIntegrator.h"

/// Whether a Bxdf whose GetEvaluateDomain() is `domain` scatters from V to L
/// at a point whose geometric normal is Ngn: V's side and L's side of the
/// surface pick the bit (V on the surface's plane counts as outside; L on it
/// has no side, and only a volume scatters there).
inline bool RixBXDomainHolds(RixBXEvaluateDomain domain, RtNormal3 const& Ngn, RtVector3 const& V, RtVector3 const& L) {
    if (domain & k_RixBXVolume) return true;
    float const l = Ngn.Dot(L);
    if (l == 0.0f) return false;
    bool const viewOutside = Ngn.Dot(V) >= 0.0f, lightOutside = l > 0.0f;
    int const needed = viewOutside ? (lightOutside ? k_RixBXOutsideReflect : k_RixBXOutsideTransmit)
                                   : (lightOutside ? k_RixBXInsideTransmit : k_RixBXInsideReflect);
    return (domain & needed) != 0;
}

struct RixBxdfScratch {
    int numPts;
    RixBXLobeTraits* lobesWanted;     ///< all lobes, for every point
    RixBXLobeTraits* lobesEvaluated;
    RixBXLobeSampled* lobeSampled;
    RtVector3* Ln;
    float* FPdf;
    float* RPdf;
    RixBXLobeWeights W;
    RtNormal3 const* Ngn = nullptr;  ///< the points' geometric normals and views, for the Bxdf's domain
    RtVector3 const* Vn = nullptr;

    explicit RixBxdfScratch(RixShadingContext const& ctx)
        : numPts(ctx.numPts),
          lobesWanted(RixShadingContext::Allocator(&ctx).AllocFor<RixBXLobeTraits>(ctx.numPts)),
          lobesEvaluated(RixShadingContext::Allocator(&ctx).AllocFor<RixBXLobeTraits>(ctx.numPts)),
          lobeSampled(RixShadingContext::Allocator(&ctx).AllocFor<RixBXLobeSampled>(ctx.numPts)),
          Ln(RixShadingContext::Allocator(&ctx).AllocFor<RtVector3>(ctx.numPts)),
          FPdf(RixShadingContext::Allocator(&ctx).AllocFor<float>(ctx.numPts)),
          RPdf(RixShadingContext::Allocator(&ctx).AllocFor<float>(ctx.numPts)),
          W(ctx.numPts, &ctx) {
        for (int i = 0; i < ctx.numPts; ++i) lobesWanted[i] = RixBXLobeTraits::All();
        ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
        ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
    }

    /// One sample per point. Every array starts cleared (no lobe, invalid,
    /// zero direction and pdfs): a Bxdf may leave untouched what its contract
    /// lets it (a point it does not sample), as the course text's plugins do.
    /// A sample the Bxdf marks valid must have FPdf > 0; one that does not
    /// (zero, negative or NaN) is a Bxdf bug: it is reported (counted in the
    /// render stats) and marked invalid, so no integrator uses it. A sample
    /// outside the Bxdf's GetEvaluateDomain() is marked invalid too, unless it
    /// is discrete (a mirror or a refraction may go anywhere).
    void generate(RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx) {
        W.ClearActiveLobes();
        for (int i = 0; i < numPts; ++i) {
            lobeSampled[i] = RixBXLobeSampled();
            Ln[i] = RtVector3(0.0f, 0.0f, 0.0f);
            FPdf[i] = RPdf[i] = 0.0f;
        }
        bxdf.GenerateSample(k_RixBXDirectLighting, lobesWanted, &rng, lobeSampled, Ln, W, FPdf, RPdf);
        RixBXEvaluateDomain const domain = bxdf.GetEvaluateDomain();
        for (int i = 0; i < numPts; ++i) {
            if (!lobeSampled[i].GetValid()) continue;
            if (!(FPdf[i] > 0.0f)) {
                ictx.CountInvalidPdf();
                lobeSampled[i].SetValid(false);
            } else if (!lobeSampled[i].GetDiscrete() && !RixBXDomainHolds(domain, Ngn[i], Vn[i], Ln[i])) {
                lobeSampled[i].SetValid(false);
            }
        }
    }
    /// Evaluates the directions currently in Ln (lobes evaluated and pdfs
    /// start cleared). Where the Bxdf says it evaluated a lobe, FPdf may be 0
    /// (it would never choose Ln) but not negative or NaN: such a value is
    /// reported and taken as 0. A direction outside the Bxdf's
    /// GetEvaluateDomain() is given no weight and no pdfs, whatever the Bxdf
    /// said (as RenderMan's integrators skip it): a Bxdf that declares
    /// reflection only lets no light through its surface where a bent shading
    /// normal would.
    void evaluate(RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx) {
        W.ClearActiveLobes();
        for (int i = 0; i < numPts; ++i) {
            lobesEvaluated[i].SetNone();
            FPdf[i] = RPdf[i] = 0.0f;
        }
        bxdf.EvaluateSample(k_RixBXDirectLighting, lobesWanted, &rng, lobesEvaluated, Ln, W, FPdf, RPdf);
        RixBXEvaluateDomain const domain = bxdf.GetEvaluateDomain();
        for (int i = 0; i < numPts; ++i) {
            if (!RixBXDomainHolds(domain, Ngn[i], Vn[i], Ln[i])) {
                W.ZeroAtPoint(i);
                lobesEvaluated[i].SetNone();
                FPdf[i] = RPdf[i] = 0.0f;
            } else if (lobesEvaluated[i].HasAny() && !(FPdf[i] >= 0.0f)) {
                ictx.CountInvalidPdf();
                FPdf[i] = 0.0f;
            }
        }
    }
};
