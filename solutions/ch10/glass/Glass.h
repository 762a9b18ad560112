// glass — a dielectric boundary (chapter 10): light that meets glass is
// partly reflected and partly refracted into it, in proportions given by
// Fresnel's equations, and the same happens again when it leaves.
//
// Two regimes, chosen per point by the roughness:
//   roughness 0   a smooth boundary: two DISCRETE lobes, the mirror direction
//                 and the refracted direction of Snell's law
//                     eta_V sin(theta_V) = eta_L sin(theta_L);
//   roughness > 0 a rough boundary of GGX microfacets (Walter et al. 2007):
//                 each microfacet is a smooth boundary with normal m.
//
// Which side is which: the outside is the side the geometric normal points to.
// eta_V is the refractive index on the viewer's side (1 outside, ior inside),
// eta_L the one on the other side. All formulas below are in the frame of
// the viewer's side: z is the normal turned toward V, so V.z > 0; L.z > 0 is
// reflection, L.z < 0 transmission.
//
// Radiance changes by (eta_V / eta_L)^2 when it crosses the boundary toward
// the viewer (the light is squeezed into a narrower cone), so
//   smooth:  reflection      W / FPdf = 1,              chosen with probability F
//            transmission    W / FPdf = T (eta_V/eta_L)^2, chosen with probability 1 - F
//            where F = F(cos theta_V) is the dielectric Fresnel reflectance (RixFresnelDielectric)
//            and T the transmissionColor.
//   rough:   reflection      H = normalize(V + L)
//                            W = F D(H) G2 / (4 V.z)
//            transmission    H = normalize(eta_V V + eta_L L), turned to z > 0, V.H > 0 > L.H
//                            W = T |V.H| |L.H| eta_V^2 (1 - F) D(H) G2 / (V.z (eta_V V.H + eta_L L.H)^2)
//            with F = F(V.H), GGX's D and the height-correlated Smith G2 of chapter 9.
// Sampling (rough): pick a visible microfacet normal H (GGXMicrofacets.h),
// then reflect about it with probability F(V.H), else refract through it.
// The density of L that gives is for you to derive (chapter 10).
//
// Parameters
//   float ior                [1.5]      refractive index inside (the side the normal points away from)
//   float roughness          [0]        GGX alpha; 0 is a perfectly smooth boundary
//   color transmissionColor  [1 1 1]    tint of the light each crossing lets through
// RIB
//   Bxdf "glass" "window" "float ior" [1.5] "float roughness" [0.1]
#pragma once

#include "RixBxdf.h"

extern RixBXLobeSampled g_glassMirrorLobe;       // discrete reflection (smooth)
extern RixBXLobeSampled g_glassRefractLobe;      // discrete transmission (smooth)
extern RixBXLobeSampled g_glassRoughReflectLobe;  // glossy reflection (rough)
extern RixBXLobeSampled g_glassRoughRefractLobe;  // glossy transmission (rough)
extern RixBXLobeTraits g_glassTraits;              // all four

struct GlassParams {
    float const* ior;
    float const* roughness;
    RtColorRGB const* transmissionColor;
};

class Glass : public RixBxdf {
public:
    Glass(RixShadingContext const* sc, RixBxdfFactory* factory, GlassParams const& params);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXBoth; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { *lobes = g_glassTraits; }

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
    /// The viewer's side of point i: its frame (z toward V) and the two refractive indices.
    struct Side {
        RtNormal3 N;     ///< the shading normal turned toward V
        RtNormal3 Ng;    ///< the geometric normal turned toward V
        RtVector3 u, v;  ///< tangents: (u, v, N) is the local frame
        float etaV, etaL;
        RtVector3 toLocal(RtVector3 const& w) const { return RtVector3(w.Dot(u), w.Dot(v), w.Dot(N)); }
        RtVector3 toWorld(RtVector3 const& w) const { return u * w.x + v * w.y + N * w.z; }
    };
    Side side(int i) const;
    float alpha(int i) const;
    bool smooth(int i) const { return !(m_params.roughness[i] > 0.0f); }

    /// The density of sampling L from V (local, V.z > 0) with the rough sampler.
    static float pdf(RtVector3 const& V, RtVector3 const& L, float etaV, float etaL, float a);
    /// The rough model at point i toward Ln (world): W, both pdfs, and which lobe. False: nothing.
    bool evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf, bool& transmits) const;
    /// Adds one evaluated direction to the lobe weights (rough lobes only: discrete lobes evaluate to nothing).
    bool evaluateInto(int i, RtVector3 const& Ln, RixBXLobeTraits const& lobesWanted, RixBXLobeWeights& W, int slot,
                      RixBXLobeTraits& evaluated, float& fpdf, float& rpdf) const;

    GlassParams m_params;
    RtNormal3 const* m_Nn;
    RtNormal3 const* m_Ngn;
    RtVector3 const* m_Tn;
    RtVector3 const* m_Vn;
};
