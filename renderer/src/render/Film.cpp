#include "render/Film.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace bxdflab {

Film::Film(int width, int height)
    : m_width(width), m_height(height), m_pixels(static_cast<size_t>(width) * static_cast<size_t>(height)) {}

void Film::addSample(int x, int y, RtColorRGB const& radiance, float alpha, float weight) {
    Pixel& p = m_pixels[static_cast<size_t>(y) * static_cast<size_t>(m_width) + static_cast<size_t>(x)];
    for (int c = 0; c < 3; ++c) {
        double v = radiance[c];
        p.sum[c] += weight * v;
        p.sumSq[c] += v * v;
    }
    p.alpha += weight * alpha;
    p.weight += weight;
    ++p.count;
}

namespace {
/// Splats are summed as integers of this size: 2^-20 resolves any visible
/// difference, and 2^63 units leave room for 8.8e12 in one pixel.
constexpr double kSplatUnit = 1.0 / 1048576.0;
constexpr double kSplatLimit = 1e12;  ///< larger single values are clamped (they can only be fireflies)
}  // namespace

void Film::enableSplats() {
    size_t const n = 3 * m_pixels.size();
    m_splats.reset(new std::atomic<int64_t>[n]);
    for (size_t i = 0; i < n; ++i) m_splats[i] = 0;
    m_splatPaths = 0;
}

void Film::addSplat(int x, int y, RtColorRGB const& value) {
    if (!m_splats) return;
    size_t const pixel = static_cast<size_t>(y) * static_cast<size_t>(m_width) + static_cast<size_t>(x);
    for (int c = 0; c < 3; ++c) {
        double v = std::clamp(static_cast<double>(value[c]), -kSplatLimit, kSplatLimit);
        if (!std::isfinite(v)) continue;
        m_splats[3 * pixel + static_cast<size_t>(c)].fetch_add(std::llround(v / kSplatUnit), std::memory_order_relaxed);
    }
}

std::vector<float> Film::rgba() const {
    std::vector<float> out(m_pixels.size() * 4, 0.0f);
    uint64_t const paths = m_splatPaths.load();
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count == 0 || p.weight == 0.0) continue;
        for (int c = 0; c < 3; ++c) {
            double splat = m_splats && paths > 0 ? static_cast<double>(m_splats[3 * i + static_cast<size_t>(c)].load()) *
                                                       kSplatUnit / static_cast<double>(paths)
                                                 : 0.0;
            out[4 * i + static_cast<size_t>(c)] = static_cast<float>(p.sum[c] / p.weight + splat);
        }
        out[4 * i + 3] = static_cast<float>(p.alpha / p.weight);
        m_finish.apply(&out[4 * i]);
    }
    return out;
}

std::vector<float> Film::varianceOfMean() const {
    std::vector<float> out(m_pixels.size() * 3, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count < 2 || p.weight == 0.0) continue;
        for (int c = 0; c < 3; ++c) {
            double mean = p.sum[c] / p.weight;
            double variance = std::max(0.0, (p.sumSq[c] - p.count * mean * mean) / (p.count - 1));
            out[3 * i + static_cast<size_t>(c)] = static_cast<float>(variance / p.count);
        }
    }
    return out;
}

}  // namespace bxdflab
