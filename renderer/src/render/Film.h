// The image being rendered. Each pixel averages its own samples (drawn around
// it from the pixel filter, a box one pixel wide unless the scene names
// another), so every pixel is an independent Monte Carlo estimate and its
// sample variance is meaningful: the autograder compares renders pixel by
// pixel with it (under the default box). Under a filter with negative lobes
// (catmull-rom, sinc, mitchell) a pixel is its positive lobes' mean less its
// negative lobes' mean, each weighted by its lobes' share of the filter.
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
#include "scene/DisplayChannels.h"

namespace bxdflab {

class Film final : public SplatTarget {
public:
    Film(int width, int height);
    Film(Film&& other) noexcept
        : m_width(other.m_width), m_height(other.m_height), m_pixels(std::move(other.m_pixels)),
          m_negative(std::move(other.m_negative)), m_positiveShare(other.m_positiveShare),
          m_negativeShare(other.m_negativeShare), m_splats(std::move(other.m_splats)),
          m_splatPaths(other.m_splatPaths.load()), m_finish(other.m_finish), m_surface(other.m_surface),
          m_surfaceSums(std::move(other.m_surfaceSums)), m_nearest(std::move(other.m_nearest)) {}
    int width() const override { return m_width; }
    int height() const override { return m_height; }

    /// Adds one sample to pixel (x, y); `weight` is the pixel filter's (below 0
    /// in a negative lobe). Samples must arrive in a fixed order per pixel for
    /// renders to be bit-for-bit reproducible.
    void addSample(int x, int y, RtColorRGB const& radiance, float alpha, float weight = 1.0f);
    /// Before rendering with a filter that has negative lobes: `absoluteWeight`
    /// is the integral of |filter| over the integral of the filter (each sample's
    /// |weight|), from which the lobes' shares of the filter follow.
    void enableNegativeLobes(float absoluteWeight);

    /// Light tracing (PxrVCM): light subpaths joined to the camera add to
    /// whichever pixel they land in, from any thread. Those additions are
    /// summed in fixed point, so the total does not depend on their order,
    /// and divided by the number of light subpaths counted. Call enableSplats
    /// before rendering. They are left out of varianceOfMean.
    void enableSplats();
    void addSplat(int x, int y, RtColorRGB const& value) override;
    void countSplatPaths(uint64_t paths) override { m_splatPaths.fetch_add(paths, std::memory_order_relaxed); }

    /// Displays that read the surface the camera saw (z, P, N, ...): call before
    /// rendering with what they need; each camera sample then adds its record.
    void enableSurface(SurfaceRecord const& record);
    SurfaceRecord const& surfaceRecord() const { return m_surface; }
    /// One camera sample's surface values (surfaceRecord().width() floats, zero
    /// where the ray saw no surface) and camera-space depth (kInfinity for none).
    void addSurface(int x, int y, float depth, float const* values);

    /// What rgba() does to each pixel last (a background, a clamp): the scene's Imager.
    void setFinish(ImageFinish const& finish) { m_finish = finish; }
    /// Per-pixel mean as RGBA floats (row-major from the top left), finished.
    std::vector<float> rgba() const;
    /// One display's image: its layout's channels per pixel, row-major from the
    /// top left. Colour and alpha are rgba()'s; surface values are each pixel's
    /// mean over its samples (0 where none saw a surface), and depth is the
    /// nearest sample's (the largest float where no sample saw a surface).
    std::vector<float> channels(DisplayLayout const& layout) const;
    /// Per-pixel variance of the mean (sample variance / n) as RGB floats.
    std::vector<float> varianceOfMean() const;
    /// Pixel (x, y)'s variance of the mean in the channel where it is largest (infinite
    /// before the pixel has two samples): adaptive sampling stops a pixel on it.
    double largestVarianceOfMean(int x, int y) const;
    /// Pixel (x, y)'s value in its brightest channel (0 before it has a sample).
    double brightness(int x, int y) const;
    /// How many camera samples pixel (x, y) has taken.
    int samplesTaken(int x, int y) const { return m_pixels[index(x, y)].allSamples; }

private:
    /// The samples drawn in the filter's positive lobes (all of them under a
    /// filter that never goes below 0); sumSq over every sample.
    struct Pixel {
        double sum[3] = {0, 0, 0};
        double sumSq[3] = {0, 0, 0};
        double alpha = 0;
        int count = 0;       ///< samples in positive lobes
        int allSamples = 0;  ///< in any lobe
    };
    /// The samples drawn in negative lobes, kept only under such a filter.
    struct NegativeLobes {
        double sum[3] = {0, 0, 0};
        double alpha = 0;
        int count = 0;
    };
    /// A pixel's value for one channel from its lobes' sums (the positive ones alone under most filters).
    double resolve(double positiveSum, int positiveCount, double negativeSum, int negativeCount) const;
    /// One channel's variance of the mean of a pixel that has at least two samples.
    double varianceOfMean(size_t pixel, int channel) const;
    size_t index(int x, int y) const {
        return static_cast<size_t>(y) * static_cast<size_t>(m_width) + static_cast<size_t>(x);
    }
    int m_width, m_height;
    std::vector<Pixel> m_pixels;
    std::vector<NegativeLobes> m_negative;  ///< empty unless enableNegativeLobes was called
    double m_positiveShare = 1.0, m_negativeShare = 0.0;  ///< the lobes' integrals, which differ by 1
    std::shared_ptr<std::atomic<int64_t>[]> m_splats;  ///< 3 per pixel, in units of kSplatUnit
    std::atomic<uint64_t> m_splatPaths{0};
    ImageFinish m_finish;
    SurfaceRecord m_surface;
    std::vector<double> m_surfaceSums;  ///< m_surface.width() per pixel
    std::vector<float> m_nearest;       ///< per pixel, when a display asks for depth
};

}  // namespace bxdflab
