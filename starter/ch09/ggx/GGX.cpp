#include "GGX.h"
#include "Todo.h"

#include <cmath>

#include "RixShadingUtils.h"

RixBXLobeSampled g_ggxSpecularLobe;
RixBXLobeTraits g_ggxTraits;

namespace {
constexpr float kMinRoughness = 1e-4f;

/// Schlick's approximation of the Fresnel reflectance at cos(angle) c.
[[maybe_unused]] RtColorRGB schlick(RtColorRGB const& F0, float c) {
    float m = RixMax(0.0f, 1.0f - c);
    float m5 = (m * m) * (m * m) * m;
    return F0 + (RtColorRGB(1.0f) - F0) * m5;
}
}  // namespace

GGX::GGX(RixShadingContext const* sc, RixBxdfFactory* factory, GGXParams const& params)
    : RixBxdf(sc, factory), m_params(params) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Tn, &m_Tn);  // anisotropy needs the tangent
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

GGX::Frame GGX::frame(int i) const {
    Frame f;
    f.N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
    RixComputeShadingBasis(f.N, m_Tn[i], f.u, f.v);  // any frame where Tn is zero or along N
    return f;
}

GGX::Roughness GGX::roughness(int i) const {
    return {RixMax(m_params.uRoughness[i], kMinRoughness), RixMax(m_params.vRoughness[i], kMinRoughness)};
}

float GGX::D(RtVector3 const& m, Roughness a) {
    if (m.z <= 0.0f) return 0.0f;
    // TODO (exercise 1): the GGX distribution of microfacet normals, D(m), for a unit m in
    // the local frame (m.z along N). Chapter 9 gives two forms; pick the one that stays
    // finite for every m when a.u and a.v are 1e-4 (the hard-cases check tries that).
    PIXAR_ARGUSED(a);
    return 0.0f;
}

float GGX::Lambda(RtVector3 const& w, Roughness a) {
    // TODO (exercise 1): Smith's Lambda(w) for GGX, w a unit direction with w.z > 0.
    //   Lambda = (sqrt(1 + t) - 1) / 2,   t = (au^2 wx^2 + av^2 wy^2) / wz^2
    // Written this way it loses every digit when t is tiny (a polished surface):
    // rewrite it without the subtraction (chapter 9, "Masking").
    PIXAR_ARGUSED(w);
    PIXAR_ARGUSED(a);
    return 0.0f;
}

RtVector3 GGX::sampleNormals(RtFloat2 const& xi, Roughness a) {
    // phi as in Ward's sampler; the CDF of tan^2(theta) is t / (1 + t) with
    // t = tan^2(theta) (cos^2 phi / au^2 + sin^2 phi / av^2).
    float phi = std::atan2(a.v * std::sin(F_TWOPI * xi[1]), a.u * std::cos(F_TWOPI * xi[1]));
    float cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    float inverseAlpha2 = cosPhi * cosPhi / (a.u * a.u) + sinPhi * sinPhi / (a.v * a.v);
    float tanTheta2 = xi[0] / (1.0f - xi[0]) / inverseAlpha2;  // xi[0] < 1
    float cosTheta = 1.0f / std::sqrt(1.0f + tanTheta2);
    float sinTheta = std::sqrt(RixMax(0.0f, 1.0f - cosTheta * cosTheta));
    return RtVector3(sinTheta * cosPhi, sinTheta * sinPhi, cosTheta);
}

RtVector3 GGX::sampleVisibleNormals(RtVector3 const& V, RtFloat2 const& xi, Roughness a) {
    // TODO (exercise 3): a microfacet normal drawn from the normals V sees, D_V(m), by the
    // five steps of chapter 9 ("Sampling the normals the viewer sees"): stretch V, build a
    // frame around it, draw a point on the visible half disk, lift it onto the hemisphere,
    // unstretch. Until then this returns N, a mirror reflection: the chi2 check will fail.
    PIXAR_ARGUSED(V);
    PIXAR_ARGUSED(xi);
    PIXAR_ARGUSED(a);
    return RtVector3(0.0f, 0.0f, 1.0f);
}

