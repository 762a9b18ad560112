// The pixel filter (PixelFilter "gaussian" 2 2): how much a sample at an
// offset from a pixel's centre counts toward that pixel. Samples are drawn
// from the filter itself (filter importance sampling), so each pixel stays an
// independent estimate whose sample variance means what it says; a filter
// with negative lobes (catmull-rom, sinc, mitchell) gives the samples drawn
// there a negative weight.
#pragma once

#include <string>
#include <vector>

#include "core/Distribution.h"
#include "core/Math.h"

namespace bxdflab {

/// The filters this renderer has, by RenderMan's names.
std::vector<std::string> const& pixelFilterNames();

class PixelFilter {
public:
    /// A box one pixel wide: each sample counts for the pixel it falls in.
    PixelFilter() : PixelFilter("box", 1.0f, 1.0f) {}
    /// `name` one of pixelFilterNames(); widths in pixels, above 0.
    PixelFilter(std::string const& name, float xwidth, float ywidth);

    /// Where a sample goes, from two uniform numbers in [0, 1): its offset
    /// from the pixel's lower corner (in [0, 1) for the one-pixel box), and
    /// the weight it counts with (1 for filters that never go below 0).
    Vec2 sample(float u1, float u2, float& weight) const;
    /// The one-pixel box: samples stay in their pixel with weight 1.
    bool isUnitBox() const { return m_unitBox; }
    /// Whether the filter goes below 0 anywhere (then some samples' weights are negative).
    bool hasNegativeLobes() const { return absoluteWeight() != 1.0f; }
    /// Every sample's |weight|: the integral of |filter| over the integral of the filter.
    float absoluteWeight() const { return m_x.scale * m_y.scale; }

private:
    /// One direction of the (separable) filter, tabulated in cells across
    /// its width: offsets are drawn in proportion to |filter|, and a sample
    /// counts with the sign of its cell times integral |filter| / integral
    /// filter (exactly 1 for a filter that never goes below 0).
    struct Axis {
        float halfWidth = 0.5f;
        Distribution1D absolute;     ///< |filter| per cell
        std::vector<bool> negative;  ///< the cells where the filter is below 0
        float scale = 1.0f;
        float sample(float u, float& weight) const;
    };
    static Axis makeAxis(std::string const& name, float width);
    Axis m_x, m_y;
    bool m_unitBox = false;
};

}  // namespace bxdflab
