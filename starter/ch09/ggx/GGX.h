// ggx — a microfacet reflection model (chapter 9): the surface is made of
// tiny mirrors whose normals m follow the GGX (Trowbridge–Reitz)
// distribution D; Smith's masking-shadowing G2 removes the light that other
// microfacets block; Schlick's Fresnel F says how much each mirror reflects.
//
//   f(V, L) = F(V.H) D(H) G2(V, L) / (4 cos(theta_V) cos(theta_L)),   H = normalize(V + L)
//
// Everything is computed in the local frame (x along u, y along v, z along N):
//   D(m)      = 1 / (pi au av (mx^2/au^2 + my^2/av^2 + mz^2)^2)
//   Lambda(w) = (sqrt(1 + (au^2 wx^2 + av^2 wy^2) / wz^2) - 1) / 2
//   G1(w)     = 1 / (1 + Lambda(w)),   G2(V, L) = 1 / (1 + Lambda(V) + Lambda(L))
//   F(c)      = F0 + (1 - F0)(1 - c)^5
// and the weight a Bxdf returns is W = f cos(theta_L) = F D G2 / (4 cos(theta_V)).
//
// Sampling (samplingMode):
//   0  cosine-weighted directions, to compare;
//   1  microfacet normals m drawn with density D(m) cos(theta_m) (Walter et al. 2007);
//   2  the normals the viewer sees, drawn with density
//        D_V(m) = G1(V) max(0, V.m) D(m) / cos(theta_V)   (Heitz 2018).
// In modes 1 and 2, L is V mirrored about the sampled normal, and a sample
// that lands below the surface is invalid. What density of L that gives is
// for you to derive (chapter 9, "From normals to directions").
//
// Parameters
//   color specularColor  [1 1 1]   F0: the reflectance at normal incidence
//   float uRoughness     [0.2]     au, the roughness along u (clamped to at least 1e-4)
//   float vRoughness     [0.2]     av, along v = N x u
//   int   samplingMode   [2]       0 cosine, 1 distribution of normals, 2 visible normals
// RIB
//   Bxdf "ggx" "metal" "color specularColor" [0.95 0.64 0.54] "float uRoughness" [0.2] "float vRoughness" [0.2]
#pragma once

#include "RixBxdf.h"

extern RixBXLobeSampled g_ggxSpecularLobe;
extern RixBXLobeTraits g_ggxTraits;

struct GGXParams {
    RtColorRGB const* specularColor;
    float const* uRoughness;
    float const* vRoughness;
    int samplingMode;
};

class GGX : public RixBxdf {
public:
    GGX(RixShadingContext const* sc, RixBxdfFactory* factory, GGXParams const& params);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { *lobes = g_ggxTraits; }

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
        RtVector3 toLocal(RtVector3 const& w) const { return RtVector3(w.Dot(u), w.Dot(v), w.Dot(N)); }
        RtVector3 toWorld(RtVector3 const& w) const { return u * w.x + v * w.y + N * w.z; }
    };
    /// The roughness of point i, clamped away from a perfect mirror.
    struct Roughness {
        float u, v;
    };
    Frame frame(int i) const;
    Roughness roughness(int i) const;

    // The model, on unit vectors in the local frame (z is the normal).
    static float D(RtVector3 const& m, Roughness a);
    static float Lambda(RtVector3 const& w, Roughness a);
    static RtVector3 sampleNormals(RtFloat2 const& xi, Roughness a);
    static RtVector3 sampleVisibleNormals(RtVector3 const& V, RtFloat2 const& xi, Roughness a);
    /// The density of choosing L when the sampler starts from V.
    float pdf(RtVector3 const& V, RtVector3 const& L, Roughness a) const;

    bool evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const;

    GGXParams m_params;
    RtNormal3 const* m_Nn;
    RtNormal3 const* m_Ngn;
    RtVector3 const* m_Tn;
    RtVector3 const* m_Vn;
};
