#include "scene/shapes/NurbsPrimvars.h"

#include <algorithm>
#include <memory>

#include "scene/shapes/Primvars.h"

namespace bxdflab {
namespace {

/// The segment of one direction a parameter falls in (0 to segments - 1,
/// counting empty ones, as the specification counts values) and where in it,
/// from 0 to 1. A segment's ends are the knots order - 1 + segment and the next.
int locateSegment(std::vector<float> const& knots, int count, int order, float t, float& local) {
    int const segments = count - order + 1;
    int segment = 0;
    for (int i = 1; i < segments; ++i)
        if (knots[static_cast<size_t>(order - 1 + i)] <= t) segment = i;
    float const lo = knots[static_cast<size_t>(order - 1 + segment)],
                hi = knots[static_cast<size_t>(order + segment)];
    local = hi > lo ? std::clamp((t - lo) / (hi - lo), 0.0f, 1.0f) : 0.0f;
    return segment;
}

class NurbsValues final : public LaidOutValues {
public:
    NurbsValues(Param const& param, int components, std::shared_ptr<NurbsDesc const> const& shared)
        : LaidOutValues(param, components), m_nurbs(shared) {
        NurbsDesc const& nurbs = *shared;
        m_segmentsU = nurbs.nu - nurbs.uorder + 1;
        m_segmentsV = nurbs.nv - nurbs.vorder + 1;
        if (m_uniform)
            requireCount(param, static_cast<size_t>(m_segmentsU) * static_cast<size_t>(m_segmentsV),
                         "one per segment");
        else if (m_vertexClass)
            requireCount(param, static_cast<size_t>(nurbs.nu) * static_cast<size_t>(nurbs.nv),
                         "one per control point");
        else
            requireCount(param, static_cast<size_t>(m_segmentsU + 1) * static_cast<size_t>(m_segmentsV + 1),
                         "one per segment corner");
    }

    void at(unsigned, float u, float v, float* out) const override {
        if (m_vertexClass) {
            atControlPoints(u, v, out);
            return;
        }
        float su, sv;
        int const iu = locateSegment(m_nurbs->uknot, m_nurbs->nu, m_nurbs->uorder, u, su);
        int const iv = locateSegment(m_nurbs->vknot, m_nurbs->nv, m_nurbs->vorder, v, sv);
        if (m_uniform) {
            std::fill(out, out + m_c, 0.0f);
            add(out, static_cast<size_t>(iv) * static_cast<size_t>(m_segmentsU) + static_cast<size_t>(iu),
                1.0f);
            return;
        }
        size_t const row = static_cast<size_t>(m_segmentsU + 1);
        auto corner = [&](int i, int j) {
            return static_cast<size_t>(iv + j) * row + static_cast<size_t>(iu + i);
        };
        blend(out, corner(0, 0), corner(1, 0), corner(0, 1), corner(1, 1), su, sv);
    }

private:
    /// As the points: sum N_i(u) N_j(v) w_ij value_ij / sum N_i(u) N_j(v) w_ij,
    /// so that a vertex primvar holding the control points gives the surface's P.
    void atControlPoints(float u, float v, float* out) const {
        std::fill(out, out + m_c, 0.0f);
        std::vector<float> Nu, dNu, Nv, dNv;
        bsplineBasis(m_nurbs->uknot, m_nurbs->nu, m_nurbs->uorder, u, Nu, dNu);
        bsplineBasis(m_nurbs->vknot, m_nurbs->nv, m_nurbs->vorder, v, Nv, dNv);
        float weightSum = 0.0f;
        for (int j = 0; j < m_nurbs->nv; ++j) {
            if (Nv[static_cast<size_t>(j)] == 0.0f) continue;
            for (int i = 0; i < m_nurbs->nu; ++i) {
                size_t const point =
                    static_cast<size_t>(j) * static_cast<size_t>(m_nurbs->nu) + static_cast<size_t>(i);
                float const weight =
                    Nu[static_cast<size_t>(i)] * Nv[static_cast<size_t>(j)] * m_nurbs->Pw[point].w;
                add(out, point, weight);
                weightSum += weight;
            }
        }
        if (weightSum != 0.0f)
            for (size_t k = 0; k < m_c; ++k) out[k] /= weightSum;
    }

    std::shared_ptr<NurbsDesc const> m_nurbs;  ///< the patch's knots, orders and weights, kept once for its primvars
    int m_segmentsU = 0, m_segmentsV = 0;
};

}  // namespace

void addNurbsPrimvars(MeshData& mesh, ParamList const& params, NurbsDesc const& nurbs) {
    auto const shared = std::make_shared<NurbsDesc const>(nurbs);
    addParametricPrimvars<NurbsValues>(mesh.primvars, params, shared);
}

}  // namespace bxdflab
