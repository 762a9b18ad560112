#include "GGX.h"

#include <cmath>

#include "RixShadingUtils.h"

RixBXLobeSampled g_ggxSpecularLobe;
RixBXLobeTraits g_ggxTraits;

namespace {
constexpr float kMinRoughness = 1e-4f;

/// Schlick's approximation of the Fresnel reflectance at cos(angle) c.
RtColorRGB schlick(RtColorRGB const& F0, float c) {
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
    // The form 1 / (pi au av (x^2/au^2 + y^2/av^2 + z^2)^2) stays finite for every
    // unit m, also when au is 1e-4 (the cos^4 tan^2 form divides 0 by 0 at the horizon).
    float s = m.x * m.x / (a.u * a.u) + m.y * m.y / (a.v * a.v) + m.z * m.z;
    return 1.0f / (F_PI * a.u * a.v * s * s);
}

float GGX::Lambda(RtVector3 const& w, Roughness a) {
    // (sqrt(1 + t) - 1) / 2 with t = (au^2 wx^2 + av^2 wy^2) / wz^2, rewritten as
    // t / (2 (sqrt(1 + t) + 1)) so that a small t does not cancel to 0 - 0.
    float a2 = a.u * a.u * w.x * w.x + a.v * a.v * w.y * w.y;
    float z = w.z;
    return a2 / (2.0f * z * (z + std::sqrt(z * z + a2)));
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
    // Stretch the view so that the surface becomes a hemisphere of roughness 1,
    // pick a point on the half disk the stretched view sees, lift it onto the
    // hemisphere and stretch back (Heitz 2018).
    RtVector3 Vh = Normalize(RtVector3(a.u * V.x, a.v * V.y, V.z));
    float lengthSq = Vh.x * Vh.x + Vh.y * Vh.y;
    RtVector3 T1 = lengthSq > 0.0f ? RtVector3(-Vh.y, Vh.x, 0.0f) * (1.0f / std::sqrt(lengthSq))
                                   : RtVector3(1.0f, 0.0f, 0.0f);
    RtVector3 T2 = Vh.Cross(T1);
    float r = std::sqrt(xi[0]), phi = F_TWOPI * xi[1];
    float t1 = r * std::cos(phi), t2 = r * std::sin(phi);
    float s = 0.5f * (1.0f + Vh.z);  // how much of the disk the view sees
    t2 = (1.0f - s) * std::sqrt(RixMax(0.0f, 1.0f - t1 * t1)) + s * t2;
    RtVector3 Nh = T1 * t1 + T2 * t2 + Vh * std::sqrt(RixMax(0.0f, 1.0f - t1 * t1 - t2 * t2));
    return Normalize(RtVector3(a.u * Nh.x, a.v * Nh.y, RixMax(0.0f, Nh.z)));
}

float GGX::pdf(RtVector3 const& V, RtVector3 const& L, Roughness a) const {
    if (L.z <= 0.0f || V.z <= 0.0f) return 0.0f;
    if (m_params.samplingMode == 0) return L.z * F_INVPI;
    RtVector3 H = Normalize(V + L);
    float VdotH = V.Dot(H);
    if (VdotH <= 0.0f) return 0.0f;
    // Mirroring V about H turns a density of normals into one of directions
    // with the Jacobian d(omega_H) / d(omega_L) = 1 / (4 V.H):
    //   mode 1: D(H) (N.H) / (4 V.H)
    //   mode 2: D_V(H) / (4 V.H) = G1(V) D(H) / (4 cos(theta_V))   (the V.H cancels)
    if (m_params.samplingMode == 1) return D(H, a) * H.z / (4.0f * VdotH);
    float G1 = 1.0f / (1.0f + Lambda(V, a));
    return G1 * D(H, a) / (4.0f * V.z);
}

bool GGX::evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const {
    weight = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    Frame f = frame(i);
    RtNormal3 Ng = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    RtVector3 V = f.toLocal(m_Vn[i]), L = f.toLocal(Ln);
    if (L.z <= 0.0f || V.z <= 0.0f || Ng.Dot(Ln) <= 0.0f) return false;

    Roughness a = roughness(i);
    RtVector3 H = Normalize(V + L);
    float G2 = 1.0f / (1.0f + Lambda(V, a) + Lambda(L, a));
    // W = f cos(theta_L) = F D G2 / (4 cos(theta_V))
    weight = schlick(m_params.specularColor[i], V.Dot(H)) * (D(H, a) * G2 / (4.0f * V.z));
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
