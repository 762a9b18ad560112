// RixShadingUtils.h — small, robust helpers for writing Bxdfs.
//
// Everything here is inline and self-contained. Directions follow the course
// convention: V and L point AWAY from the surface; N is a unit normal.
#pragma once

#include <cmath>

#include "RiTypesHelper.h"

// ---------------------------------------------------------------- scalars

template <typename T> PRMAN_INLINE T RixMin(T a, T b) { return a < b ? a : b; }
template <typename T> PRMAN_INLINE T RixMax(T a, T b) { return a > b ? a : b; }
template <typename T> PRMAN_INLINE T RixClamp(T x, T lo, T hi) { return x < lo ? lo : (x > hi ? hi : x); }
/// Linear interpolation: a at t = 0, b at t = 1.
template <typename T> PRMAN_INLINE T RixMix(T const& a, T const& b, float t) { return a * (1.0f - t) + b * t; }
/// 0 below lo, 1 above hi, a smooth cubic in between.
PRMAN_INLINE float RixSmoothStep(float lo, float hi, float x) {
    if (x <= lo) return 0.0f;
    if (x >= hi) return 1.0f;
    float t = (x - lo) / (hi - lo);
    return t * t * (3.0f - 2.0f * t);
}
PRMAN_INLINE void RixSinCos(float angle, float* sine, float* cosine) {
    *sine = std::sin(angle);
    *cosine = std::cos(angle);
}
/// x minus its floor, in [0, 1): where x lies within its repeat (also below 0).
PRMAN_INLINE float RixFractional(float x) { return x - std::floor(x); }
PRMAN_INLINE float RixDegreesToRadians(float degrees) { return degrees * (F_PI / 180.0f); }
PRMAN_INLINE float RixRadiansToDegrees(float radians) { return radians * (180.0f / F_PI); }
/// Rec. 709 luminance of a linear colour.
PRMAN_INLINE float RixLuminance(RtColorRGB const& c) { return c.Luminance(); }

// ---------------------------------------------------------------- frames

/// Builds an orthonormal frame (TX, TY, N) around the unit normal N, with TX
/// as close to the tangent T as possible. Robust when T is zero, not unit
/// length, or parallel to N: then an arbitrary but continuous TX is chosen
/// (N.CreateOrthonormalBasis's first vector).
/// TY = N x TX.
PRMAN_INLINE void RixComputeShadingBasis(RtNormal3 const& N, RtVector3 const& T, RtVector3& TX, RtVector3& TY) {
    RtVector3 tangent = T - N * N.Dot(T);  // Gram-Schmidt: remove the normal part
    float lenSq = tangent.LengthSq();
    if (lenSq > 1e-12f && lenSq > 1e-8f * T.LengthSq()) {
        TX = tangent / std::sqrt(lenSq);
    } else {
        RtFloat3 unused;
        N.CreateOrthonormalBasis(TX, unused);
    }
    TY = N.Cross(TX);
}

/// The normal flipped, if needed, to lie on the same side as V.
PRMAN_INLINE RtNormal3 RixGetForwardFacingNormal(RtVector3 const& V, RtNormal3 const& N) {
    return N.Dot(V) < 0.0f ? RtNormal3(-N) : N;
}
/// Same, also returning N.V (>= 0) for the flipped normal.
PRMAN_INLINE RtNormal3 RixGetForwardFacingNormal(RtVector3 const& V, RtNormal3 const& N, float* NdV) {
    RtNormal3 Nf = RixGetForwardFacingNormal(V, N);
    *NdV = Nf.Dot(V);
    return Nf;
}
/// The normal flipped, if needed, to lie on the side opposite V.
PRMAN_INLINE RtNormal3 RixGetBackwardFacingNormal(RtVector3 const& V, RtNormal3 const& N) {
    return N.Dot(V) > 0.0f ? RtNormal3(-N) : N;
}

// ---------------------------------------------------------------- reflection and refraction

/// Mirror reflection of an INCIDENT direction I (pointing toward the surface),
/// as in RSL's reflect(): I - 2 (I.N) N. To reflect the view direction Vn (which
/// points away), use RixReflect(-Vn, N), which equals 2 (N.V) N - V.
PRMAN_INLINE RtVector3 RixReflect(RtVector3 const& I, RtNormal3 const& N) {
    return I - N * (2.0f * I.Dot(N));
}

