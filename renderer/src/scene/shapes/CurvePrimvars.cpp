#include "scene/shapes/CurvePrimvars.h"

#include <algorithm>
#include <memory>

namespace bxdflab {
namespace {

class CurveValues final : public LaidOutValues {
public:
    CurveValues(Param const& param, int components, std::shared_ptr<CurveLayout const> const& layout)
        : LaidOutValues(param, components), m_layout(layout) {
        if (m_uniform)
            requireCount(param, layout->curves, "one per curve");
        else if (m_vertexClass)
            requireCount(param, layout->vertices, "one per control vertex");
        else
            requireCount(param, layout->varyings, "one per segment end");
    }

    /// `face` is the segment drawn, `u` the parameter along it.
    void at(unsigned face, float u, float, float* out) const override {
        CurveLayout::Segment const& segment = m_layout->segments[face];
        if (m_uniform) {
            std::fill(out, out + m_c, 0.0f);
            add(out, segment.curve, 1.0f);
        } else if (!m_vertexClass) {
            unsigned const next = (segment.index + 1) % segment.varyings;  // wraps only when periodic
            mix(out, segment.firstVarying + segment.index, segment.firstVarying + next, u);
        } else if (!m_layout->cubic) {
            unsigned const next = (segment.index + 1) % segment.vertices;
            mix(out, segment.firstVertex + segment.index, segment.firstVertex + next, u);
        } else {
            std::fill(out, out + m_c, 0.0f);
            float w[4], dw[4];
            m_layout->basis.weights(u, w, dw);
            for (unsigned m = 0; m < 4; ++m) {
                unsigned const vertex =
                    (segment.index * static_cast<unsigned>(m_layout->basis.step) + m) % segment.vertices;
                add(out, segment.firstVertex + vertex, w[m]);
            }
        }
    }

private:
    std::shared_ptr<CurveLayout const> m_layout;  ///< shared by the request's primvars
};

}  // namespace

void addCurvePrimvars(PrimvarSet& primvars, ParamList const& params, CurveLayout layout) {
    auto const shared = std::make_shared<CurveLayout const>(std::move(layout));
    addParametricPrimvars<CurveValues>(primvars, params, shared);
}

}  // namespace bxdflab
