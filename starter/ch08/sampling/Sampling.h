// Chapter 8 exercise: turning uniform random numbers into directions.
//
// Every function works in a LOCAL frame whose z axis is the axis of the
// distribution (the surface normal, or the mirror direction for a Phong lobe),
// takes a 2-D uniform sample xi in [0,1)^2, and returns a unit direction and
// its density (pdf, per unit solid angle). Each sampler has its pdf function
// next to it, so a test can check that the two agree.
//
// The recipe for all three (inverse-CDF sampling): write the density in
// spherical coordinates, p(theta, phi) = pdf(w) sin(theta); integrate over phi
// to get the marginal p(theta); invert its CDF with xi[0]; phi = 2 pi xi[1].
#pragma once

#include "RiTypesHelper.h"

namespace sampling {

/// Uniform over the hemisphere z > 0: pdf = 1 / (2 pi).  cos(theta) = 1 - xi0.
RtVector3 sampleUniformHemisphere(RtFloat2 const& xi, float* pdf);
float uniformHemispherePdf(RtVector3 const& w);

/// Cosine-weighted (Malley): pdf = cos(theta) / pi.  cos(theta) = sqrt(1 - xi0).
RtVector3 sampleCosineHemisphere(RtFloat2 const& xi, float* pdf);
float cosineHemispherePdf(RtVector3 const& w);

/// Phong lobe of exponent n about z: pdf = (n + 1) / (2 pi) cos^n(alpha),
/// cos(alpha) = xi0^(1 / (n + 1)). Directions below z = 0 never occur.
RtVector3 samplePhongLobe(RtFloat2 const& xi, float n, float* pdf);
float phongLobePdf(RtVector3 const& w, float n);

/// Expresses a local direction in the frame (TX, TY, N).
inline RtVector3 toWorld(RtVector3 const& local, RtVector3 const& TX, RtVector3 const& TY, RtVector3 const& N) {
    return TX * local.x + TY * local.y + N * local.z;
}
/// Expresses a world direction in the frame (TX, TY, N).
inline RtVector3 toLocal(RtVector3 const& w, RtVector3 const& TX, RtVector3 const& TY, RtVector3 const& N) {
    return RtVector3(w.Dot(TX), w.Dot(TY), w.Dot(N));
}

}  // namespace sampling
