// The image being rendered. Each pixel averages its own samples (drawn around
// it from the pixel filter, a box one pixel wide unless the scene names
// another, and weighted by its sign), so every pixel is an independent Monte
// Carlo estimate and its sample variance is meaningful: the autograder
// compares renders pixel by pixel with it (under the default box).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "RiTypesHelper.h"
#include "core/ImageFiles.h"
#include "core/ImageFinish.h"
#include "integrate/SplatTarget.h"

namespace bxdflab {

class Film final : public SplatTarget {
public:
    Film(int width, int height);
    Film(Film&& other) noexcept
        : m_width(other.m_width), m_height(other.m_height), m_pixels(std::move(other.m_pixels)),
          m_splats(std::move(other.m_splats)), m_splatPaths(other.m_splatPaths.load()), m_finish(other.m_finish) {}
    int width() const override { return m_width; }
    int height() const override { return m_height; }

    /// Adds one sample to pixel (x, y), counting `weight` times (the pixel
    /// filter's: below 0 in a negative lobe); a pixel is the weighted mean of
    /// its samples. Samples must arrive in a fixed order per pixel for renders
    /// to be bit-for-bit reproducible.
    void addSample(int x, int y, RtColorRGB const& radiance, float alpha, float weight = 1.0f);

    /// Light tracing (PxrVCM): light subpaths joined to the camera add to
    /// whichever pixel they land in, from any thread. Those additions are
    /// summed in fixed point, so the total does not depend on their order,
    /// and divided by the number of light subpaths counted. Call enableSplats
    /// before rendering. They are left out of varianceOfMean.
    void enableSplats();
    void addSplat(int x, int y, RtColorRGB const& value) override;
    void countSplatPaths(uint64_t paths) override { m_splatPaths.fetch_add(paths, std::memory_order_relaxed); }

    /// What rgba() does to each pixel last (a background, a clamp): the scene's Imager.
    void setFinish(ImageFinish const& finish) { m_finish = finish; }
    /// Per-pixel mean as RGBA floats (row-major from the top left), finished.
    std::vector<float> rgba() const;
    /// Per-pixel variance of the mean (sample variance / n) as RGB floats.
    std::vector<float> varianceOfMean() const;

private:
    struct Pixel {
        double sum[3] = {0, 0, 0};
        double sumSq[3] = {0, 0, 0};
        double alpha = 0;
        double weight = 0;  ///< the samples' filter weights, summed (their count under a box)
        int count = 0;
    };
    int m_width, m_height;
    std::vector<Pixel> m_pixels;
    std::shared_ptr<std::atomic<int64_t>[]> m_splats;  ///< 3 per pixel, in units of kSplatUnit
    std::atomic<uint64_t> m_splatPaths{0};
    ImageFinish m_finish;
};

}  // namespace bxdflab
