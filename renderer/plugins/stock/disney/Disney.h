// PxrDisney — Burley's "principled" BRDF (Burley 2012, "Physically Based
// Shading at Disney"), the material RenderMan 20-21 scenes and exporters use
// most. One artist-friendly set of parameters drives five terms:
//
//   f = (1 - metallic) [ mix(baseColor F_d, subsurfaceColor F_ss,        diffuse
//                            subsurface) / pi
//                        + sheen * C_sheen * (1 - L.H)^5 ]                sheen
//     + D_s(H) F_s(L.H) G_s(L, V) / (4 cos_L cos_V)                       specular
//     + clearcoat / 4 * D_c(H) F_c(L.H) G_c(L, V) / (4 cos_L cos_V)       clearcoat
//
// with H = normalize(L + V) and every cosine taken with the shading normal N
// (bumpNormal where a pattern gives one; light below the geometric surface
// still gets nothing, so a bent normal cannot let light through a wall).
//
// Diffuse, with Burley's retro-reflection at grazing angles:
//   F_d  = (1 + (F_D90 - 1)(1 - cos_L)^5) (1 + (F_D90 - 1)(1 - cos_V)^5),
//   F_D90 = 0.5 + 2 roughness (L.H)^2
// and its flattened "subsurface" variant (Hanrahan-Krueger-like):
//   F_ss = 1.25 [ S (1 / (cos_L + cos_V) - 0.5) + 0.5 ],
//   S = (1 + (F_SS90 - 1)(1 - cos_L)^5)(1 + (F_SS90 - 1)(1 - cos_V)^5), F_SS90 = roughness (L.H)^2.
// The flattened variant takes its own colour, subsurfaceColor: RenderMan's
// parameter is "the colour to mix with the diffuse response according to
// subsurface", black by default, so subsurface 1 with no subsurfaceColor has
// no diffuse at all, as in RenderMan.
//
// Specular: anisotropic GGX (Trowbridge-Reitz) with alpha = roughness^2
// stretched by aspect = sqrt(1 - 0.9 anisotropic):
//   alpha_u = alpha / aspect, alpha_v = alpha * aspect (both at least 0.001),
//   D_s(H) = 1 / (pi alpha_u alpha_v ((H.u/alpha_u)^2 + (H.v/alpha_v)^2 + (H.N)^2)^2),
//   G_s    = 1 / (1 + Lambda(L) + Lambda(V))       (Smith, height-correlated),
//   Lambda(w) = (sqrt(1 + ((alpha_u w.u)^2 + (alpha_v w.v)^2) / (w.N)^2) - 1) / 2,
//   F_s = C0 + (1 - C0)(1 - L.H)^5 (Schlick), with the colour at normal incidence
//   C0 = mix(0.08 specular mix(1, tint, specularTint), baseColor, metallic).
// Here tint = baseColor / its luminance (its hue at full brightness), as is
// C_sheen = mix(1, tint, sheenTint).
//
// Clearcoat: a fixed, isotropic second lobe of index 1.5 (F_c = Schlick with
// C0 = 0.04) whose highlight has a long tail (Burley's GTR1):
//   D_c(H) = (a^2 - 1) / (pi ln(a^2) (1 + (a^2 - 1)(H.N)^2)),  a = mix(0.1, 0.001, clearcoatGloss),
//   G_c    = Smith GGX with alpha 0.25.
//
// Sampling picks ONE term with probability proportional to its estimated
// albedo, samples a direction from it, and reports the mixture pdf:
//   diffuse and sheen: cosine-weighted, pdf cos_L / pi;
//   specular: GGX's distribution of VISIBLE normals (Heitz 2018), which never
//             proposes a normal facing away from V: pdf = G1(V) D_s(H) / (4 cos_V);
//   clearcoat: GTR1 half vectors, pdf = D_c(H) (H.N) / (4 L.H).
//
// Every term is symmetric in L and V, so f is reciprocal. f does not conserve
// energy exactly: the retro-reflection term is an empirical fit that can
// reflect a little more than 1 at grazing views with high roughness, and the
// specular lobe loses the energy of multiple scattering between microfacets.
//
// Parameters (RenderMan's names and defaults)
//   color baseColor       [0.2 0.5 0.8]
//   color emitColor       [0 0 0]        emitted radiance
//   float subsurface      [0]            0: Burley diffuse, 1: the flattened variant
//   color subsurfaceColor [0 0 0]        the flattened variant's colour
//   float metallic        [0]
//   float specular        [0.5]          0.5 is a reflectance of 4% (index 1.5)
//   float specularTint    [0]
//   float roughness       [0.25]
//   float anisotropic     [0]            0 isotropic .. 1 aspect 3.2 (along u = dPdu)
//   float sheen           [0]
//   float sheenTint       [0.5]
//   float clearcoat       [0]
//   float clearcoatGloss  [1]
//   normal bumpNormal     (connected only)  a bent shading normal, e.g. PxrNormalMap's resultN
// RIB
//   Bxdf "PxrDisney" "paint" "color baseColor" [0.8 0.1 0.1] "float clearcoat" [1] "float roughness" [0.4]
#pragma once

