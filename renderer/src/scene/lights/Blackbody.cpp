#include "scene/lights/Blackbody.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {
namespace {

/// Planck's law: spectral radiance at wavelength (nm) up to a constant factor.
double planck(double nm, double kelvin) {
    double const c2 = 1.4387769e7;  // h c / k in nm K
    double const lambda = nm;
    return 1.0 / (std::pow(lambda, 5.0) * (std::exp(c2 / (lambda * kelvin)) - 1.0));
}

/// The CIE 1931 colour-matching functions, as the multi-lobe Gaussian fit of
/// Wyman, Sloan and Shirley (2013).
double gauss(double x, double mu, double s1, double s2) {
    double t = (x - mu) / (x < mu ? s1 : s2);
    return std::exp(-0.5 * t * t);
}
Vec3 cieXYZ(double nm) {
    double x = 1.056 * gauss(nm, 599.8, 37.9, 31.0) + 0.362 * gauss(nm, 442.0, 16.0, 26.7) -
               0.065 * gauss(nm, 501.1, 20.4, 26.2);
    double y = 0.821 * gauss(nm, 568.8, 46.9, 40.5) + 0.286 * gauss(nm, 530.9, 16.3, 31.1);
    double z = 1.217 * gauss(nm, 437.0, 11.8, 36.0) + 0.681 * gauss(nm, 459.0, 26.0, 13.8);
    return Vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

}  // namespace

Vec3 blackbodyColor(float kelvin) {
    double const t = std::clamp(static_cast<double>(kelvin), 1000.0, 40000.0);
    double X = 0, Y = 0, Z = 0;
    for (double nm = 380.0; nm <= 780.0; nm += 5.0) {
        double power = planck(nm, t);
        Vec3 cmf = cieXYZ(nm);
        X += power * cmf.x;
        Y += power * cmf.y;
        Z += power * cmf.z;
    }
    // XYZ to linear Rec. 709, then scaled to luminance (Y) 1.
    double r = 3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z;
    double g = -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z;
    double b = 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z;
    Vec3 rgb(static_cast<float>(std::max(r, 0.0) / Y), static_cast<float>(std::max(g, 0.0) / Y),
             static_cast<float>(std::max(b, 0.0) / Y));
    float luminance = 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z;
    return luminance > 0.0f ? rgb / luminance : Vec3(1.0f);
}

}  // namespace bxdflab
