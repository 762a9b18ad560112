// How many samples each pixel takes, and when it has enough (adaptive
// sampling, as RenderMan's PixelVariance and Hider sample counts ask).
#pragma once

#include <algorithm>
#include <cmath>

namespace bxdflab {

/// Every pixel takes `first` samples; then, until it has `most` or is settled(),
/// `step` more at a time. Without a PixelVariance every pixel takes `most` at once.
struct SampleSchedule {
    int most = 16;
    int first = 16;
    int step = 16;
    float pixelVariance = 0.0f;
    float darkFalloff = 0.025f;
    bool adaptive() const { return first < most; }
    /// A pixel has enough samples once its relative variance, its variance of the
    /// mean over its value squared, is at most pixelVariance, as RenderMan measures
    /// it; a value below darkFalloff counts as darkFalloff, so that dark pixels do
    /// not take every sample.
    bool settled(double varianceOfMean, double brightness) const {
        double const value = std::max(brightness, static_cast<double>(darkFalloff));
        return varianceOfMean <= static_cast<double>(pixelVariance) * value * value;
    }
};

/// RenderMan's rules: minsamples of 0 or below is the square root of maxsamples;
/// minextrasamples of 0 or below is minsamples. A pixel takes at least two
/// samples before its first test, as one sample has no variance to measure.
inline SampleSchedule sampleSchedule(int most, float pixelVariance, int minSamples, int minExtraSamples,
                                     float darkFalloff) {
    SampleSchedule schedule;
    schedule.most = most;
    schedule.first = schedule.step = most;
    schedule.pixelVariance = pixelVariance;
    schedule.darkFalloff = darkFalloff;
    if (pixelVariance <= 0.0f) return schedule;
    int const automatic = static_cast<int>(std::lround(std::sqrt(static_cast<double>(most))));
    schedule.first = std::min(most, std::max(2, minSamples > 0 ? minSamples : automatic));
    schedule.step = std::max(1, minExtraSamples > 0 ? minExtraSamples : schedule.first);
    return schedule;
}

}  // namespace bxdflab
