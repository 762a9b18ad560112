// Chapter 9's microfacet toolkit, isotropic (one roughness alpha), for the
// glass of chapter 10. Every function works on unit vectors in a local frame
// whose z axis is the surface normal on the viewer's side.
//   D(m)      = alpha^2 / (pi (m.z^2 (alpha^2 - 1) + 1)^2)          (GGX, for m.z > 0)
//   Lambda(w) = (sqrt(1 + alpha^2 tan^2(theta_w)) - 1) / 2          (Smith)
//   G1(w)     = 1 / (1 + Lambda(w)),   G2(V, L) = 1 / (1 + Lambda(V) + Lambda(L))
// Lambda uses |w.z|: it is the same on both sides of the surface, which is
// what transmission needs.
// This file holds the answers to chapter 9's parts 1 and 3: do chapter 9 first.
#pragma once

#include <cmath>

#include "RixShadingUtils.h"

namespace ggx {

constexpr float kMinAlpha = 1e-4f;

inline float D(RtVector3 const& m, float alpha) {
    if (m.z <= 0.0f) return 0.0f;
    // alpha^2 / (pi t^2) with t = m.z^2 (alpha^2 - 1) + 1, written as
    // 1 / (pi alpha^2 s^2) with s = (m.x^2 + m.y^2) / alpha^2 + m.z^2: for a tiny
    // alpha, alpha^2 - 1 rounds to -1 and t to 0 along the normal; s stays 1.
    float a2 = alpha * alpha;
    float s = (m.x * m.x + m.y * m.y) / a2 + m.z * m.z;
    return 1.0f / (F_PI * a2 * s * s);
}

inline float Lambda(RtVector3 const& w, float alpha) {
    // t / (2 (sqrt(1 + t) + 1)) with t = alpha^2 tan^2: no cancellation when t is small.
    float z = std::fabs(w.z);
    float a2s2 = alpha * alpha * (w.x * w.x + w.y * w.y);
    return a2s2 / (2.0f * z * (z + std::sqrt(z * z + a2s2)));
}

inline float G1(RtVector3 const& w, float alpha) { return 1.0f / (1.0f + Lambda(w, alpha)); }

inline float G2(RtVector3 const& V, RtVector3 const& L, float alpha) {
    return 1.0f / (1.0f + Lambda(V, alpha) + Lambda(L, alpha));
}

/// A microfacet normal drawn with the density of the normals V sees,
///   D_V(m) = G1(V) max(0, V.m) D(m) / V.z     (Heitz 2018; V.z > 0).
inline RtVector3 sampleVisibleNormal(RtVector3 const& V, RtFloat2 const& xi, float alpha) {
    RtVector3 Vh = Normalize(RtVector3(alpha * V.x, alpha * V.y, V.z));
    float lengthSq = Vh.x * Vh.x + Vh.y * Vh.y;
    RtVector3 T1 = lengthSq > 0.0f ? RtVector3(-Vh.y, Vh.x, 0.0f) * (1.0f / std::sqrt(lengthSq))
                                   : RtVector3(1.0f, 0.0f, 0.0f);
    RtVector3 T2 = Vh.Cross(T1);
    float r = std::sqrt(xi[0]), phi = F_TWOPI * xi[1];
    float t1 = r * std::cos(phi), t2 = r * std::sin(phi);
    float s = 0.5f * (1.0f + Vh.z);
    t2 = (1.0f - s) * std::sqrt(RixMax(0.0f, 1.0f - t1 * t1)) + s * t2;
    RtVector3 Nh = T1 * t1 + T2 * t2 + Vh * std::sqrt(RixMax(0.0f, 1.0f - t1 * t1 - t2 * t2));
    return Normalize(RtVector3(alpha * Nh.x, alpha * Nh.y, RixMax(0.0f, Nh.z)));
}

}  // namespace ggx
