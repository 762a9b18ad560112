// Colour models the colour-adjusting patterns work in (PxrColorCorrect, PxrHSL,
// PxrInvert): hue, saturation and value (HSV), and hue, saturation and
// lightness (HSL). Hue is in turns (0 to 1, red at 0, green at 1/3, blue at 2/3),
// so that a hue shift of 0.5 gives the complementary colour; saturation, value
// and lightness are 0 to 1 for colours between black and white.
#pragma once

#include <algorithm>
#include <cmath>

#include "RiTypesHelper.h"

namespace stockpatterns {

/// Hue, saturation and value or lightness: three numbers, in the order their names say.
struct HueColor {
    float hue, saturation, third;
};

/// The hue (in turns) of a colour whose largest channel is `high` and smallest `low` (0 for a grey).
inline float hueOf(RtColorRGB const& c, float high, float low) {
    float const range = high - low;
    if (range <= 0.0f) return 0.0f;
    float sixths;
    if (high == c.r)
        sixths = (c.g - c.b) / range;
    else if (high == c.g)
        sixths = 2.0f + (c.b - c.r) / range;
    else
        sixths = 4.0f + (c.r - c.g) / range;
    float const turns = sixths / 6.0f;
    return turns < 0.0f ? turns + 1.0f : turns;
}

/// A hue back to the fully saturated colour of value 1 it names (any number of turns: it wraps).
inline RtColorRGB pureHue(float hue) {
    float const h = 6.0f * (hue - std::floor(hue));
    auto channel = [h](float offset) {  // the standard piecewise-linear hue ramps
        float const k = std::fmod(offset + h, 6.0f);
        return 1.0f - std::clamp(std::min(k, 4.0f - k), 0.0f, 1.0f);
    };
    return RtColorRGB(channel(5.0f), channel(3.0f), channel(1.0f));
}

inline HueColor rgbToHsv(RtColorRGB const& c) {
    float const high = std::max({c.r, c.g, c.b}), low = std::min({c.r, c.g, c.b});
    return {hueOf(c, high, low), high > 0.0f ? (high - low) / high : 0.0f, high};
}

inline RtColorRGB hsvToRgb(HueColor const& hsv) {
    // value * (1 - saturation * (1 - pure hue)): grey at saturation 0, the pure hue scaled by value at 1.
    RtColorRGB const pure = pureHue(hsv.hue);
    float const v = hsv.third, s = hsv.saturation;
    return RtColorRGB(v * (1.0f - s * (1.0f - pure.r)), v * (1.0f - s * (1.0f - pure.g)),
                      v * (1.0f - s * (1.0f - pure.b)));
}

inline HueColor rgbToHsl(RtColorRGB const& c) {
    float const high = std::max({c.r, c.g, c.b}), low = std::min({c.r, c.g, c.b});
    float const lightness = 0.5f * (high + low);
    float const spread = 1.0f - std::fabs(2.0f * lightness - 1.0f);
    return {hueOf(c, high, low), spread > 0.0f ? (high - low) / spread : 0.0f, lightness};
}

inline RtColorRGB hslToRgb(HueColor const& hsl) {
    // The pure hue squeezed into [lightness - chroma/2, lightness + chroma/2].
    RtColorRGB const pure = pureHue(hsl.hue);
    float const l = hsl.third;
    float const chroma = hsl.saturation * (1.0f - std::fabs(2.0f * l - 1.0f));
    float const low = l - 0.5f * chroma;
    return RtColorRGB(low + chroma * pure.r, low + chroma * pure.g, low + chroma * pure.b);
}

/// A channel's gamma: x^gamma for positive x (a gamma of 2.2 turns a colour stored for display, like an
/// sRGB texture, into a linear one); 0 and below stay as they are, and so does everything when the gamma is
/// not positive (an unusable gamma is ignored).
inline float applyGamma(float x, float gamma) { return x > 0.0f && gamma > 0.0f ? std::pow(x, gamma) : x; }

}  // namespace stockpatterns
