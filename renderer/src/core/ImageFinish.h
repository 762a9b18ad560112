// What is done to each finished pixel before the image is written, in the
// order the RenderMan Interface Specification gives: the imager (`Imager
// "background"` or `"clamptoalpha"`, or RenderMan's `DisplayFilter
// "PxrBackgroundDisplayFilter"`), then `Exposure gain gamma`.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/Math.h"

namespace bxdflab {

struct ImageFinish {
    /// Composed over a colour: C += (1 - a) * background, a += (1 - a) * backgroundAlpha.
    bool overBackground = false;
    Vec3 background{0.0f};
    float backgroundAlpha = 0.0f;
    /// No colour channel above the pixel's alpha (nor below 0).
    bool clampToAlpha = false;
    /// Exposure: each colour channel c becomes (gain c)^(1 / gamma).
    float exposureGain = 1.0f, exposureGamma = 1.0f;

    /// Applies the finish to one pixel's RGBA.
    void apply(float* rgba) const {
        float const a = rgba[3];
        if (overBackground) {
            for (int c = 0; c < 3; ++c) rgba[c] += (1.0f - a) * background[c];
            rgba[3] = a + (1.0f - a) * backgroundAlpha;
        }
        if (clampToAlpha)
            for (int c = 0; c < 3; ++c) rgba[c] = std::min(std::max(rgba[c], 0.0f), rgba[3]);
        if (exposureGain != 1.0f || exposureGamma != 1.0f)
            for (int c = 0; c < 3; ++c)
                rgba[c] = rgba[c] > 0.0f ? std::pow(exposureGain * rgba[c], 1.0f / exposureGamma) : exposureGain * rgba[c];
    }
};

}  // namespace bxdflab
