// RenderMan's light shaping for flat lights (PxrRectLight, PxrDiskLight):
// how the radiance a light sends depends on the angle theta between its
// emitting normal and the direction of emission.
//
//   cone:  1 for theta <= theta_soft, 0 for theta >= theta_cut, and a smooth
//          step between, where theta_cut = coneAngle (at most 90 degrees) and
//          theta_soft = theta_cut (1 - coneSoftness), as UsdLux's ShapingAPI
//          (whose cone angle and softness hdPrman hands to these parameters)
//          defines them;
//   focus: cos(theta)^emissionFocus, the light pulled toward the normal; what
//          it takes away is given back in emissionFocusTint (black by default).
//
// The factor multiplies the light's colour; the light is still sampled as an
// unshaped one, so estimates stay unbiased (a narrow cone is only noisier).
#pragma once

#include <algorithm>
#include <cmath>

#include "core/Math.h"

namespace bxdflab {

struct EmissionShaping {
    float coneAngle = 0.5f * kPi;  ///< radians, in (0, pi/2]
    float coneSoftness = 0.0f;     ///< 0: a hard edge, 1: soft all the way to the normal
    float focus = 0.0f;            ///< cosine exponent, >= 0
    Vec3 focusTint{0.0f};

    bool shapes() const { return coneAngle < 0.5f * kPi || focus > 0.0f; }

    /// The factor on the light's colour for emission at cos(theta) > 0.
    Vec3 factor(float cosTheta) const {
        float const theta = std::acos(std::clamp(cosTheta, -1.0f, 1.0f));
        if (theta >= coneAngle) return Vec3(0.0f);
        float const softStart = coneAngle * (1.0f - coneSoftness);
        float cone = 1.0f;
        if (theta > softStart) {
            float const x = (theta - softStart) / (coneAngle - softStart);
            cone = 1.0f - x * x * (3.0f - 2.0f * x);
        }
        float const focused = focus > 0.0f ? std::pow(std::max(cosTheta, 0.0f), focus) : 1.0f;
        return cone * (Vec3(focused) + (1.0f - focused) * focusTint);
    }
};

}  // namespace bxdflab
