// Piecewise-constant 1-D and 2-D distributions for importance sampling
// tabulated functions (an environment map's luminance). Sampling inverts the
// cumulative distribution (pbrt-v4, section A.1).
#pragma once

#include <algorithm>
#include <vector>

#include "core/Math.h"

namespace bxdflab {

class Distribution1D {
public:
    Distribution1D() = default;
    explicit Distribution1D(std::vector<float> values) : m_func(std::move(values)), m_cdf(m_func.size() + 1, 0.0f) {
        size_t n = m_func.size();
        for (size_t i = 0; i < n; ++i) m_cdf[i + 1] = m_cdf[i] + std::max(0.0f, m_func[i]) / static_cast<float>(n);
        m_integral = m_cdf[n];
        if (m_integral <= 0.0f) {
            for (size_t i = 1; i <= n; ++i) m_cdf[i] = static_cast<float>(i) / static_cast<float>(n);
        } else {
            for (size_t i = 1; i <= n; ++i) m_cdf[i] /= m_integral;
        }
    }
    size_t size() const { return m_func.size(); }
    float integral() const { return m_integral; }
    /// A point in [0,1) distributed like the function; its density and cell.
    float sample(float xi, float& pdf, size_t& cell) const {
        auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), xi);
        cell = static_cast<size_t>(std::clamp<std::ptrdiff_t>(it - m_cdf.begin() - 1, 0, static_cast<std::ptrdiff_t>(size()) - 1));
        float width = m_cdf[cell + 1] - m_cdf[cell];
        float offset = width > 0.0f ? (xi - m_cdf[cell]) / width : 0.5f;
        pdf = density(cell);
        return std::min((static_cast<float>(cell) + offset) / static_cast<float>(size()), 0x1.fffffep-1f);
    }
    float density(size_t cell) const {
        return m_integral > 0.0f ? std::max(0.0f, m_func[cell]) / m_integral : 1.0f;
    }

private:
    std::vector<float> m_func;
    std::vector<float> m_cdf;
    float m_integral = 0.0f;
};

/// f(u, v) on a width x height grid over [0,1)^2, row-major (v selects the row).
class Distribution2D {
public:
    Distribution2D() = default;
    Distribution2D(std::vector<float> const& values, int width, int height) : m_width(width), m_height(height) {
        std::vector<float> rowIntegrals;
        for (int y = 0; y < height; ++y) {
            m_rows.emplace_back(std::vector<float>(values.begin() + static_cast<std::ptrdiff_t>(y) * width,
                                                   values.begin() + static_cast<std::ptrdiff_t>(y + 1) * width));
            rowIntegrals.push_back(m_rows.back().integral());
        }
        m_marginal = Distribution1D(rowIntegrals);
    }
    bool empty() const { return m_rows.empty(); }
    Vec2 sample(Vec2 const& xi, float& pdf) const {
        float pdfV, pdfU;
        size_t row, column;
        float v = m_marginal.sample(xi.y, pdfV, row);
        float u = m_rows[row].sample(xi.x, pdfU, column);
        pdf = pdfU * pdfV;
        return Vec2(u, v);
    }
    float pdf(Vec2 const& uv) const {
        size_t column = static_cast<size_t>(std::clamp(static_cast<int>(uv.x * m_width), 0, m_width - 1));
        size_t row = static_cast<size_t>(std::clamp(static_cast<int>(uv.y * m_height), 0, m_height - 1));
        return m_marginal.density(row) * m_rows[row].density(column);
    }

private:
    int m_width = 0, m_height = 0;
    std::vector<Distribution1D> m_rows;
    Distribution1D m_marginal;
};

}  // namespace bxdflab