/// Refraction of an INCIDENT direction I (toward the surface) through a
/// boundary with normal N (facing against I) and eta = n_incident / n_transmitted.
/// Returns false (and T = 0) on total internal reflection.
PRMAN_INLINE bool RixRefract(RtVector3 const& I, RtNormal3 const& N, float eta, RtVector3& T) {
    float cosI = -I.Dot(N);
    float sin2T = eta * eta * RixMax(0.0f, 1.0f - cosI * cosI);
    if (sin2T >= 1.0f) {
        T = RtVector3(0.0f, 0.0f, 0.0f);
        return false;
    }
    float cosT = std::sqrt(1.0f - sin2T);
    T = I * eta + N * (eta * cosI - cosT);
    return true;
}

/// Unpolarised Fresnel reflectance of a dielectric boundary for an incident
/// cosine cosTheta (>= 0 on the incident side) and eta = n_incident / n_transmitted.
/// Total internal reflection gives Kr = 1.
PRMAN_INLINE void RixFresnelDielectric(float cosTheta, float eta, float* Kr) {
    float cosI = RixClamp(std::fabs(cosTheta), 0.0f, 1.0f);
    float sin2T = eta * eta * (1.0f - cosI * cosI);
    if (sin2T >= 1.0f) {
        *Kr = 1.0f;
        return;
    }
    float cosT = std::sqrt(1.0f - sin2T);
    // Perpendicular and parallel amplitude ratios (Hecht, Optics, ch. 4).
    float rPerp = (eta * cosI - cosT) / (eta * cosI + cosT);
    float rPar = (cosI - eta * cosT) / (cosI + eta * cosT);
    *Kr = RixClamp(0.5f * (rPerp * rPerp + rPar * rPar), 0.0f, 1.0f);
}

/// Fresnel at a dielectric boundary seen from direction V (pointing away from
/// the surface) with unit normal N on V's side, eta = n_outside / n_inside
/// (e.g. 1/1.5 for air over a varnish). Outputs (each may be null):
///   Kr    reflectance, in [0, 1]
///   Rdir  the mirror direction 2 (N.V) N - V
///   Tdir  the transmitted direction, or the zero vector on total internal
///         reflection (then Kr = 1).
/// Like V, Rdir and Tdir point AWAY from the shading point: Rdir is where light
/// must come from to reflect toward V, Tdir where it must come from (inside the
/// surface) to refract toward V. Tdir is therefore the eye ray -V bent into the
/// surface, ready to use as a transmission sample's Ln; the path light takes
/// inside the surface on its way out to the viewer is -Tdir.
/// If V is below N the normal is flipped so the formulas stay valid.
PRMAN_INLINE void RixFresnelDielectric(RtVector3 const& V, RtNormal3 const& N, float eta, float* Kr,
                                       RtVector3* Rdir, RtVector3* Tdir) {
    RtNormal3 Nf = RixGetForwardFacingNormal(V, N);
    float cosI = RixClamp(Nf.Dot(V), 0.0f, 1.0f);
    float kr = 1.0f;
    RixFresnelDielectric(cosI, eta, &kr);
    if (Kr) *Kr = kr;
    if (Rdir) *Rdir = Nf * (2.0f * cosI) - V;
    if (Tdir) {
        RtVector3 T;
        if (!RixRefract(-V, Nf, eta, T)) {
            T = RtVector3(0.0f, 0.0f, 0.0f);
            if (Kr) *Kr = 1.0f;
        }
        *Tdir = T;
    }
}

// ---------------------------------------------------------------- hemisphere sampling
//
// Each sampler maps a uniform 2-D sample xi in [0,1)^2 to a direction in the
// hemisphere around N and returns its cosine with N. The density of the
// result is stated next to each; use it as FPdf.

