#include "core/PixelFilter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bxdflab {
namespace {

constexpr int kTableCells = 256;  // cells of the tabulated |filter| offsets are drawn from

// Each kernel takes x, the offset from the pixel's centre in pixels, and the filter's half width.
float box(float, float) { return 1.0f; }
float triangle(float x, float h) { return std::max(0.0f, 1.0f - std::fabs(x) / h); }
// RenderMan's: exp(-2 x'^2) with x' = 2 x / width.
float gaussian(float x, float h) { return std::exp(-2.0f * (x / h) * (x / h)); }
// Catmull-Rom's cubic in pixel units (it reaches 0 two pixels out), taken along each axis.
float catmullRom(float x, float) {
    float const t = std::fabs(x);
    if (t < 1.0f) return 1.5f * t * t * t - 2.5f * t * t + 1.0f;
    if (t < 2.0f) return -0.5f * t * t * t + 2.5f * t * t - 4.0f * t + 2.0f;
    return 0.0f;
}
float sinc(float x, float) {
    float const a = kPi * x;
    return std::fabs(a) < 1e-6f ? 1.0f : std::sin(a) / a;
}
// Mitchell and Netravali's cubic (B = C = 1/3), stretched so its support of two fills the half width.
float mitchell(float x, float h) {
    float const t = 2.0f * std::fabs(x) / h, B = 1.0f / 3.0f, C = 1.0f / 3.0f;
    if (t < 1.0f)
        return ((12 - 9 * B - 6 * C) * t * t * t + (-18 + 12 * B + 6 * C) * t * t + (6 - 2 * B)) / 6.0f;
    if (t < 2.0f)
        return ((-B - 6 * C) * t * t * t + (6 * B + 30 * C) * t * t + (-12 * B - 48 * C) * t +
                (8 * B + 24 * C)) /
               6.0f;
    return 0.0f;
}
float blackmanHarris(float x, float h) {
    float const s = 2.0f * kPi * (x / (2.0f * h) + 0.5f);
    return 0.35875f - 0.48829f * std::cos(s) + 0.14128f * std::cos(2 * s) - 0.01168f * std::cos(3 * s);
}

struct NamedKernel {
    char const* name;
    float (*kernel)(float, float);
};
NamedKernel const kKernels[] = {{"box", box},
                                {"triangle", triangle},
                                {"gaussian", gaussian},
                                {"catmull-rom", catmullRom},
                                {"separable-catmull-rom", catmullRom},
                                {"sinc", sinc},
                                {"mitchell", mitchell},
                                {"blackman-harris", blackmanHarris}};

}  // namespace

std::vector<std::string> const& pixelFilterNames() {
    static std::vector<std::string> const names = [] {
        std::vector<std::string> out;
        for (NamedKernel const& k : kKernels) out.push_back(k.name);
        return out;
    }();
    return names;
}

PixelFilter::Axis PixelFilter::makeAxis(std::string const& name, float width) {
    float (*kernel)(float, float) = nullptr;
    for (NamedKernel const& k : kKernels)
        if (name == k.name) kernel = k.kernel;
    if (!kernel || !(width > 0.0f))
        throw std::invalid_argument("no pixel filter \"" + name + "\" of that width");
    Axis axis;
    axis.halfWidth = 0.5f * width;
    // Each cell holds the most |filter| reaches on it (at its ends or middle), so that no part of the filter
    // where it is not 0 goes unsampled (a sinc crossing 0 mid-cell); its sign is its middle's.
    std::vector<float> cells(kTableCells);
    axis.negative.assign(kTableCells, false);
    double absoluteSum = 0.0, signedSum = 0.0;
    for (int i = 0; i < kTableCells; ++i) {
        auto at = [&](float fraction) {
            return kernel(axis.halfWidth * (2.0f * (static_cast<float>(i) + fraction) / kTableCells - 1.0f),
                          axis.halfWidth);
        };
        float const middle = at(0.5f);
        float const value = std::max({std::fabs(at(0.0f)), std::fabs(middle), std::fabs(at(1.0f))});
        cells[static_cast<size_t>(i)] = value;
        axis.negative[static_cast<size_t>(i)] = middle < 0.0f;
        absoluteSum += value;
        signedSum += middle < 0.0f ? -value : value;
    }
    if (!(signedSum > 0.0))
        throw std::invalid_argument("pixel filter \"" + name + "\" integrates to 0 or less");
    if (absoluteSum != signedSum) axis.scale = static_cast<float>(absoluteSum / signedSum);
    axis.absolute = Distribution1D(std::move(cells));
    return axis;
}

PixelFilter::PixelFilter(std::string const& name, float xwidth, float ywidth)
    : m_x(makeAxis(name, xwidth)),
      m_y(makeAxis(name, ywidth)),
      m_unitBox(name == "box" && xwidth == 1.0f && ywidth == 1.0f) {}

float PixelFilter::Axis::sample(float u, float& weight) const {
    float density;
    size_t cell;
    float const x = halfWidth * (2.0f * absolute.sample(u, density, cell) - 1.0f);
    weight = negative[cell] ? -scale : scale;
    return x;
}

Vec2 PixelFilter::sample(float u1, float u2, float& weight) const {
    if (m_unitBox) {
        weight = 1.0f;
        return Vec2(u1, u2);
    }
    float wx, wy;
    Vec2 const offset(m_x.sample(u1, wx), m_y.sample(u2, wy));
    weight = wx * wy;
    return Vec2(0.5f) + offset;
}

}  // namespace bxdflab
