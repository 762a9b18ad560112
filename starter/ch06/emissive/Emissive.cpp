#include "Todo.h"
#include "Emissive.h"

Emissive::Emissive(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB const* emission)
    : RixBxdf(sc, factory), m_emission(emission) {}

bool Emissive::EmitLocal(RtColorRGB* result) {
    // TODO: for every shade point i (0 .. shadingCtx->numPts - 1), write the
    // emitted radiance, m_emission[i], into result[i], and return true to
    // tell the integrator this surface glows.
    PIXAR_ARGUSED(result);
    RIX_TODO(shadingCtx, "Emissive::EmitLocal");
    return false;  // "no emission": the sphere renders black
}

// An emissive surface reflects nothing, so no direction can be generated:
// every sample is marked invalid (which tells the integrator to stop the path).
void Emissive::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeSampled* lobeSampled,
                              RtVector3* Ln, RixBXLobeWeights&, float* FPdf, float* RPdf, RtColorRGB*) {
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobeSampled[i].SetValid(false);
        Ln[i] = RtVector3(0.0f, 0.0f, 0.0f);
        FPdf[i] = 0.0f;
        RPdf[i] = 0.0f;
    }
}

// ...and every given direction reflects zero: no lobe contributes.
void Emissive::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeTraits* lobesEvaluated,
                              RtVector3 const*, RixBXLobeWeights&, float* FPdf, float* RPdf) {
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = 0.0f;
        RPdf[i] = 0.0f;
    }
}

void Emissive::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const&, RixRNG*, int, int numSamples,
                                      RixBXLobeTraits* lobesEvaluated, RtVector3 const*, RixBXLobeWeights&,
                                      float* FPdf, float* RPdf) {
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = 0.0f;
        RPdf[s] = 0.0f;
    }
}
