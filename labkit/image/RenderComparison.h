// Are two renders of one scene the same image up to Monte Carlo noise?
// For each pixel a two-sample z test on the difference of the means, with
// each render's per-pixel variance of the mean, at alpha = 0.01 with Sidak's
// correction over the pixels (the reference's variance is at least the mean
// of its 5 x 5 neighbourhood's, so that a pixel whose few samples all agreed
// by chance is not taken as noise-free); the renders agree when at least 99.75% of the
// pixels pass (the render-regression rule of Mitsuba's test suite) and the
// image means agree (a z test on the sums, which catches a bias spread too
// thinly for any one pixel to show).
#pragma once

#include <string>
#include <vector>

namespace bxdflab {

/// A render as the comparison sees it: RGB means and variances of the mean.
struct RenderImage {
    int width = 0, height = 0;
    std::vector<float> rgb;       ///< 3 per pixel
    std::vector<float> variance;  ///< 3 per pixel
};

struct RenderVerdict {
    double passFraction = 0.0;  ///< of pixels
    double relMse = 0.0;        ///< mean of (a - b)^2 / (b^2 + 0.01)
    double meanTested = 0.0, meanReference = 0.0;
    double meanZ = 0.0;         ///< the worst channel's z of the image means
    bool pixelsAgree = false, meansAgree = false;
    bool passed() const { return pixelsAgree && meansAgree; }
    std::string message;        ///< what was measured and what was needed, in words
    /// Per pixel: the z of the difference, signed (tested brighter > 0), clamped to +-50.
    std::vector<float> zMap;
    double zCritical = 0.0;     ///< the per-pixel z beyond which a pixel fails
};

/// `tested` is judged against `reference`. A tested variance larger than
/// `varianceCap` times the reference's (plus a little) is not believed: it
/// is taken at that cap, so claiming a huge variance gains nothing.
/// With block > 1 both images are first averaged over block x block squares
/// (the variance of a square's mean from its pixels'): for scenes whose light
/// arrives as rare fireflies, whose single pixels at a few samples are far
/// from the normal distribution the test assumes.
RenderVerdict compareRenders(RenderImage const& tested, RenderImage const& reference, double varianceCap = 16.0,
                             int block = 1);

/// The image averaged over block x block squares (a partial square at the
/// right or bottom edge averages what it has).
RenderImage averageBlocks(RenderImage const& image, int block);

/// How noisy `tested` is against `reference`, rendered with the same samples
/// per pixel: the ratio of their summed per-pixel variances of the mean
/// (each image's largest 1% left out, see compareNoise in the .cpp). An
/// integrator that leaves out a sampling strategy (or weights it badly) can
/// still converge to the right image, but slower: this ratio shows it.
struct NoiseVerdict {
    double ratio = 0.0;  ///< tested / reference (1 for the same estimator)
    bool passed = false;
    std::string message;
};
/// With `bothWays` the ratio must also be at least 1 / limit: for a scene
/// whose parameters fix the estimator (one sampling strategy alone), where a
/// right integrator is as noisy as the solution and a smoother image means
/// samples the scene did not ask for.
NoiseVerdict compareNoise(RenderImage const& tested, RenderImage const& reference, double limit, bool bothWays = false);

/// Relative mean squared error, mean((a - b)^2 / (b^2 + 0.01)), over every value.
double relativeMse(std::vector<float> const& a, std::vector<float> const& b);

}  // namespace bxdflab
