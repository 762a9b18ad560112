#include "Specular.h"

#include <cmath>

#include "RixShadingUtils.h"

RixBXLobeSampled g_specularLobe;
RixBXLobeTraits g_specularTraits;

Specular::Specular(RixShadingContext const* sc, RixBxdfFactory* factory, SpecularParams const& params)
    : RixBxdf(sc, factory), m_params(params) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

float Specular::pdf(int i, RtNormal3 const& N, RtVector3 const& from, RtVector3 const& to) const {
    float cosTo = N.Dot(to);
    if (cosTo <= 0.0f) return 0.0f;
    if (m_params.samplingMode == 0) return cosTo * F_INVPI;
    RtVector3 R = RixReflect(-from, N);  // the lobe's axis: the mirror direction of `from`
    return RixPhongLobePdf(R.Dot(to), m_params.gloss[i]);
}

bool Specular::evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const {
    weight = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
    RtNormal3 Ng = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    float NdL = N.Dot(Ln), NdV = N.Dot(m_Vn[i]);
    if (NdL <= 0.0f || NdV <= 0.0f || Ng.Dot(Ln) <= 0.0f) return false;  // reflection only

    float n = RixMax(m_params.gloss[i], 0.0f);
    RtVector3 R = RixReflect(-m_Vn[i], N);  // mirror direction of the viewer: 2 (N.V) N - V
    float RdL = RixMax(R.Dot(Ln), 0.0f);
    float lobe = std::pow(RdL, n);
    if (m_params.normalize) lobe *= (n + 2.0f) * F_INVTWOPI;
    weight = m_params.specularColor[i] * (lobe * NdL);
    fpdf = pdf(i, N, m_Vn[i], Ln);
    rpdf = pdf(i, N, Ln, m_Vn[i]);
    return true;
}

void Specular::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                              RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                              float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* weights = W.AddActiveLobe(g_specularLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples2D(xi);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_specularTraits).HasAny()) continue;
        RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
        float cosine;
        if (m_params.samplingMode == 0)
            RixCosDirectionalDistribution(xi[i], N, Ln[i], cosine);
        else
            RixPhongLobeDirectionalDistribution(xi[i], m_params.gloss[i], RixReflect(-m_Vn[i], N), Ln[i], cosine);
        // A lobe direction below the surface reflects nothing: the sample is invalid.
        if (!evaluate(i, Ln[i], weights[i], FPdf[i], RPdf[i]) || !(FPdf[i] > 0.0f)) continue;
        lobeSampled[i] = g_specularLobe;
        lobeSampled[i].SetValid(true);
    }
}

void Specular::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                              RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                              float* RPdf) {
    RtColorRGB* weights = W.AddActiveLobe(g_specularLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        if ((all & lobesWanted[i] & g_specularTraits).HasAny() && evaluate(i, Ln[i], weights[i], FPdf[i], RPdf[i])) {
            lobesEvaluated[i] |= g_specularTraits;
            lobesEvaluated[i].SetValid(true);
        }
    }
}

void Specular::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                      int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                      RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* weights = W.AddActiveLobe(g_specularLobe);
    bool wanted = (GetAllLobeTraits() & lobesWanted & g_specularTraits).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        if (wanted && evaluate(index, Ln[s], weights[s], FPdf[s], RPdf[s])) {
            lobesEvaluated[s] |= g_specularTraits;
            lobesEvaluated[s].SetValid(true);
        }
    }
}
