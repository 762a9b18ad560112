// Statistical comparison of two renders of the same scene: for each pixel a
// two-sample z test on the difference of the means, using each render's
// per-pixel variance of the mean, at alpha = 0.01 with Sidak's correction
// over the pixels. A correct submission passes when at least 99.75% of the
// pixels pass (the render-regression rule of Mitsuba's test suite).
#pragma once

#include <string>

namespace rixgrade {

struct RenderVerdict {
    double passFraction = 0.0;  ///< of pixels
    double relMse = 0.0;
    double meanStudent = 0.0, meanSolution = 0.0;
    bool passed = false;
    std::string message;
};

/// Compares the images and their variance images (EXR, RGB or RGBA) and writes a
/// heatmap of the failing pixels (red) over the difference (grey) to heatmapPath.
RenderVerdict compareRenders(std::string const& student, std::string const& studentVariance,
                             std::string const& solution, std::string const& solutionVariance,
                             std::string const& heatmapPath);

/// An 8-bit sRGB copy of a linear EXR, for reports.
void toDisplayPng(std::string const& exr, std::string const& png);

}  // namespace rixgrade
