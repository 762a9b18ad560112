#include "scene/shapes/PatchPrimvars.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/Primvars.h"

namespace bxdflab {
namespace {

/// The patch a mesh parameter falls in (0 to patches - 1) and the parameter within it.
int locate(float meshParameter, int patches, float& local) {
    float const x = meshParameter * static_cast<float>(patches);
    int const patch = std::clamp(static_cast<int>(std::floor(x)), 0, patches - 1);
    local = x - static_cast<float>(patch);
    return patch;
}

class PatchValues final : public LaidOutValues {
public:
    PatchValues(Param const& param, int components, PatchLayout const& layout)
        : LaidOutValues(param, components), m_layout(layout) {
        // A bilinear mesh's vertices are its patches' corners.
        m_throughBasis = m_vertexClass && layout.bicubic;
        m_cornersU = layout.uPeriodic ? layout.patchesU : layout.patchesU + 1;
        m_cornersV = layout.vPeriodic ? layout.patchesV : layout.patchesV + 1;
        if (m_uniform)
            requireCount(param, static_cast<size_t>(layout.patchesU) * static_cast<size_t>(layout.patchesV),
                         "one per patch");
        else if (m_throughBasis)
            requireCount(param, static_cast<size_t>(layout.nu) * static_cast<size_t>(layout.nv),
                         "one per control point");
        else
            requireCount(param, static_cast<size_t>(m_cornersU) * static_cast<size_t>(m_cornersV),
                         "one per patch corner");
    }

    void at(unsigned, float meshU, float meshV, float* out) const override {
        float u, v;
        int const pu = locate(meshU, m_layout.patchesU, u), pv = locate(meshV, m_layout.patchesV, v);
        if (!m_uniform && !m_throughBasis) {
            auto corner = [&](int i, int j) {
                return static_cast<size_t>((pv + j) % m_cornersV) * static_cast<size_t>(m_cornersU) +
                       static_cast<size_t>((pu + i) % m_cornersU);
            };
            blend(out, corner(0, 0), corner(1, 0), corner(0, 1), corner(1, 1), u, v);
            return;
        }
        std::fill(out, out + m_c, 0.0f);
        if (m_uniform) {
            add(out,
                static_cast<size_t>(pv) * static_cast<size_t>(m_layout.patchesU) + static_cast<size_t>(pu),
                1.0f);
            return;
        }
        float wu[4], dwu[4], wv[4], dwv[4];
        m_layout.uBasis.weights(u, wu, dwu);
        m_layout.vBasis.weights(v, wv, dwv);
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                int const col = (pu * m_layout.uBasis.step + i) % m_layout.nu;
                int const row = (pv * m_layout.vBasis.step + j) % m_layout.nv;
                add(out,
                    static_cast<size_t>(row) * static_cast<size_t>(m_layout.nu) + static_cast<size_t>(col),
                    wu[i] * wv[j]);
            }
    }

private:
    PatchLayout m_layout;
    bool m_throughBasis = false;  ///< vertex values of a bicubic mesh, at its control points
    int m_cornersU = 0, m_cornersV = 0;
};

}  // namespace

void addPatchPrimvars(MeshData& mesh, ParamList const& params, PatchLayout const& layout) {
    addParametricPrimvars<PatchValues>(mesh.primvars, params, layout);
}

}  // namespace bxdflab
