#include "Sampling.h"

#include <cmath>

namespace sampling {
namespace {

/// The direction with polar cosine cosTheta and azimuth 2 pi u.
RtVector3 spherical(float cosTheta, float u) {
    float sinTheta = std::sqrt(std::fmax(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = F_TWOPI * u;
    return RtVector3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

}  // namespace

// p(theta) = sin(theta) on [0, pi/2]; CDF = 1 - cos(theta) = xi0.
RtVector3 sampleUniformHemisphere(RtFloat2 const& xi, float* pdf) {
    *pdf = F_INVTWOPI;
    return spherical(1.0f - xi[0], xi[1]);
}

float uniformHemispherePdf(RtVector3 const& w) { return w.z > 0.0f ? F_INVTWOPI : 0.0f; }

// p(theta) = 2 cos(theta) sin(theta); CDF = sin^2(theta) = xi0, so cos(theta) = sqrt(1 - xi0).
RtVector3 sampleCosineHemisphere(RtFloat2 const& xi, float* pdf) {
    float cosTheta = std::sqrt(std::fmax(0.0f, 1.0f - xi[0]));
    *pdf = cosTheta * F_INVPI;
    return spherical(cosTheta, xi[1]);
}

float cosineHemispherePdf(RtVector3 const& w) { return w.z > 0.0f ? w.z * F_INVPI : 0.0f; }

// p(alpha) = (n + 1) cos^n(alpha) sin(alpha); CDF = 1 - cos^(n+1)(alpha). Using
// 1 - xi0 (equally uniform) gives cos(alpha) = xi0^(1/(n+1)).
RtVector3 samplePhongLobe(RtFloat2 const& xi, float n, float* pdf) {
    // xi0 = 0 would give cos(alpha) = 0 (a grazing direction with zero pdf):
    // nudge it to the smallest float so the pdf stays positive.
    float u = std::fmax(xi[0], 0x1p-24f);
    float cosAlpha = std::pow(u, 1.0f / (n + 1.0f));
    RtVector3 w = spherical(cosAlpha, xi[1]);
    *pdf = phongLobePdf(w, n);
    return w;
}

float phongLobePdf(RtVector3 const& w, float n) {
    if (w.z <= 0.0f) return 0.0f;
    return (n + 1.0f) * F_INVTWOPI * std::pow(w.z, n);
}

}  // namespace sampling
