#include "Todo.h"
#include "Plastic.h"

#include <cmath>

#include "RixShadingUtils.h"

RixBXLobeSampled g_plasticDiffuseLobe;
RixBXLobeSampled g_plasticSpecularLobe;
RixBXLobeTraits g_plasticTraits;

Plastic::Plastic(RixShadingContext const* sc, RixBxdfFactory* factory, PlasticParams const& params)
    : RixBxdf(sc, factory), m_params(params) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

float Plastic::specularProbability(int i) const {
    float d = RixMax(m_params.diffuseColor[i].Luminance(), 0.0f);
    float s = RixMax(m_params.specularColor[i].Luminance(), 0.0f);
    return d + s > 0.0f ? s / (d + s) : 0.0f;
}

float Plastic::mixturePdf(int i, RtNormal3 const& N, RtVector3 const& from, RtVector3 const& to) const {
    float cosTo = N.Dot(to);
    if (cosTo <= 0.0f) return 0.0f;
    // TODO: the mixture pdf p_d * cos/pi + p_s * (n + 1)/(2 pi) max(0, R.to)^n,
    // with p_s = specularProbability(i), p_d = 1 - p_s, R the mirror direction of
    // `from` (RixReflect(-from, N)). RixPhongLobePdf computes the Phong part.
    PIXAR_ARGUSED(i);
    PIXAR_ARGUSED(from);
    RIX_TODO(shadingCtx, "Plastic::mixturePdf");
    return 0.0f;
}

bool Plastic::evaluate(int i, RtVector3 const& Ln, RtColorRGB& diffuse, RtColorRGB& specular, float& fpdf,
                       float& rpdf) const {
    diffuse = specular = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
    RtNormal3 Ng = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    float NdL = N.Dot(Ln), NdV = N.Dot(m_Vn[i]);
    if (NdL <= 0.0f || NdV <= 0.0f || Ng.Dot(Ln) <= 0.0f) return false;

    // TODO: both lobes' weights at Ln, and the mixture pdfs.
    //  diffuse  = rho_d / pi * NdL                        (m_params.diffuseColor[i])
    //  specular = ks * lobe * NdL, lobe as in the specular exercise
    //  fpdf = mixturePdf(i, N, m_Vn[i], Ln), rpdf = mixturePdf(i, N, Ln, m_Vn[i]); return true.
    RIX_TODO(shadingCtx, "Plastic::evaluate");
    return false;
}

void Plastic::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                             RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                             float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* diffuseW = W.AddActiveLobe(g_plasticDiffuseLobe);
    RtColorRGB* specularW = W.AddActiveLobe(g_plasticSpecularLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    float* choice = static_cast<float*>(RixAlloca(sizeof(float) * n));
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples1D(choice);
    rng->DrawSamples2D(xi);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_plasticTraits).HasAny()) continue;
        float probabilities[2] = {1.0f - specularProbability(i), specularProbability(i)};
        int chosen = RixBXChooseLobe(choice[i], probabilities, 2);
        if (chosen < 0) continue;  // both lobes black: nothing to sample

        RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
        float cosine;
        if (chosen == 0)
            RixCosDirectionalDistribution(xi[i], N, Ln[i], cosine);
        else
            RixPhongLobeDirectionalDistribution(xi[i], m_params.gloss[i], RixReflect(-m_Vn[i], N), Ln[i], cosine);
        if (!evaluate(i, Ln[i], diffuseW[i], specularW[i], FPdf[i], RPdf[i]) || !(FPdf[i] > 0.0f)) continue;
        lobeSampled[i] = chosen == 0 ? g_plasticDiffuseLobe : g_plasticSpecularLobe;
        lobeSampled[i].SetValid(true);
    }
}

void Plastic::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                             RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                             float* RPdf) {
    RtColorRGB* diffuseW = W.AddActiveLobe(g_plasticDiffuseLobe);
    RtColorRGB* specularW = W.AddActiveLobe(g_plasticSpecularLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        if ((all & lobesWanted[i] & g_plasticTraits).HasAny() &&
            evaluate(i, Ln[i], diffuseW[i], specularW[i], FPdf[i], RPdf[i])) {
            lobesEvaluated[i] |= g_plasticTraits;
            lobesEvaluated[i].SetValid(true);
        }
    }
}

void Plastic::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                     int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                     RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* diffuseW = W.AddActiveLobe(g_plasticDiffuseLobe);
    RtColorRGB* specularW = W.AddActiveLobe(g_plasticSpecularLobe);
    bool wanted = (GetAllLobeTraits() & lobesWanted & g_plasticTraits).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        if (wanted && evaluate(index, Ln[s], diffuseW[s], specularW[s], FPdf[s], RPdf[s])) {
            lobesEvaluated[s] |= g_plasticTraits;
            lobesEvaluated[s].SetValid(true);
        }
    }
}
