// ward — Ward's anisotropic Gaussian highlight (Ward 1992), in the form
// corrected by Walter (2005), plus an optional diffuse base.
//
//   f_s(V, L) = rho_s / (4 pi au av sqrt(cos(theta_L) cos(theta_V)))
//               * exp( -((H.u / au)^2 + (H.v / av)^2) / (H.N)^2 )
//
// with H = L + V (its length cancels in the ratio), u and v the tangent
// directions (u from dPdu, v = N x u), and au, av the roughness across u and v:
// a highlight on brushed metal is stretched ACROSS the brushing direction.
//
// Sampling (samplingMode 1, Walter 2005): choose the half vector H from
//   phi_h   = atan(av/au tan(2 pi xi1))        (kept in xi1's quadrant)
//   theta_h = atan(sqrt(-ln(xi0) / (cos^2(phi_h)/au^2 + sin^2(phi_h)/av^2)))
// reflect V about H to get L (invalid if L is below the surface), and
//   pdf(L) = exp(-tan^2(theta_h)(cos^2/au^2 + sin^2/av^2)) / (4 pi au av (H.V) cos^3(theta_h)).
// (1 - xi0 is used for xi0: equally uniform, and it never takes the log of 0.)
// samplingMode 0 samples the cosine distribution instead, to compare.
//
// Parameters
//   color specularColor  [1 1 1]     rho_s
//   float uRoughness     [0.2]       au (clamped to at least 1e-4)
//   float vRoughness     [0.2]       av
//   color diffuseColor   [0 0 0]     rho_d of a Lambertian base (chosen by albedo when sampling)
//   int   samplingMode   [1]         0: cosine, 1: Walter importance sampling
// RIB
//   Bxdf "ward" "brushed" "color specularColor" [0 1 1] "float uRoughness" [0.2] "float vRoughness" [1.0]
#pragma once

#include "RixBxdf.h"

extern RixBXLobeSampled g_wardSpecularLobe;
extern RixBXLobeSampled g_wardDiffuseLobe;
extern RixBXLobeTraits g_wardTraits;

struct WardParams {
    RtColorRGB const* specularColor;
    RtColorRGB const* diffuseColor;
    float const* uRoughness;
    float const* vRoughness;
    int samplingMode;
};

class Ward : public RixBxdf {
public:
    Ward(RixShadingContext const* sc, RixBxdfFactory* factory, WardParams const& params);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { *lobes = g_wardTraits; }

    void GenerateSample(RixBXTransportTrait transportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                        RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                        float* RPdf, RtColorRGB* compTrans) override;
    void EvaluateSample(RixBXTransportTrait transportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                        RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                        float* RPdf) override;
    void EvaluateSamplesAtIndex(RixBXTransportTrait transportTrait, RixBXLobeTraits const& lobesWanted, RixRNG* rng,
                                int index, int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                RixBXLobeWeights& W, float* FPdf, float* RPdf) override;

private:
    /// The shading frame at point i: N toward the viewer, u along dPdu, v = N x u.
    struct Frame {
        RtNormal3 N;
        RtVector3 u, v;
    };
    Frame frame(int i) const;
    float diffuseProbability(int i) const;
    /// Walter's density of choosing `to` by reflecting `from` about a sampled H.
    float wardPdf(int i, Frame const& f, RtVector3 const& from, RtVector3 const& to) const;
    float pdf(int i, Frame const& f, RtVector3 const& from, RtVector3 const& to) const;
    bool evaluate(int i, RtVector3 const& Ln, RtColorRGB& specular, RtColorRGB& diffuse, float& fpdf,
                  float& rpdf) const;

    WardParams m_params;
    RtNormal3 const* m_Nn;
    RtNormal3 const* m_Ngn;
    RtVector3 const* m_Tn;
    RtVector3 const* m_Vn;
};
