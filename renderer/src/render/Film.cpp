#include "render/Film.h"

#include <algorithm>

#include "core/Error.h"

namespace bxdflab {

Film::Film(int width, int height)
    : m_width(width), m_height(height), m_pixels(static_cast<size_t>(width) * static_cast<size_t>(height)) {}

void Film::addSample(int x, int y, RtColorRGB const& radiance, float alpha) {
    Pixel& p = m_pixels[static_cast<size_t>(y) * static_cast<size_t>(m_width) + static_cast<size_t>(x)];
    for (int c = 0; c < 3; ++c) {
        double v = radiance[c];
        p.sum[c] += v;
        p.sumSq[c] += v * v;
    }
    p.alpha += alpha;
    ++p.count;
}

std::vector<float> Film::rgba() const {
    std::vector<float> out(m_pixels.size() * 4, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count == 0) continue;
        for (int c = 0; c < 3; ++c) out[4 * i + static_cast<size_t>(c)] = static_cast<float>(p.sum[c] / p.count);
        out[4 * i + 3] = static_cast<float>(p.alpha / p.count);
    }
    return out;
}

std::vector<float> Film::varianceOfMean() const {
    std::vector<float> out(m_pixels.size() * 3, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count < 2) continue;
        for (int c = 0; c < 3; ++c) {
            double mean = p.sum[c] / p.count;
            double variance = std::max(0.0, (p.sumSq[c] - p.count * mean * mean) / (p.count - 1));
            out[3 * i + static_cast<size_t>(c)] = static_cast<float>(variance / p.count);
        }
    }
    return out;
}

}  // namespace bxdflab
