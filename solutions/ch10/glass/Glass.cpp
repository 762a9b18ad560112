#include "Glass.h"

#include <cmath>

#include "GGXMicrofacets.h"
#include "RixShadingUtils.h"

RixBXLobeSampled g_glassMirrorLobe;
RixBXLobeSampled g_glassRefractLobe;
RixBXLobeSampled g_glassRoughReflectLobe;
RixBXLobeSampled g_glassRoughRefractLobe;
RixBXLobeTraits g_glassTraits;

namespace {

/// The dielectric Fresnel reflectance for light meeting the boundary at cos
/// c on the side of index etaI, the other side being etaT (1 on total internal reflection).
float fresnel(float c, float etaI, float etaT) {
    float F = 1.0f;
    RixFresnelDielectric(c, etaI / etaT, &F);
    return F;
}

/// F for a refraction through a microfacet, V.H and L.H on its two sides. Both
/// cosines give the same F; the one on the side of the lower index is used,
/// because the other sits near the critical angle when the first is grazing,
/// where F is steep in it and float rounding of 1 - eta^2 sin^2 shows.
float refractionFresnel(float VdotH, float LdotH, float etaV, float etaL) {
    return etaV <= etaL ? fresnel(VdotH, etaV, etaL) : fresnel(std::fabs(LdotH), etaL, etaV);
}

/// The generalised half vector of a refraction between V (index etaV) and L
/// (index etaL, on the other side): the microfacet normal that bends one into
/// the other by Snell's law, h = etaV V + etaL L normalised and turned to
/// z > 0. False when V and L cannot be joined by a refraction (then H is
/// unset). lengthSq = |h|^2 is also (etaV V.H + etaL L.H)^2, the denominator of
/// the refraction's Jacobian: taken from h it does not lose its digits to the
/// cancellation between the two dot products (of opposite signs).
bool refractionHalfVector(RtVector3 const& V, RtVector3 const& L, float etaV, float etaL, RtVector3& H,
                          float& lengthSq) {
    RtVector3 h = V * etaV + L * etaL;
    lengthSq = h.LengthSq();
    if (!(lengthSq > 1e-12f)) return false;
    H = h * ((h.z < 0.0f ? -1.0f : 1.0f) / std::sqrt(lengthSq));
    return V.Dot(H) > 0.0f && L.Dot(H) < 0.0f;  // V and L on opposite sides of the microfacet
}

bool wanted(RixBXLobeTraits const& lobesWanted, RixBXLobeSampled const& lobe) {
    return (lobesWanted & RixBXLobeTraits(lobe)).HasAny();
}

}  // namespace

Glass::Glass(RixShadingContext const* sc, RixBxdfFactory* factory, GlassParams const& params)
    : RixBxdf(sc, factory), m_params(params) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Tn, &m_Tn);
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

Glass::Side Glass::side(int i) const {
    Side s;
    // The geometric normal points outside: a viewer behind it looks from inside the glass.
    bool outside = m_Vn[i].Dot(m_Ngn[i]) >= 0.0f;
    float ior = m_params.ior[i] > 0.0f ? m_params.ior[i] : 1.0f;
    s.etaV = outside ? 1.0f : ior;
    s.etaL = outside ? ior : 1.0f;
    s.N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
    s.Ng = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    RixComputeShadingBasis(s.N, m_Tn[i], s.u, s.v);
    return s;
}

float Glass::alpha(int i) const { return RixMax(m_params.roughness[i], ggx::kMinAlpha); }

float Glass::pdf(RtVector3 const& V, RtVector3 const& L, float etaV, float etaL, float a) {
    if (V.z <= 0.0f || L.z == 0.0f) return 0.0f;
    if (L.z > 0.0f) {
        // Reflection: chosen with probability F(V.H), and mirroring about H has
        // the Jacobian d(omega_H)/d(omega_L) = 1 / (4 V.H), which cancels D_V's V.H.
        RtVector3 H = Normalize(V + L);
        float VdotH = V.Dot(H);
        if (VdotH <= 0.0f) return 0.0f;
        return fresnel(VdotH, etaV, etaL) * ggx::G1(V, a) * ggx::D(H, a) / (4.0f * V.z);
    }
    // Transmission: chosen with probability 1 - F(V.H); refracting through H
    // has the Jacobian d(omega_H)/d(omega_L) = etaL^2 |L.H| / (etaV V.H + etaL L.H)^2.
    RtVector3 H;
    float denominatorSq;
    if (!refractionHalfVector(V, L, etaV, etaL, H, denominatorSq)) return 0.0f;
    float VdotH = V.Dot(H), LdotH = L.Dot(H);
    float jacobian = etaL * etaL * std::fabs(LdotH) / denominatorSq;
    float visibleNormals = ggx::G1(V, a) * VdotH * ggx::D(H, a) / V.z;
    return (1.0f - refractionFresnel(VdotH, LdotH, etaV, etaL)) * visibleNormals * jacobian;
}

