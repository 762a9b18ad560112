// diffuse — the Lambertian reflector: light is scattered equally in every
// direction above the surface.
//
//   f(V, L) = rho / pi                (rho: the albedo, diffuseColor)
//   W       = f |cos theta_L| = rho cos(theta_L) / pi
//
// Sampling: cosine-weighted directions, pdf(L) = cos(theta_L) / pi, which is
// exactly proportional to W, so W / pdf = rho for every sample: the best
// possible importance sampling for this Bxdf.
//
// Parameters
//   color diffuseColor   [0.8 0.8 0.8]   albedo: the fraction of light reflected
//   int   samplingMode   [0]             0: cosine-weighted (the best choice);
//                                        1: uniform over the hemisphere, pdf 1/(2 pi),
//                                        to compare in the chapter 4 study
//
// RIB
//   Bxdf "diffuse" "white" "color diffuseColor" [1 1 1]
//
// The surface is two-sided: whichever side the viewer is on reflects.
#pragma once

#include "RixBxdf.h"

/// The lobe this Bxdf reports (looked up by the factory at render begin).
extern RixBXLobeSampled g_diffuseLobe;
extern RixBXLobeTraits g_diffuseTraits;

class Diffuse : public RixBxdf {
public:
    /// `albedo` holds one colour per shade point.
    Diffuse(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB const* albedo, int samplingMode = 0);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { *lobes = g_diffuseTraits; }

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
    /// f*cos and both pdfs for one (V, L) pair at point i. Returns false (all
    /// zero) when L is not on the viewer's side of the surface.
    bool evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const;

    RtColorRGB const* m_albedo;
    int m_samplingMode;
    RtNormal3 const* m_Nn;   // shading normals
    RtNormal3 const* m_Ngn;  // geometric normals
    RtVector3 const* m_Vn;   // directions toward the viewer
};
