#include "FinishedWood.h"

#include <cmath>

#include "RixShadingUtils.h"

RixBXLobeSampled g_woodSubsurfaceLobe;
RixBXLobeSampled g_woodCoatLobe;
RixBXLobeSampled g_woodFiberLobe;
RixBXLobeTraits g_woodTraits;

namespace {

/// The normalised Gaussian of standard deviation beta.
float gaussian(float beta, float x) {
    return std::exp(-x * x / (2.0f * beta * beta)) / (beta * std::sqrt(F_TWOPI));
}

float safeAsin(float x) { return std::asin(RixClamp(x, -1.0f, 1.0f)); }

}  // namespace

FinishedWood::FinishedWood(RixShadingContext const* sc, RixBxdfFactory* factory, FinishedWoodParams const& params)
    : RixBxdf(sc, factory), m_params(params) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Tn, &m_Tn);  // the fiber axis is given in the tangent frame
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

bool FinishedWood::evaluate(int i, RtVector3 const& Ln, Weights& w, float& fpdf, float& rpdf) const {
    w = Weights{};
    fpdf = rpdf = 0.0f;
    RtVector3 const& Vn = m_Vn[i];
    RtNormal3 N = RixGetForwardFacingNormal(Vn, m_Nn[i]);
    RtNormal3 Ng = RixGetForwardFacingNormal(Vn, m_Ngn[i]);
    float cosL = N.Dot(Ln), cosV = N.Dot(Vn);
    if (cosL <= 0.0f || cosV <= 0.0f || Ng.Dot(Ln) <= 0.0f) return false;

    // 1. The coat: a Fresnel-weighted highlight at the varnish surface.
    float relativeEta = 1.0f / RixMax(m_params.eta[i], 1e-3f);  // outside over inside
    RtVector3 H = Normalize(Ln + Vn);
    float fresnelH;
    RixFresnelDielectric(RixClamp(H.Dot(Vn), 0.0f, 1.0f), relativeEta, &fresnelH);
    float exponent = 1.0f / RixMax(m_params.roughness[i], 1e-4f);
    w.coat = m_params.specularColor[i] * (fresnelH * std::pow(RixMax(N.Dot(H), 0.0f), exponent) * cosL);

    // 2. Into and out of the finish: refracted directions and transmittances.
    float fresnelL, fresnelV;
    RtVector3 refractedL, refractedV;  // both travel INTO the wood (zero on total internal reflection)
    RixFresnelDielectric(Ln, N, relativeEta, &fresnelL, nullptr, &refractedL);
    RixFresnelDielectric(Vn, N, relativeEta, &fresnelV, nullptr, &refractedV);
    RtVector3 sIn = refractedL;    // the light's path in the wood
    RtVector3 sOut = -refractedV;  // the path that leaves toward the viewer
    // What reaches the wood and comes back out: both transmittances, and the
    // radiance compression by eta^2 entering the denser finish, undone leaving
    // it (Marschner et al. 2005, section 4). The cosine that weights the
    // reflectance equation stays the OUTSIDE one, cos(theta_L).
    float eta = RixMax(m_params.eta[i], 1e-3f);
    float underFinish = (1.0f - fresnelL) * (1.0f - fresnelV) / (eta * eta);

    // 3. Subsurface diffuse: f = rho_d / pi, under the finish.
    w.subsurface = m_params.diffuseColor[i] * (F_INVPI * underFinish * cosL);

    // 4. Fibers: a highlight where the refracted paths make opposite angles with the fiber.
    RtVector3 TX, TY;
    RixComputeShadingBasis(N, m_Tn[i], TX, TY);
    RtVector3 const& axisLocal = m_params.fiberAxis[i];
    RtVector3 axis = Normalize(TX * axisLocal.x + TY * axisLocal.y + N * axisLocal.z);
    if (!axis.IsZero() && !sIn.IsZero() && !sOut.IsZero()) {
        float psiI = safeAsin(-sIn.Dot(axis));
        float psiR = safeAsin(sOut.Dot(axis));
        float psiH = psiR + psiI, psiD = psiR - psiI;
        float beta = RixMax(m_params.beta[i], 1e-4f);
        float cosHalfD = std::cos(0.5f * psiD);
        float fiber = gaussian(beta, psiH) / RixMax(cosHalfD * cosHalfD, 1e-4f);
        w.fiber = m_params.fiberColor[i] * (fiber * underFinish * cosL);
    }

    // Every lobe is sampled by the cosine distribution.
    fpdf = cosL * F_INVPI;
    rpdf = cosV * F_INVPI;
    return true;
}

void FinishedWood::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                                  RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                                  float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* subsurface = W.AddActiveLobe(g_woodSubsurfaceLobe);
    RtColorRGB* coat = W.AddActiveLobe(g_woodCoatLobe);
    RtColorRGB* fiber = W.AddActiveLobe(g_woodFiberLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples2D(xi);
    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_woodTraits).HasAny()) continue;
        RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
        float cosTheta;
        RixCosDirectionalDistribution(xi[i], N, Ln[i], cosTheta);
        Weights w;
        if (!evaluate(i, Ln[i], w, FPdf[i], RPdf[i])) continue;
        subsurface[i] = w.subsurface;
        coat[i] = w.coat;
        fiber[i] = w.fiber;
        lobeSampled[i] = g_woodSubsurfaceLobe;  // the cosine distribution is the diffuse lobe's
        lobeSampled[i].SetValid(true);
    }
}

void FinishedWood::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                                  RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W,
                                  float* FPdf, float* RPdf) {
    RtColorRGB* subsurface = W.AddActiveLobe(g_woodSubsurfaceLobe);
    RtColorRGB* coat = W.AddActiveLobe(g_woodCoatLobe);
    RtColorRGB* fiber = W.AddActiveLobe(g_woodFiberLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        Weights w;
        if (!(all & lobesWanted[i] & g_woodTraits).HasAny() || !evaluate(i, Ln[i], w, FPdf[i], RPdf[i])) continue;
        subsurface[i] = w.subsurface;
        coat[i] = w.coat;
        fiber[i] = w.fiber;
        lobesEvaluated[i] |= g_woodTraits;
        lobesEvaluated[i].SetValid(true);
    }
}

void FinishedWood::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*,
                                          int index, int numSamples, RixBXLobeTraits* lobesEvaluated,
                                          RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* subsurface = W.AddActiveLobe(g_woodSubsurfaceLobe);
    RtColorRGB* coat = W.AddActiveLobe(g_woodCoatLobe);
    RtColorRGB* fiber = W.AddActiveLobe(g_woodFiberLobe);
    bool wanted = (GetAllLobeTraits() & lobesWanted & g_woodTraits).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        Weights w;
        if (!wanted || !evaluate(index, Ln[s], w, FPdf[s], RPdf[s])) continue;
        subsurface[s] = w.subsurface;
        coat[s] = w.coat;
        fiber[s] = w.fiber;
        lobesEvaluated[s] |= g_woodTraits;
        lobesEvaluated[s].SetValid(true);
    }
}
