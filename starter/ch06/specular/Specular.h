// specular — the modified Phong highlight: a glossy lobe around the mirror
// direction R of the viewer.
//
//   f(V, L) = ks (n + 2) / (2 pi) max(0, R.L)^n      R = 2 (N.V) N - V
//   W       = f cos(theta_L)
//
// The factor (n + 2) / (2 pi) normalises the lobe: at normal incidence the
// surface reflects exactly ks of the light, whatever the exponent n (Lewis,
// "Making shaders more physically plausible", 1994). With `normalize 0` it is
// left out, as in the course text's first version: then the highlight gets
// dimmer as it gets sharper.
//
// Parameters
//   color specularColor  [1 1 1]   ks, the reflectance at normal incidence
//   float gloss          [20]      n, the Phong exponent (0 = broad, 1000 = mirror-like)
//   int   normalize      [1]       1: energy-normalised lobe; 0: the raw cos^n
//   int   samplingMode   [0]       0: cosine sampling (the course text's choice);
//                                  1: sample the Phong lobe itself (chapter 8)
// RIB
//   Bxdf "specular" "teal" "color specularColor" [0 0.8 0.6] "float gloss" [200]
#pragma once

#include "RixBxdf.h"

extern RixBXLobeSampled g_specularLobe;
extern RixBXLobeTraits g_specularTraits;

/// The parameters of one batch, one value per point.
struct SpecularParams {
    RtColorRGB const* specularColor;
    float const* gloss;
    int normalize;
    int samplingMode;
};

class Specular : public RixBxdf {
public:
    Specular(RixShadingContext const* sc, RixBxdfFactory* factory, SpecularParams const& params);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { *lobes = g_specularTraits; }

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
    /// W and both pdfs for direction Ln at point i; false when Ln gets nothing.
    bool evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const;
    /// The density with which GenerateSample picks `to` when looking from `from`.
    float pdf(int i, RtNormal3 const& N, RtVector3 const& from, RtVector3 const& to) const;

    SpecularParams m_params;
    RtNormal3 const* m_Nn;
    RtNormal3 const* m_Ngn;
    RtVector3 const* m_Vn;
};
