// The blend modes of PxrBlend (Photoshop's, in RenderMan's numbering, which
// lists them alphabetically: 19, Normal, is the default), each a function of
// the bottom colour b and the top colour t. The per-channel ones work channel
// by channel; Hue, Saturation, Color and Luminosity mix the hue, saturation and
// luminosity of the two (the W3C compositing specification's formulas).
#pragma once

#include <algorithm>
#include <cmath>

#include "RiTypesHelper.h"

namespace stockpatterns {

enum class BlendMode {
    Color, ColorBurn, ColorDodge, Darken, DarkerColor, Difference, Dissolve, Divide, Exclusion, HardLight,
    HardMix, Hue, Lighten, LighterColor, LinearBurn, LinearDodge, LinearLight, Luminosity, Multiply, Normal,
    Overlay, PinLight, Saturation, Screen, SoftLight, Subtract, VividLight, Count
};

namespace blend {

inline float colorBurn(float b, float t) {
    if (b >= 1.0f) return 1.0f;
    return t <= 0.0f ? 0.0f : 1.0f - std::min(1.0f, (1.0f - b) / t);
}
inline float colorDodge(float b, float t) {
    if (b <= 0.0f) return 0.0f;
    return t >= 1.0f ? 1.0f : std::min(1.0f, b / (1.0f - t));
}
inline float hardLight(float b, float t) { return t <= 0.5f ? 2.0f * b * t : 1.0f - 2.0f * (1.0f - b) * (1.0f - t); }
inline float softLight(float b, float t) {
    if (t <= 0.5f) return b - (1.0f - 2.0f * t) * b * (1.0f - b);
    float const d = b <= 0.25f ? ((16.0f * b - 12.0f) * b + 4.0f) * b : std::sqrt(std::max(b, 0.0f));
    return b + (2.0f * t - 1.0f) * (d - b);
}

/// One channel of a separable mode.
inline float channel(BlendMode mode, float b, float t) {
    switch (mode) {
        case BlendMode::ColorBurn: return colorBurn(b, t);
        case BlendMode::ColorDodge: return colorDodge(b, t);
        case BlendMode::Darken: return std::min(b, t);
        case BlendMode::Difference: return std::fabs(b - t);
        case BlendMode::Divide: return t > 0.0f ? b / t : (b > 0.0f ? 1.0f : 0.0f);
        case BlendMode::Exclusion: return b + t - 2.0f * b * t;
        case BlendMode::HardLight: return hardLight(b, t);
        case BlendMode::HardMix: return b + t >= 1.0f ? 1.0f : 0.0f;
        case BlendMode::Lighten: return std::max(b, t);
        case BlendMode::LinearBurn: return std::max(0.0f, b + t - 1.0f);
        case BlendMode::LinearDodge: return b + t;
        case BlendMode::LinearLight: return b + 2.0f * t - 1.0f;
        case BlendMode::Multiply: return b * t;
        case BlendMode::Overlay: return hardLight(t, b);
        case BlendMode::PinLight: return t <= 0.5f ? std::min(b, 2.0f * t) : std::max(b, 2.0f * t - 1.0f);
        case BlendMode::Screen: return b + t - b * t;
        case BlendMode::SoftLight: return softLight(b, t);
        case BlendMode::Subtract: return b - t;
        case BlendMode::VividLight: return t <= 0.5f ? colorBurn(b, 2.0f * t) : colorDodge(b, 2.0f * t - 1.0f);
        default: return t;  // Normal
    }
}

inline float lum(RtColorRGB const& c) { return 0.3f * c.r + 0.59f * c.g + 0.11f * c.b; }
inline float sat(RtColorRGB const& c) {
    return std::max(c.r, std::max(c.g, c.b)) - std::min(c.r, std::min(c.g, c.b));
}
/// `c` moved to luminosity `l`, brought back inside [0, 1] keeping its hue.
inline RtColorRGB setLum(RtColorRGB const& c, float l) {
    float const d = l - lum(c);
    RtColorRGB out(c.r + d, c.g + d, c.b + d);
    float const L = lum(out);
    float const lo = std::min(out.r, std::min(out.g, out.b)), hi = std::max(out.r, std::max(out.g, out.b));
    if (lo < 0.0f) out = RtColorRGB(L) + (out - RtColorRGB(L)) * (L / (L - lo));
    if (hi > 1.0f) out = RtColorRGB(L) + (out - RtColorRGB(L)) * ((1.0f - L) / (hi - L));
    return out;
}
/// `c` with saturation `s`, its hue kept.
inline RtColorRGB setSat(RtColorRGB const& c, float s) {
    float v[3] = {c.r, c.g, c.b};
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int a, int b) { return v[a] < v[b]; });
    float const lo = v[order[0]], mid = v[order[1]], hi = v[order[2]];
    float out[3];
    if (hi > lo) {
        out[order[1]] = (mid - lo) * s / (hi - lo);
        out[order[2]] = s;
    } else {
        out[order[1]] = out[order[2]] = 0.0f;
    }
    out[order[0]] = 0.0f;
    return RtColorRGB(out[0], out[1], out[2]);
}

}  // namespace blend

/// The top colour `t` blended onto the bottom colour `b` by `mode` (before the top's alpha is applied).
inline RtColorRGB blendColors(BlendMode mode, RtColorRGB const& b, RtColorRGB const& t) {
    using namespace blend;
    switch (mode) {
        case BlendMode::Color: return setLum(t, lum(b));
        case BlendMode::Hue: return setLum(setSat(t, sat(b)), lum(b));
        case BlendMode::Saturation: return setLum(setSat(b, sat(t)), lum(b));
        case BlendMode::Luminosity: return setLum(b, lum(t));
        case BlendMode::DarkerColor: return t.r + t.g + t.b < b.r + b.g + b.b ? t : b;
        case BlendMode::LighterColor: return t.r + t.g + t.b > b.r + b.g + b.b ? t : b;
        default: return RtColorRGB(channel(mode, b.r, t.r), channel(mode, b.g, t.g), channel(mode, b.b, t.b));
    }
}

}  // namespace stockpatterns
