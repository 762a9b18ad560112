#include "Glass.h"

#include <cmath>

#include "GGXMicrofacets.h"
#include "RixShadingUtils.h"
#include "Todo.h"

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
    // TODO (exercise 2): the microfacet normal H through which V refracts into L
    // (chapter 10, "The half vector of a refraction"): write Snell's law at H as one
    // vector equation and solve it for H. Turn H to z > 0, set lengthSq to the squared
    // length of the vector you normalised, and return whether V and L lie on opposite
    // sides of the microfacet (V.H > 0 > L.H) -- otherwise no refraction joins them.
    PIXAR_ARGUSED(V);
    PIXAR_ARGUSED(L);
    PIXAR_ARGUSED(etaV);
    PIXAR_ARGUSED(etaL);
    H = RtVector3(0.0f, 0.0f, 1.0f);
    lengthSq = 1.0f;
    return false;
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
        // TODO (exercise 3): reflection, chosen with probability F(V.H): chapter 9's
        // visible-normal density of L times that probability.
        return 0.0f;
    }
    // TODO (exercise 3): transmission, chosen with probability 1 - F(V.H)
    // (refractionFresnel). The density of L is the density of the visible normal H
    // that refracts V into L, D_V(H) = G1(V) V.H D(H) / V.z, times the Jacobian
    // d(omega_H) / d(omega_L) of the refraction, which you derive in chapter 10
    // ("From normals to directions, through glass"). Until then transmission has no density.
    PIXAR_ARGUSED(a);
    RtVector3 H;
    float denominatorSq;
    if (!refractionHalfVector(V, L, etaV, etaL, H, denominatorSq)) return 0.0f;
    return 0.0f;
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
        // TODO (exercise 2): W = f cos(theta_L) for the light reflected by the microfacet
        // H = normalize(V + L): chapter 9's weight with Schlick's F replaced by the
        // dielectric F(V.H) (fresnel(V.H, s.etaV, s.etaL)).
        RIX_TODO(shadingCtx, "Glass::evaluate (reflection)");
        PIXAR_ARGUSED(G2);
        weight = RtColorRGB(0.0f);
    } else {
        RtVector3 H;
        float denominatorSq;  // (etaV V.H + etaL L.H)^2
        if (!refractionHalfVector(V, L, s.etaV, s.etaL, H, denominatorSq)) return false;
        float VdotH = V.Dot(H), LdotH = L.Dot(H);
        // TODO (exercise 2): W = f cos(theta_L) for the light refracted through H, with f
        // Walter et al.'s BTDF as Glass.h writes it (F from refractionFresnel, D and G2
        // from GGXMicrofacets.h), tinted by m_params.transmissionColor[i].
        RIX_TODO(shadingCtx, "Glass::evaluate (transmission)");
        float F = refractionFresnel(VdotH, LdotH, s.etaV, s.etaL);
        PIXAR_ARGUSED(F);
        weight = RtColorRGB(0.0f);
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
            // TODO (exercise 1): a smooth boundary (chapter 10, "Smooth glass").
            //  - F = fresnel(V.z, s.etaV, s.etaL); reflect when choice[i] < F, else refract;
            //  - L in the local frame: the mirror direction, or Snell's refracted
            //    direction (RixRefract, with the normal (0, 0, 1));
            //  - Ln[i] = s.toWorld(L); a direction on the wrong side of s.Ng is invalid;
            //  - W into the lobe's array (W.AddActiveLobe), FPdf and RPdf: the probability of
            //    the choice; what W must be so that W / FPdf is the light each way carries,
            //    radiance being squeezed by (eta_V / eta_L)^2 as it crosses, is yours to work out;
            //  - lobeSampled[i] = the lobe (g_glassMirrorLobe or g_glassRefractLobe), valid.
            // Until then every smooth sample is invalid (the surface renders black).
            RIX_TODO(shadingCtx, "Glass::GenerateSample (smooth)");
            PIXAR_ARGUSED(choice);
            continue;
        }

        // Rough: a visible microfacet normal, then reflect or refract about it.
        float a = alpha(i);
        RtVector3 H = ggx::sampleVisibleNormal(V, xi[i], a);
        float VdotH = V.Dot(H);
        // TODO (exercise 4): reflect V about H with probability F(V.H) (fresnel), else
        // refract it through H (RixRefract with the microfacet normal H); a direction that
        // ends on the wrong side of the surface (reflected below, refracted above) is invalid.
        // Until then every rough sample reflects, and transmission is never sampled.
        RIX_TODO(shadingCtx, "Glass::GenerateSample (rough)");
        PIXAR_ARGUSED(VdotH);
        bool reflect = true;
        RtVector3 L = H * (2.0f * VdotH) - V;
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
