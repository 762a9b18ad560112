// Chapter 8 exercise: write each sampler and its pdf (see Sampling.h for
// the recipe). Until you do, each returns the normal direction with pdf 0,
// which callers treat as "no sample".
// RixShadingUtils.h has samplers of its own (chapter 6 uses them); here you
// write these yourself: the grader compiles this exercise with the API's
// samplers forbidden, and a call to one earns it no points.
#include "Sampling.h"

#include <cmath>

namespace sampling {

RtVector3 sampleUniformHemisphere(RtFloat2 const& xi, float* pdf) {
    // TODO: cos(theta) = 1 - xi[0], phi = 2 pi xi[1]; *pdf = 1 / (2 pi).
    PIXAR_ARGUSED(xi);
    *pdf = 0.0f;
    return RtVector3(0.0f, 0.0f, 1.0f);
}

float uniformHemispherePdf(RtVector3 const& w) {
    // TODO: 1 / (2 pi) above the surface (w.z > 0), 0 below.
    PIXAR_ARGUSED(w);
    return 0.0f;
}

RtVector3 sampleCosineHemisphere(RtFloat2 const& xi, float* pdf) {
    // TODO: cos(theta) = sqrt(1 - xi[0]), phi = 2 pi xi[1]; *pdf = cos(theta) / pi.
    PIXAR_ARGUSED(xi);
    *pdf = 0.0f;
    return RtVector3(0.0f, 0.0f, 1.0f);
}

float cosineHemispherePdf(RtVector3 const& w) {
    // TODO: w.z / pi above the surface, 0 below.
    PIXAR_ARGUSED(w);
    return 0.0f;
}

RtVector3 samplePhongLobe(RtFloat2 const& xi, float n, float* pdf) {
    // TODO: cos(alpha) = xi[0]^(1 / (n + 1)), phi = 2 pi xi[1]; *pdf = phongLobePdf(w, n).
    // Careful at xi[0] = 0: keep the pdf of a returned direction positive.
    PIXAR_ARGUSED(xi);
    PIXAR_ARGUSED(n);
    *pdf = 0.0f;
    return RtVector3(0.0f, 0.0f, 1.0f);
}

float phongLobePdf(RtVector3 const& w, float n) {
    // TODO: (n + 1) / (2 pi) * w.z^n above the surface, 0 below.
    PIXAR_ARGUSED(w);
    PIXAR_ARGUSED(n);
    return 0.0f;
}

}  // namespace sampling
