// The image being rendered. Each pixel averages its samples with a box
// filter one pixel wide (a sample counts only for the pixel it falls in), so
// every pixel is an independent Monte Carlo estimate and its sample variance
// is meaningful: the autograder compares renders pixel by pixel with it.
#pragma once

#include <string>
#include <vector>

#include "RiTypesHelper.h"
#include "core/ImageFiles.h"

namespace bxdflab {

class Film {
public:
    Film(int width, int height);
    int width() const { return m_width; }
    int height() const { return m_height; }

    /// Adds one sample to pixel (x, y). Samples must arrive in a fixed order
    /// per pixel for renders to be bit-for-bit reproducible.
    void addSample(int x, int y, RtColorRGB const& radiance, float alpha);

    /// Per-pixel mean as RGBA floats (row-major from the top left).
    std::vector<float> rgba() const;
    /// Per-pixel variance of the mean (sample variance / n) as RGB floats.
    std::vector<float> varianceOfMean() const;

private:
    struct Pixel {
        double sum[3] = {0, 0, 0};
        double sumSq[3] = {0, 0, 0};
        double alpha = 0;
        int count = 0;
    };
    int m_width, m_height;
    std::vector<Pixel> m_pixels;
};

}  // namespace bxdflab
