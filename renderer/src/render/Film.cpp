#include "render/Film.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.h"
#include "core/Math.h"

namespace bxdflab {

Film::Film(int width, int height)
    : m_width(width), m_height(height), m_pixels(static_cast<size_t>(width) * static_cast<size_t>(height)) {}

void Film::addSample(int x, int y, RtColorRGB const& radiance, float alpha, float weight) {
    size_t const pixel = index(x, y);
    Pixel& p = m_pixels[pixel];
    for (int c = 0; c < 3; ++c) p.sumSq[c] += static_cast<double>(radiance[c]) * radiance[c];
    ++p.allSamples;
    if (weight < 0.0f && !m_negative.empty()) {
        NegativeLobes& n = m_negative[pixel];
        for (int c = 0; c < 3; ++c) n.sum[c] += radiance[c];
        n.alpha += alpha;
        ++n.count;
        return;
    }
    for (int c = 0; c < 3; ++c) p.sum[c] += radiance[c];
    p.alpha += alpha;
    ++p.count;
}

void Film::enableNegativeLobes(float absoluteWeight) {
    // integral f+ + integral f- = absoluteWeight and integral f+ - integral f- = 1.
    m_positiveShare = 0.5 * (static_cast<double>(absoluteWeight) + 1.0);
    m_negativeShare = 0.5 * (static_cast<double>(absoluteWeight) - 1.0);
    m_negative.assign(m_pixels.size(), NegativeLobes());
}

double Film::resolve(double positiveSum, int positiveCount, double negativeSum, int negativeCount) const {
    // Each lobe's mean estimates the image under that lobe alone, so a bright sample in a
    // negative lobe takes away its lobe's small share, never as much as a positive one adds
    // (which a mean of signed weights would let it do). Where no sample fell in one kind of
    // lobe, the other kind's mean stands in for it.
    if (negativeCount == 0) return positiveSum / positiveCount;
    double const negativeMean = negativeSum / negativeCount;
    double const positiveMean = positiveCount > 0 ? positiveSum / positiveCount : negativeMean;
    return m_positiveShare * positiveMean - m_negativeShare * negativeMean;
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
    size_t const pixel = index(x, y);
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
        if (p.allSamples == 0) continue;
        NegativeLobes const none;
        NegativeLobes const& n = m_negative.empty() ? none : m_negative[i];
        for (int c = 0; c < 3; ++c) {
            double splat = m_splats && paths > 0 ? static_cast<double>(m_splats[3 * i + static_cast<size_t>(c)].load()) *
                                                       kSplatUnit / static_cast<double>(paths)
                                                 : 0.0;
            double const own = resolve(p.sum[c], p.count, n.sum[c], n.count);
            out[4 * i + static_cast<size_t>(c)] = static_cast<float>(own + splat);
        }
        out[4 * i + 3] = static_cast<float>(resolve(p.alpha, p.count, n.alpha, n.count));
        m_finish.apply(&out[4 * i]);
    }
    return out;
}

void Film::enableSurface(SurfaceRecord const& record) {
    m_surface = record;
    m_surfaceSums.assign(m_pixels.size() * static_cast<size_t>(record.width()), 0.0);
    m_nearest.assign(record.needsDepth() ? m_pixels.size() : 0, kInfinity);
}

void Film::addSurface(int x, int y, float depth, float const* values) {
    size_t const pixel = index(x, y);
    if (!m_nearest.empty()) m_nearest[pixel] = std::min(m_nearest[pixel], depth);
    size_t const width = static_cast<size_t>(m_surface.width());
    for (size_t k = 0; k < width; ++k) m_surfaceSums[pixel * width + k] += values[k];
}

std::vector<float> Film::channels(DisplayLayout const& layout) const {
    size_t const count = layout.channels.size();
    std::vector<float> out(m_pixels.size() * count, 0.0f);
    std::vector<float> const shaded = rgba();
    size_t const width = static_cast<size_t>(m_surface.width());
    for (size_t i = 0; i < m_pixels.size(); ++i)
        for (size_t c = 0; c < count; ++c) {
            DisplayChannel const& channel = layout.channels[c];
            float& value = out[i * count + c];
            size_t const component = static_cast<size_t>(channel.component);
            if (channel.quantity == Quantity::Color) {
                value = shaded[4 * i + component];
            } else if (channel.quantity == Quantity::Alpha) {
                value = shaded[4 * i + 3];
            } else if (channel.quantity == Quantity::Depth) {
                float const nearest = m_nearest.empty() ? kInfinity : m_nearest[i];
                value = nearest < kInfinity ? nearest : std::numeric_limits<float>::max();
            } else {
                int const offset = m_surface.offset(channel.quantity);
                int const samples = m_pixels[i].allSamples;
                if (offset >= 0 && samples > 0)
                    value = static_cast<float>(m_surfaceSums[i * width + static_cast<size_t>(offset) + component] /
                                               samples);
            }
        }
    return out;
}

double Film::varianceOfMean(size_t pixel, int channel) const {
    Pixel const& p = m_pixels[pixel];
    NegativeLobes const none;
    NegativeLobes const& n = m_negative.empty() ? none : m_negative[pixel];
    // Under negative lobes, the spread of all samples about the pixel's value: an estimate, not exact.
    double const mean = resolve(p.sum[channel], p.count, n.sum[channel], n.count);
    double const variance = std::max(0.0, (p.sumSq[channel] - p.allSamples * mean * mean) / (p.allSamples - 1));
    return variance / p.allSamples;
}

std::vector<float> Film::varianceOfMean() const {
    std::vector<float> out(m_pixels.size() * 3, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        if (m_pixels[i].allSamples < 2) continue;
        for (int c = 0; c < 3; ++c) out[3 * i + static_cast<size_t>(c)] = static_cast<float>(varianceOfMean(i, c));
    }
    return out;
}

double Film::brightness(int x, int y) const {
    size_t const i = index(x, y);
    Pixel const& p = m_pixels[i];
    if (p.allSamples == 0) return 0.0;
    NegativeLobes const none;
    NegativeLobes const& n = m_negative.empty() ? none : m_negative[i];
    double brightest = resolve(p.sum[0], p.count, n.sum[0], n.count);
    for (int c = 1; c < 3; ++c) brightest = std::max(brightest, resolve(p.sum[c], p.count, n.sum[c], n.count));
    return brightest;
}

double Film::largestVarianceOfMean(int x, int y) const {
    size_t const i = index(x, y);
    if (m_pixels[i].allSamples < 2) return std::numeric_limits<double>::infinity();
    return std::max({varianceOfMean(i, 0), varianceOfMean(i, 1), varianceOfMean(i, 2)});
}

}  // namespace bxdflab
