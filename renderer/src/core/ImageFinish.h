// What is done to each finished pixel before the image is written: the
// classic imagers `Imager "background"` and `Imager "clamptoalpha"`, and
// RenderMan's `DisplayFilter "PxrBackgroundDisplayFilter"`.
#pragma once

#include <algorithm>

#include "core/Math.h"

namespace bxdflab {

struct ImageFinish {
    /// Composed over a colour: C += (1 - a) * background, a += (1 - a) * backgroundAlpha.
    bool overBackground = false;
    Vec3 background{0.0f};
    float backgroundAlpha = 0.0f;
    /// No colour channel above the pixel's alpha (nor below 0).
    bool clampToAlpha = false;

    /// Applies the finish to one pixel's RGBA.
    void apply(float* rgba) const {
        float const a = rgba[3];
        if (overBackground) {
            for (int c = 0; c < 3; ++c) rgba[c] += (1.0f - a) * background[c];
            rgba[3] = a + (1.0f - a) * backgroundAlpha;
        }
        if (clampToAlpha)
            for (int c = 0; c < 3; ++c) rgba[c] = std::min(std::max(rgba[c], 0.0f), rgba[3]);
    }
};

}  // namespace bxdflab