bool Glass::evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf, bool& transmits) const {
    weight = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    if (smooth(i)) return false;  // discrete lobes: no direction can be evaluated
    Side s = side(i);
    RtVector3 V = s.toLocal(m_Vn[i]), L = s.toLocal(Ln);
    transmits = L.z < 0.0f;
    // The geometric normal decides the side, so that no light leaks through a
    // surface whose shading normal is bent.
    if (V.z <= 0.0f || L.z == 0.0f || (s.Ng.Dot(Ln) < 0.0f) != transmits) return false;

    float a = alpha(i);
    float const G2 = ggx::G2(V, L, a);
    if (!transmits) {
        RtVector3 H = Normalize(V + L);
        float F = fresnel(V.Dot(H), s.etaV, s.etaL);
        weight = RtColorRGB(F * ggx::D(H, a) * G2 / (4.0f * V.z));
    } else {
        RtVector3 H;
        float denominatorSq;  // (etaV V.H + etaL L.H)^2
        if (!refractionHalfVector(V, L, s.etaV, s.etaL, H, denominatorSq)) return false;
        float VdotH = V.Dot(H), LdotH = L.Dot(H);
        float F = refractionFresnel(VdotH, LdotH, s.etaV, s.etaL);
        float f = VdotH * std::fabs(LdotH) * s.etaV * s.etaV * (1.0f - F) * ggx::D(H, a) * G2 / (V.z * denominatorSq);
        weight = m_params.transmissionColor[i] * f;
    }
    fpdf = pdf(V, L, s.etaV, s.etaL, a);
    // The reverse: sampling V from L's side, where z and the indices swap for a transmission.
    float flip = transmits ? -1.0f : 1.0f;
    RtVector3 Lr(L.x, L.y, flip * L.z), Vr(V.x, V.y, flip * V.z);
    rpdf = transmits ? pdf(Lr, Vr, s.etaL, s.etaV, a) : pdf(L, V, s.etaV, s.etaL, a);
    return true;
}

bool Glass::evaluateInto(int i, RtVector3 const& Ln, RixBXLobeTraits const& lobesWanted, RixBXLobeWeights& W, int slot,
                         RixBXLobeTraits& evaluated, float& fpdf, float& rpdf) const {
    RtColorRGB weight;
    bool transmits = false;
    bool const found = evaluate(i, Ln, weight, fpdf, rpdf, transmits);
    RixBXLobeSampled const& lobe = transmits ? g_glassRoughRefractLobe : g_glassRoughReflectLobe;
    if (!found || !wanted(lobesWanted, lobe)) {
        fpdf = rpdf = 0.0f;
        return false;
    }
    W.AddActiveLobe(lobe)[slot] = weight;
    evaluated |= RixBXLobeTraits(lobe);
    evaluated.SetValid(true);
    return true;
}

void Glass::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                           RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                           float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RixBXLobeTraits const all = GetAllLobeTraits();
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    float* choice = static_cast<float*>(RixAlloca(sizeof(float) * n));
    rng->DrawSamples2D(xi);
    rng->DrawSamples1D(choice);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        RixBXLobeTraits const want = all & lobesWanted[i];
        Side s = side(i);
        RtVector3 V = s.toLocal(m_Vn[i]);
        if (!(V.z > 0.0f)) continue;

        if (smooth(i)) {
            // One of two exact directions, chosen with the Fresnel probabilities.
            float F = fresnel(V.z, s.etaV, s.etaL);
            bool reflect = choice[i] < F;
            RixBXLobeSampled const& lobe = reflect ? g_glassMirrorLobe : g_glassRefractLobe;
            if (!wanted(want, lobe)) continue;
            RtVector3 L;
            if (reflect) {
                L = RtVector3(-V.x, -V.y, V.z);
            } else if (!RixRefract(-V, RtNormal3(0.0f, 0.0f, 1.0f), s.etaV / s.etaL, L)) {
                continue;  // total internal reflection has F = 1: not reached
            }
            Ln[i] = s.toWorld(L);
            if ((s.Ng.Dot(Ln[i]) > 0.0f) != reflect) continue;  // through the geometric surface: no light
            float probability = reflect ? F : 1.0f - F;
            RtColorRGB weight = reflect ? RtColorRGB(F)
                                        : m_params.transmissionColor[i] *
                                              ((1.0f - F) * (s.etaV * s.etaV) / (s.etaL * s.etaL));
            W.AddActiveLobe(lobe)[i] = weight;
            FPdf[i] = RPdf[i] = probability;  // F is the same seen from either side of a refraction
            lobeSampled[i] = lobe;
            lobeSampled[i].SetValid(true);
            continue;
        }

        // Rough: a visible microfacet normal, then reflect or refract about it.
        float a = alpha(i);
        RtVector3 H = ggx::sampleVisibleNormal(V, xi[i], a);
        float VdotH = V.Dot(H);
        float F = fresnel(VdotH, s.etaV, s.etaL);
        bool reflect = choice[i] < F;
        RtVector3 L;
        if (reflect)
            L = H * (2.0f * VdotH) - V;
        else if (!RixRefract(-V, RtNormal3(H.x, H.y, H.z), s.etaV / s.etaL, L))
            continue;
        if ((L.z > 0.0f) != reflect) continue;  // the microfacet sent it to the wrong side: invalid
        Ln[i] = s.toWorld(L);
        RtColorRGB weight;
        bool transmits = false;
        if (!evaluate(i, Ln[i], weight, FPdf[i], RPdf[i], transmits) || !(FPdf[i] > 0.0f)) {
            FPdf[i] = RPdf[i] = 0.0f;
            continue;
        }
        RixBXLobeSampled const& lobe = transmits ? g_glassRoughRefractLobe : g_glassRoughReflectLobe;
        if (!wanted(want, lobe)) {
            FPdf[i] = RPdf[i] = 0.0f;
            continue;
        }
        W.AddActiveLobe(lobe)[i] = weight;
        lobeSampled[i] = lobe;
        lobeSampled[i].SetValid(true);
    }
}

void Glass::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                           RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                           float* RPdf) {
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        evaluateInto(i, Ln[i], all & lobesWanted[i], W, i, lobesEvaluated[i], FPdf[i], RPdf[i]);
    }
}

void Glass::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                   int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                   RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RixBXLobeTraits const want = GetAllLobeTraits() & lobesWanted;
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        evaluateInto(index, Ln[s], want, W, s, lobesEvaluated[s], FPdf[s], RPdf[s]);
    }
}
