// emissive — a surface that glows with a constant colour and reflects nothing.
//
// Parameters
//   color emissiveColor   [1 1 1]   radiance leaving the surface, in every direction
//
// RIB
//   Bxdf "emissive" "glow" "color emissiveColor" [2 1.6 1.2]
//
// This is the smallest useful Bxdf: it has no lobes, so the integrator never
// asks it to sample or evaluate directions; it only calls EmitLocal.
#pragma once

#include "RixBxdf.h"

class Emissive : public RixBxdf {
public:
    /// `emission` has one colour per shade point (numPts entries).
    Emissive(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB const* emission);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXEmptyDomain; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { lobes->SetNone(); }
    bool EmitLocal(RtColorRGB* result) override;

    void GenerateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeSampled* lobeSampled,
                        RtVector3* Ln, RixBXLobeWeights& W, float* FPdf, float* RPdf,
                        RtColorRGB* compTrans) override;
    void EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeTraits* lobesEvaluated,
                        RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf, float* RPdf) override;
    void EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const&, RixRNG*, int index, int numSamples,
                                RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W,
                                float* FPdf, float* RPdf) override;

private:
    RtColorRGB const* m_emission;
};