float GGX::pdf(RtVector3 const& V, RtVector3 const& L, Roughness a) const {
    if (L.z <= 0.0f || V.z <= 0.0f) return 0.0f;
    if (m_params.samplingMode == 0) return L.z * F_INVPI;
    RtVector3 H = Normalize(V + L);
    float VdotH = V.Dot(H);
    if (VdotH <= 0.0f) return 0.0f;
    // TODO (exercise 2): the density of L, derived in chapter 9 ("From normals to
    // directions"): the density of the normal H that mirrors V onto L, times the
    // Jacobian of the mirror map, which you derive there.
    //   samplingMode 1: normals drawn with density D(m) cos(theta_m)
    //   samplingMode 2: normals drawn with density D_V(m) = G1(V) max(0, V.m) D(m) / cos(theta_V)
    RIX_TODO(shadingCtx, "GGX::pdf");
    PIXAR_ARGUSED(a);
    return 0.0f;
}

bool GGX::evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const {
    weight = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    Frame f = frame(i);
    RtNormal3 Ng = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    RtVector3 V = f.toLocal(m_Vn[i]), L = f.toLocal(Ln);
    if (L.z <= 0.0f || V.z <= 0.0f || Ng.Dot(Ln) <= 0.0f) return false;

    Roughness a = roughness(i);
    // TODO (exercise 1): the weight W = f cos(theta_L), with f the microfacet BRDF of
    // GGX.h (F from schlick() with m_params.specularColor[i], D, and G2 from Lambda).
    // Simplify f cos(theta_L) before you code it: one cosine cancels.
    RIX_TODO(shadingCtx, "GGX::evaluate");
    PIXAR_ARGUSED(a);
    fpdf = pdf(V, L, a);
    rpdf = pdf(L, V, a);
    return true;
}

void GGX::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                         RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                         float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* specularW = W.AddActiveLobe(g_ggxSpecularLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples2D(xi);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_ggxTraits).HasAny()) continue;
        Frame f = frame(i);
        if (m_params.samplingMode == 0) {
            float cosTheta;
            RixCosDirectionalDistribution(xi[i], f.N, f.u, f.v, Ln[i], cosTheta);
        } else {
            Roughness a = roughness(i);
            RtVector3 V = f.toLocal(m_Vn[i]);
            RtVector3 m = m_params.samplingMode == 1 ? sampleNormals(xi[i], a) : sampleVisibleNormals(V, xi[i], a);
            Ln[i] = RixReflect(-m_Vn[i], f.toWorld(m));  // mirror V about the microfacet normal
        }
        bool reflects = evaluate(i, Ln[i], specularW[i], FPdf[i], RPdf[i]);
        if (!reflects || !(FPdf[i] > 0.0f)) continue;  // below the surface: invalid sample
        lobeSampled[i] = g_ggxSpecularLobe;
        lobeSampled[i].SetValid(true);
    }
}

void GGX::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                         RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                         float* RPdf) {
    RtColorRGB* specularW = W.AddActiveLobe(g_ggxSpecularLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        if ((all & lobesWanted[i] & g_ggxTraits).HasAny() && evaluate(i, Ln[i], specularW[i], FPdf[i], RPdf[i])) {
            lobesEvaluated[i] |= g_ggxTraits;
            lobesEvaluated[i].SetValid(true);
        }
    }
}

void GGX::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                 int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                 RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* specularW = W.AddActiveLobe(g_ggxSpecularLobe);
    bool wanted = (GetAllLobeTraits() & lobesWanted & g_ggxTraits).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        if (wanted && evaluate(index, Ln[s], specularW[s], FPdf[s], RPdf[s])) {
            lobesEvaluated[s] |= g_ggxTraits;
            lobesEvaluated[s].SetValid(true);
        }
    }
}
