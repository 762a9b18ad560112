#include "RenderComparison.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <vector>

namespace rixgrade {
namespace {

std::vector<float> readRgb(std::string const& path, int& width, int& height) {
    OIIO::ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw std::runtime_error("cannot read " + path);
    width = image.spec().width;
    height = image.spec().height;
    int channels = image.spec().nchannels;
    std::vector<float> all(static_cast<size_t>(width) * height * channels), rgb(static_cast<size_t>(width) * height * 3);
    image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, all.data());
    for (size_t p = 0; p < static_cast<size_t>(width) * height; ++p)
        for (int c = 0; c < 3; ++c) rgb[3 * p + c] = all[p * channels + std::min(c, channels - 1)];
    return rgb;
}

/// The z beyond which a two-sided normal test rejects at level alpha (bisection on erfc).
double criticalZ(double alpha) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return hi;
}

}  // namespace

RenderVerdict compareRenders(std::string const& student, std::string const& studentVariance,
                             std::string const& solution, std::string const& solutionVariance,
                             std::string const& heatmapPath) {
    int w, h, w2, h2, w3, h3, w4, h4;
    auto a = readRgb(student, w, h), va = readRgb(studentVariance, w2, h2);
    auto b = readRgb(solution, w3, h3), vb = readRgb(solutionVariance, w4, h4);
    RenderVerdict verdict;
    if (w != w3 || h != h3 || w != w2 || h != h2 || w != w4 || h != h4) {
        verdict.message = "the renders have different sizes";
        return verdict;
    }
    size_t pixels = static_cast<size_t>(w) * h;
    double alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / static_cast<double>(pixels));  // Sidak over pixels
    double zCritical = criticalZ(alpha);
    size_t passing = 0;
    double sumDiff[3] = {0, 0, 0}, sumVariance[3] = {0, 0, 0};
    std::vector<float> heat(pixels * 3, 0.0f);
    for (size_t p = 0; p < pixels; ++p) {
        bool pass = true;
        for (int c = 0; c < 3; ++c) {
            size_t i = 3 * p + c;
            double d = static_cast<double>(a[i]) - b[i];
            sumDiff[c] += d;
            sumVariance[c] += static_cast<double>(va[i]) + vb[i];
            double sigma = std::sqrt(std::max(0.0, static_cast<double>(va[i]) + vb[i]));
            // Noise-free pixels must agree to float precision; noisy ones within zCritical sigmas.
            bool ok = sigma > 0.0 ? std::fabs(d) <= zCritical * sigma : std::fabs(d) <= 1e-4 * (std::fabs(b[i]) + 1e-3);
            pass = pass && ok && std::isfinite(a[i]);
            verdict.relMse += d * d / (static_cast<double>(b[i]) * b[i] + 0.01);
            verdict.meanStudent += a[i];
            verdict.meanSolution += b[i];
            heat[3 * p] = heat[3 * p + 1] = heat[3 * p + 2] = static_cast<float>(std::min(1.0, std::fabs(d)));
        }
        if (pass) {
            ++passing;
        } else {
            heat[3 * p] = 1.0f;  // failing pixels in red
            heat[3 * p + 1] = heat[3 * p + 2] = 0.0f;
        }
    }
    verdict.passFraction = static_cast<double>(passing) / static_cast<double>(pixels);
    verdict.relMse /= static_cast<double>(pixels * 3);
    verdict.meanStudent /= static_cast<double>(pixels * 3);
    verdict.meanSolution /= static_cast<double>(pixels * 3);
    // A difference confined to a few pixels (a small highlight) can hide under
    // the 99.75% rule; the image means must agree too (z test on the means).
    double worstZ = 0.0;
    for (int c = 0; c < 3; ++c) {
        double sigma = std::sqrt(sumVariance[c]);
        double z = sigma > 0 ? std::fabs(sumDiff[c]) / sigma : (std::fabs(sumDiff[c]) > 1e-6 * pixels ? 1e9 : 0.0);
        worstZ = std::max(worstZ, z);
    }
    verdict.passed = verdict.passFraction >= 0.9975 && worstZ <= criticalZ(0.01 / 3.0);
    char text[320];
    std::snprintf(text, sizeof text,
                  "%.2f%% of pixels agree with the solution's (99.75%% needed); image means %.4g vs %.4g (z = %.1f); relMSE %.3g",
                  100.0 * verdict.passFraction, verdict.meanStudent, verdict.meanSolution, std::min(worstZ, 1e6), verdict.relMse);
    verdict.message = text;
    if (!heatmapPath.empty()) {
        OIIO::ImageBuf out(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
        out.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, heat.data());
        out.set_write_format(OIIO::TypeDesc::UINT8);
        out.write(heatmapPath);
    }
    return verdict;
}

void toDisplayPng(std::string const& exr, std::string const& png) {
    OIIO::ImageBuf image(exr);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return;
    OIIO::ImageBuf rgb = OIIO::ImageBufAlgo::channels(image, std::min(3, image.nchannels()), {});
    OIIO::ImageBuf display;
    OIIO::ImageBufAlgo::colorconvert(display, rgb, "linear", "sRGB", false);
    display.set_write_format(OIIO::TypeDesc::UINT8);
    display.write(png);
}

}  // namespace rixgrade
