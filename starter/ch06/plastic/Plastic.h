// plastic — a diffuse base under a glossy coat: the sum of two lobes,
//
//   f = rho_d / pi  +  ks (n + 2) / (2 pi) max(0, R.L)^n
//
// Sampling a sum: pick ONE lobe at random (with probability proportional to
// its albedo, so the brighter lobe gets more samples), sample a direction
// from it, and report the MIXTURE pdf
//
//   pdf(L) = p_d cos(theta_L) / pi  +  p_s (n + 1) / (2 pi) max(0, R.L)^n
//
// because either lobe could have produced L. The weight W is the full f cos
// (both lobes) at L, so W / pdf is an unbiased estimate whichever lobe was picked.
//
// Parameters
//   color diffuseColor   [0.5 0.5 0.5]   rho_d
//   color specularColor  [0.2 0.2 0.2]   ks
//   float gloss          [50]            n
//   int   normalize      [1]             as in the specular plugin
// A warning is given when rho_d + ks > 1 in some channel: such a surface
// would reflect more light than it receives.
// RIB
//   Bxdf "plastic" "red" "color diffuseColor" [0.6 0.05 0.05] "color specularColor" [0.3 0.3 0.3]
#pragma once

#include "RixBxdf.h"

extern RixBXLobeSampled g_plasticDiffuseLobe;
extern RixBXLobeSampled g_plasticSpecularLobe;
extern RixBXLobeTraits g_plasticTraits;  // both lobes

struct PlasticParams {
    RtColorRGB const* diffuseColor;
    RtColorRGB const* specularColor;
    float const* gloss;
    int normalize;
};

class Plastic : public RixBxdf {
public:
    Plastic(RixShadingContext const* sc, RixBxdfFactory* factory, PlasticParams const& params);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { *lobes = g_plasticTraits; }

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
    /// Probability of choosing the specular lobe at point i (by albedo).
    float specularProbability(int i) const;
    /// Both lobes' weights and the mixture pdfs for direction Ln at point i.
    bool evaluate(int i, RtVector3 const& Ln, RtColorRGB& diffuse, RtColorRGB& specular, float& fpdf, float& rpdf) const;
    float mixturePdf(int i, RtNormal3 const& N, RtVector3 const& from, RtVector3 const& to) const;

    PlasticParams m_params;
    RtNormal3 const* m_Nn;
    RtNormal3 const* m_Ngn;
    RtVector3 const* m_Vn;
};
