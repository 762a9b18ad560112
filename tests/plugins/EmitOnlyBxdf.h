// A base for test Bxdfs that only emit, to show a value on screen: it
// reflects nothing (every sample invalid, every evaluation empty); the
// plugin gives EmitLocal, or uses ColourEmitter for a colour per point.
#pragma once

#include "RixBxdf.h"

class EmitOnlyBxdf : public RixBxdf {
public:
    EmitOnlyBxdf(RixShadingContext const* sc, RixBxdfFactory* factory) : RixBxdf(sc, factory) {}
    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXEmptyDomain; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { lobes->SetNone(); }
    void GenerateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeSampled* sampled, RtVector3* Ln,
                        RixBXLobeWeights&, float* FPdf, float* RPdf, RtColorRGB*) override {
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            sampled[i].SetValid(false);
            Ln[i] = RtVector3(0.0f);
            FPdf[i] = RPdf[i] = 0.0f;
        }
    }
    void EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeTraits* evaluated, RtVector3 const*,
                        RixBXLobeWeights&, float* FPdf, float* RPdf) override {
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            evaluated[i].SetNone();
            FPdf[i] = RPdf[i] = 0.0f;
        }
    }
    void EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const&, RixRNG*, int, int numSamples,
                                RixBXLobeTraits* evaluated, RtVector3 const*, RixBXLobeWeights&, float* FPdf,
                                float* RPdf) override {
        for (int s = 0; s < numSamples; ++s) {
            evaluated[s].SetNone();
            FPdf[s] = RPdf[s] = 0.0f;
        }
    }
};

/// An EmitOnlyBxdf that emits one given colour per point (the array must
/// live as long as the batch: allocate it from the context's pool).
class ColourEmitter : public EmitOnlyBxdf {
public:
    ColourEmitter(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB const* emission)
        : EmitOnlyBxdf(sc, factory), m_emission(emission) {}
    bool EmitLocal(RtColorRGB* result) override {
        for (int i = 0; i < shadingCtx->numPts; ++i) result[i] = m_emission[i];
        return true;
    }

private:
    RtColorRGB const* m_emission;
};