/// The direction at polar angle theta from the unit axis A (given as the
/// angle's cosine and sine) and azimuth phi from TX toward TY, in the
/// orthonormal frame (TX, TY, A). Every sampler below ends here; so can yours.
PRMAN_INLINE RtVector3 RixDirectionFromAngles(float cosTheta, float sinTheta, float phi, RtVector3 const& A,
                                              RtVector3 const& TX, RtVector3 const& TY) {
    float sinPhi, cosPhi;
    RixSinCos(phi, &sinPhi, &cosPhi);
    return TX * (sinTheta * cosPhi) + TY * (sinTheta * sinPhi) + A * cosTheta;
}

/// Cosine-weighted direction: pdf = cosTheta / pi.
/// cos(theta) = sqrt(1 - xi0), phi = 2 pi xi1; cosTheta > 0 for every xi0 < 1.
PRMAN_INLINE void RixCosDirectionalDistribution(RtFloat2 const& xi, RtNormal3 const& N, RtVector3 const& TX,
                                                RtVector3 const& TY, RtVector3& out, float& cosTheta) {
    float c = std::sqrt(RixMax(0.0f, 1.0f - xi[0]));
    out = RixDirectionFromAngles(c, std::sqrt(RixMax(0.0f, xi[0])), F_TWOPI * xi[1], N, TX, TY);
    cosTheta = c;
}
/// Cosine-weighted direction around N in a frame built from N alone.
PRMAN_INLINE void RixCosDirectionalDistribution(RtFloat2 const& xi, RtNormal3 const& N, RtVector3& out,
                                                float& cosTheta) {
    RtVector3 TX, TY;
    RixComputeShadingBasis(N, RtVector3(0.0f, 0.0f, 0.0f), TX, TY);
    RixCosDirectionalDistribution(xi, N, TX, TY, out, cosTheta);
}

/// Uniform direction over the hemisphere: pdf = 1 / (2 pi).
/// cos(theta) = 1 - xi0, phi = 2 pi xi1.
PRMAN_INLINE void RixUniformDirectionalDistribution(RtFloat2 const& xi, RtNormal3 const& N, RtVector3 const& TX,
                                                    RtVector3 const& TY, RtVector3& out, float& cosTheta) {
    float c = 1.0f - xi[0];
    out = RixDirectionFromAngles(c, std::sqrt(RixMax(0.0f, 1.0f - c * c)), F_TWOPI * xi[1], N, TX, TY);
    cosTheta = c;
}
/// Uniform hemisphere direction around N in a frame built from N alone.
PRMAN_INLINE void RixUniformDirectionalDistribution(RtFloat2 const& xi, RtNormal3 const& N, RtVector3& out,
                                                    float& cosTheta) {
    RtVector3 TX, TY;
    RixComputeShadingBasis(N, RtVector3(0.0f, 0.0f, 0.0f), TX, TY);
    RixUniformDirectionalDistribution(xi, N, TX, TY, out, cosTheta);
}

/// The density of the normalised Phong lobe about an axis, for a direction at
/// cosine cosAlpha from it: (n + 1) / (2 pi) cos^n(alpha), 0 behind the axis.
/// (A course helper, not part of RenderMan's API: chapter 8 derives it.)
PRMAN_INLINE float RixPhongLobePdf(float cosAlpha, float n) {
    if (cosAlpha <= 0.0f) return 0.0f;
    return (n + 1.0f) * F_INVTWOPI * std::pow(cosAlpha, n);
}

/// A direction distributed as the Phong lobe cos^n(alpha) about the unit axis
/// A, with density RixPhongLobePdf: cos(alpha) = xi0^(1 / (n + 1)),
/// phi = 2 pi xi1. xi0 = 0 is taken as 2^-24, so the direction returned
/// always has a positive density. (A course helper: chapter 8 derives it.)
PRMAN_INLINE void RixPhongLobeDirectionalDistribution(RtFloat2 const& xi, float n, RtVector3 const& A,
                                                      RtVector3& out, float& cosAlpha) {
    float c = std::pow(RixMax(xi[0], 5.9604645e-8f), 1.0f / (n + 1.0f));
    RtVector3 TX, TY;
    RixComputeShadingBasis(A, RtVector3(0.0f, 0.0f, 0.0f), TX, TY);
    out = RixDirectionFromAngles(c, std::sqrt(RixMax(0.0f, 1.0f - c * c)), F_TWOPI * xi[1], A, TX, TY);
    cosAlpha = c;
}
