// The colour of a black body at a temperature, for the lights' "temperature"
// parameter (RenderMan's enableTemperature): linear Rec. 709 RGB scaled to
// luminance 1, so that it tints a light without changing its brightness.
#pragma once

#include "core/Math.h"

namespace bxdflab {

/// Kelvin, clamped to [1000, 40000]; 6500 K is close to white (D65).
Vec3 blackbodyColor(float kelvin);

}  // namespace bxdflab