#include "RixBxdf.h"

/// The lobes PxrDisney reports (looked up by name at RenderBegin).
struct DisneyLobes {
    RixBXLobeSampled diffuse, specular, clearcoat;
    RixBXLobeTraits all;
};
extern DisneyLobes g_disneyLobes;

/// Per-point parameter arrays (numPts entries each).
struct DisneyParams {
    RtColorRGB const* baseColor;
    RtColorRGB const* emitColor;
    float const* subsurface;
    RtColorRGB const* subsurfaceColor;
    float const* metallic;
    float const* specular;
    float const* specularTint;
    float const* roughness;
    float const* anisotropic;
    float const* sheen;
    float const* sheenTint;
    float const* clearcoat;
    float const* clearcoatGloss;
    RtNormal3 const* bumpNormal;  ///< the normal to shade with where a pattern bends it, else nullptr
    bool anyAnisotropic;  ///< only then is the tangent frame asked for
};

class Disney : public RixBxdf {
public:
    Disney(RixShadingContext const* sc, RixBxdfFactory* factory, DisneyParams const& params);

    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { *lobes = g_disneyLobes.all; }
    bool EmitLocal(RtColorRGB* result) override;

    void GenerateSample(RixBXTransportTrait transportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                        RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                        float* RPdf, RtColorRGB* compTrans) override;
    void EvaluateSample(RixBXTransportTrait transportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                        RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                        float* RPdf) override;
    void EvaluateSamplesAtIndex(RixBXTransportTrait transportTrait, RixBXLobeTraits const& lobesWanted, RixRNG* rng,
                                int index, int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                RixBXLobeWeights& W, float* FPdf, float* RPdf) override;

    /// The shading point's parameters, resolved into what the formulas use.
    struct Point {
        RtNormal3 N;
        RtVector3 u, v;           ///< tangent frame (u along dPdu when anisotropic)
        RtColorRGB diffuseColor;     ///< (1 - metallic) baseColor
        RtColorRGB subsurfaceColor;  ///< (1 - metallic) subsurfaceColor
        RtColorRGB sheenColor;    ///< (1 - metallic) sheen C_sheen
        RtColorRGB specular0;     ///< C0
        float subsurface, roughness, alphaU, alphaV;
        float clearcoat, clearcoatAlpha;
        float pDiffuse, pSpecular, pClearcoat;  ///< lobe selection probabilities (sum 1)
    };

private:
    Point point(int i) const;
    /// The three terms' f cos_L for direction L, and the mixture pdfs both ways; false below the surface.
    bool evaluate(int i, RtVector3 const& L, RtColorRGB& diffuse, RtColorRGB& specular, RtColorRGB& clearcoat,
                  float& fpdf, float& rpdf) const;

    DisneyParams m_params;
    RtNormal3 const* m_Nn;
    RtNormal3 const* m_Ngn;
    RtVector3 const* m_Tn = nullptr;
    RtVector3 const* m_Vn;
};
