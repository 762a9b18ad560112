// buggydiffuse — the chapter 6 diffuse Bxdf with planted bugs.
//
// This plugin builds, loads and renders, but its picture is subtly wrong.
// Your job (chapter 7): find the bugs with the debugging tools rather than by
// staring at the code: a correct Bxdf's GenerateSample and EvaluateSample
// agree on W and FPdf for the same direction, and this one's do not. Then
// fix the bugs here and check that the render matches scenes/ch06/diffuse.rib's.
#include "Diffuse.h"

#include "RixShadingUtils.h"

RixBXLobeSampled g_diffuseLobe;
RixBXLobeTraits g_diffuseTraits;

Diffuse::Diffuse(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB const* albedo, int samplingMode)
    : RixBxdf(sc, factory), m_albedo(albedo), m_samplingMode(samplingMode) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

bool Diffuse::evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const {
    float NdV;
    RtNormal3 Nf = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i], &NdV);
    RtNormal3 Ngf = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    float NdL = Nf.Dot(Ln);
    if (NdL <= 0.0f || Ngf.Dot(Ln) <= 0.0f) {
        weight = RtColorRGB(0.0f);
        fpdf = rpdf = 0.0f;
        return false;
    }
    fpdf = F_INVTWOPI;
    rpdf = F_INVTWOPI;
    weight = m_albedo[i] * (NdV * F_INVPI);
    return true;
}

void Diffuse::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                             RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                             float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* weights = W.AddActiveLobe(g_diffuseLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples2D(xi);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_diffuseTraits).HasAny()) continue;

        float NdV;
        RtNormal3 Nf = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i], &NdV);
        RtNormal3 Ngf = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
        float NdL;
        RixCosDirectionalDistribution(xi[i], Nf, Ln[i], NdL);
        if (Ngf.Dot(Ln[i]) <= 0.0f) continue;
        FPdf[i] = NdL * F_INVPI;
        RPdf[i] = NdV * F_INVPI;
        weights[i] = m_albedo[i] * FPdf[i];
        lobeSampled[i] = g_diffuseLobe;
        lobeSampled[i].SetValid(true);
    }
}

void Diffuse::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                             RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                             float* RPdf) {
    RtColorRGB* weights = W.AddActiveLobe(g_diffuseLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_diffuseTraits).HasAny()) continue;
        if (evaluate(i, Ln[i], weights[i], FPdf[i], RPdf[i])) {
            lobesEvaluated[i] |= g_diffuseTraits;
            lobesEvaluated[i].SetValid(true);
        }
    }
}

void Diffuse::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                     int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                     RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* weights = W.AddActiveLobe(g_diffuseLobe);
    bool wanted = (GetAllLobeTraits() & lobesWanted & g_diffuseTraits).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        if (wanted && evaluate(index, Ln[s], weights[s], FPdf[s], RPdf[s])) {
            lobesEvaluated[s] |= g_diffuseTraits;
            lobesEvaluated[s].SetValid(true);
        }
    }
}
