#include "scene/shapes/PatchPrimvars.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/Error.h"
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

class PatchValues final : public ParametricValues {
public:
    PatchValues(Param const& param, int components, PatchLayout const& layout)
        : m_values(param.floats), m_c(static_cast<size_t>(components)), m_layout(layout) {
        std::string const& cls = param.decl.storageClass;
        m_uniform = cls == "uniform";
        // A bilinear mesh's vertices are its patches' corners.
        m_vertex = (cls.empty() || cls == "vertex") && layout.bicubic;
        m_cornersU = layout.uPeriodic ? layout.patchesU : layout.patchesU + 1;
        m_cornersV = layout.vPeriodic ? layout.patchesV : layout.patchesV + 1;
        size_t const wanted = m_uniform  ? static_cast<size_t>(layout.patchesU) * static_cast<size_t>(layout.patchesV)
                              : m_vertex ? static_cast<size_t>(layout.nu) * static_cast<size_t>(layout.nv)
                                         : static_cast<size_t>(m_cornersU) * static_cast<size_t>(m_cornersV);
        if (m_values.size() != wanted * m_c)
            throw RibError(param.location, "primvar \"" + param.name() + "\" (" + (cls.empty() ? "vertex" : cls) +
                                               ") needs " + std::to_string(wanted) + " values here (" +
                                               (m_uniform ? "one per patch" : m_vertex ? "one per control point"
                                                                                       : "one per patch corner") +
                                               "), got " + std::to_string(m_values.size() / m_c));
    }
    bool uniform() const { return m_uniform; }

    void at(unsigned, float meshU, float meshV, float* out) const override {
        float u, v;
        int const pu = locate(meshU, m_layout.patchesU, u), pv = locate(meshV, m_layout.patchesV, v);
        std::fill(out, out + m_c, 0.0f);
        if (m_uniform) {
            add(out, static_cast<size_t>(pv) * static_cast<size_t>(m_layout.patchesU) + static_cast<size_t>(pu), 1.0f);
        } else if (m_vertex) {
            float wu[4], dwu[4], wv[4], dwv[4];
            m_layout.uBasis.weights(u, wu, dwu);
            m_layout.vBasis.weights(v, wv, dwv);
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {
                    int const col = (pu * m_layout.uBasis.step + i) % m_layout.nu;
                    int const row = (pv * m_layout.vBasis.step + j) % m_layout.nv;
                    add(out, static_cast<size_t>(row) * static_cast<size_t>(m_layout.nu) + static_cast<size_t>(col),
                        wu[i] * wv[j]);
                }
        } else {
            auto corner = [&](int i, int j) {
                return static_cast<size_t>((pv + j) % m_cornersV) * static_cast<size_t>(m_cornersU) +
                       static_cast<size_t>((pu + i) % m_cornersU);
            };
            add(out, corner(0, 0), (1 - u) * (1 - v));
            add(out, corner(1, 0), u * (1 - v));
            add(out, corner(0, 1), (1 - u) * v);
            add(out, corner(1, 1), u * v);
        }
    }

private:
    void add(float* out, size_t item, float weight) const {
        for (size_t k = 0; k < m_c; ++k) out[k] += weight * m_values[item * m_c + k];
    }
    std::vector<float> m_values;
    size_t m_c;
    PatchLayout m_layout;
    bool m_uniform = false, m_vertex = false;
    int m_cornersU = 0, m_cornersV = 0;
};

}  // namespace

void addPatchPrimvars(MeshData& mesh, ParamList const& params, PatchLayout const& layout) {
    for (Param const& p : params.all()) {
        int const components = primvarComponents(p);
        if (components == 0 || p.used || isGeometryParameter(p.name()) || p.decl.storageClass == "constant") continue;
        auto values = std::make_shared<PatchValues const>(p, components, layout);
        p.used = true;
        Primvar var;
        var.name = p.name();
        var.type = p.decl.type;
        var.components = components;
        var.detail = values->uniform() ? Primvar::Detail::Uniform : Primvar::Detail::Varying;
        var.parametric = std::move(values);
        mesh.primvars.add(std::move(var));
    }
}

}  // namespace bxdflab
