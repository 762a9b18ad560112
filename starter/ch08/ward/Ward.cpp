#include "Todo.h"
#include "Ward.h"

#include <cmath>

#include "RixShadingUtils.h"

RixBXLobeSampled g_wardSpecularLobe;
RixBXLobeSampled g_wardDiffuseLobe;
RixBXLobeTraits g_wardTraits;

namespace {
constexpr float kMinRoughness = 1e-4f;

[[maybe_unused]] float roughness(float a) { return RixMax(a, kMinRoughness); }
}  // namespace

Ward::Ward(RixShadingContext const* sc, RixBxdfFactory* factory, WardParams const& params)
    : RixBxdf(sc, factory), m_params(params) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Tn, &m_Tn);  // anisotropy needs the tangent
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

Ward::Frame Ward::frame(int i) const {
    Frame f;
    f.N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
    // Robust when Tn is zero (a sphere's pole) or along N: any frame will do there.
    RixComputeShadingBasis(f.N, m_Tn[i], f.u, f.v);
    return f;
}

float Ward::diffuseProbability(int i) const {
    float d = RixMax(m_params.diffuseColor[i].Luminance(), 0.0f);
    float s = RixMax(m_params.specularColor[i].Luminance(), 0.0f);
    return d + s > 0.0f ? d / (d + s) : 0.0f;
}

float Ward::wardPdf(int i, Frame const& f, RtVector3 const& from, RtVector3 const& to) const {
    RtVector3 H = Normalize(from + to);
    float cosH = f.N.Dot(H), HdV = H.Dot(from);
    if (cosH <= 0.0f || HdV <= 0.0f) return 0.0f;
    // TODO: the density of Walter's sampling, for H = normalize(from + to):
    //   exp(-((H.u/au)^2 + (H.v/av)^2) / (H.N)^2) / (4 pi au av (H.from) (H.N)^3)
    PIXAR_ARGUSED(i);
    RIX_TODO(shadingCtx, "Ward::wardPdf");
    return 0.0f;
}

float Ward::pdf(int i, Frame const& f, RtVector3 const& from, RtVector3 const& to) const {
    float cosTo = f.N.Dot(to);
    if (cosTo <= 0.0f) return 0.0f;
    if (m_params.samplingMode == 0) return cosTo * F_INVPI;
    float pDiffuse = diffuseProbability(i);
    return pDiffuse * cosTo * F_INVPI + (1.0f - pDiffuse) * wardPdf(i, f, from, to);
}

bool Ward::evaluate(int i, RtVector3 const& Ln, RtColorRGB& specular, RtColorRGB& diffuse, float& fpdf,
                    float& rpdf) const {
    specular = diffuse = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    Frame f = frame(i);
    RtNormal3 Ng = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    float cosL = f.N.Dot(Ln), cosV = f.N.Dot(m_Vn[i]);
    if (cosL <= 0.0f || cosV <= 0.0f || Ng.Dot(Ln) <= 0.0f) return false;

    // TODO: the Ward (Walter) specular weight, W = f * cos(theta_L):
    //   H = Ln + V (unnormalised), au/av = roughness(m_params.uRoughness[i]) / (...vRoughness[i])
    //   exponent = -((H.u/au)^2 + (H.v/av)^2) / (H.N)^2        (f.u, f.v, f.N: the frame)
    //   specular = rho_s * exp(exponent) / (4 pi au av) * sqrt(cosL / cosV)
    RIX_TODO(shadingCtx, "Ward::evaluate (specular lobe)");
    diffuse = m_params.diffuseColor[i] * (cosL * F_INVPI);
    fpdf = pdf(i, f, m_Vn[i], Ln);
    rpdf = pdf(i, f, Ln, m_Vn[i]);
    return true;
}

void Ward::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                          RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                          float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* specularW = W.AddActiveLobe(g_wardSpecularLobe);
    RtColorRGB* diffuseW = W.AddActiveLobe(g_wardDiffuseLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    float* choice = static_cast<float*>(RixAlloca(sizeof(float) * n));
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples1D(choice);
    rng->DrawSamples2D(xi);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_wardTraits).HasAny()) continue;
        Frame f = frame(i);
        bool diffuse = m_params.samplingMode == 0 || choice[i] < diffuseProbability(i);
        if (diffuse) {
            float cosTheta;
            RixCosDirectionalDistribution(xi[i], f.N, f.u, f.v, Ln[i], cosTheta);
        } else {
            // TODO: Walter's importance sampling of the half vector H (see Ward.h):
            //   phi_h = atan2(av sin(2 pi xi1), au cos(2 pi xi1))
            //   tan^2(theta_h) = -log(1 - xi0) / (cos^2(phi_h)/au^2 + sin^2(phi_h)/av^2)
            //   H = u sin(theta_h) cos(phi_h) + v sin(theta_h) sin(phi_h) + N cos(theta_h)
            //   Ln[i] = RixReflect(-m_Vn[i], H)
            RIX_TODO(shadingCtx, "Ward::GenerateSample (Walter sampling)");
            Ln[i] = -f.N;  // below the surface: the sample becomes invalid
        }
        bool reflects = evaluate(i, Ln[i], specularW[i], diffuseW[i], FPdf[i], RPdf[i]);
        if (!reflects || !(FPdf[i] > 0.0f)) continue;  // below the surface: invalid sample
        lobeSampled[i] = diffuse && m_params.samplingMode != 0 ? g_wardDiffuseLobe : g_wardSpecularLobe;
        lobeSampled[i].SetValid(true);
    }
}

void Ward::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                          RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                          float* RPdf) {
    RtColorRGB* specularW = W.AddActiveLobe(g_wardSpecularLobe);
    RtColorRGB* diffuseW = W.AddActiveLobe(g_wardDiffuseLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        if ((all & lobesWanted[i] & g_wardTraits).HasAny() &&
            evaluate(i, Ln[i], specularW[i], diffuseW[i], FPdf[i], RPdf[i])) {
            lobesEvaluated[i] |= g_wardTraits;
            lobesEvaluated[i].SetValid(true);
        }
    }
}

void Ward::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                  int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                  RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* specularW = W.AddActiveLobe(g_wardSpecularLobe);
    RtColorRGB* diffuseW = W.AddActiveLobe(g_wardDiffuseLobe);
    bool wanted = (GetAllLobeTraits() & lobesWanted & g_wardTraits).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        if (wanted && evaluate(index, Ln[s], specularW[s], diffuseW[s], FPdf[s], RPdf[s])) {
            lobesEvaluated[s] |= g_wardTraits;
            lobesEvaluated[s].SetValid(true);
        }
    }
}
