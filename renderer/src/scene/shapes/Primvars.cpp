#include "scene/shapes/Primvars.h"

#include <algorithm>

#include "core/Error.h"

namespace bxdflab {

LaidOutValues::LaidOutValues(Param const& param, int components)
    : m_values(param.floats),
      m_c(static_cast<size_t>(components)),
      m_uniform(param.decl.storageClass == "uniform"),
      m_vertexClass(param.decl.storageClass.empty() || param.decl.storageClass == "vertex") {}

void LaidOutValues::requireCount(Param const& param, size_t wanted, char const* each) const {
    if (m_values.size() == wanted * m_c) return;
    std::string const& cls = param.decl.storageClass;
    throw RibError(param.location, "primvar \"" + param.name() + "\" (" + (cls.empty() ? "vertex" : cls) +
                                       ") needs " + std::to_string(wanted) + " values here (" + each +
                                       "), got " + std::to_string(m_values.size() / m_c));
}

void LaidOutValues::add(float* out, size_t item, float weight) const {
    for (size_t k = 0; k < m_c; ++k) out[k] += weight * m_values[item * m_c + k];
}

void LaidOutValues::mix(float* out, size_t item0, size_t item1, float t) const {
    std::fill(out, out + m_c, 0.0f);
    add(out, item0, 1 - t);
    add(out, item1, t);
}

void LaidOutValues::blend(float* out, size_t item00, size_t item10, size_t item01, size_t item11, float u,
                          float v) const {
    std::fill(out, out + m_c, 0.0f);
    add(out, item00, (1 - u) * (1 - v));
    add(out, item10, u * (1 - v));
    add(out, item01, (1 - u) * v);
    add(out, item11, u * v);
}

bool isGeometryParameter(std::string const& name) {
    for (char const* g : {"P", "Pw", "Pz", "N", "width", "constantwidth"})
        if (name == g) return true;
    return false;
}

int primvarComponents(Param const& param) {
    if (param.decl.reference || param.decl.untyped) return 0;
    switch (param.decl.type) {
        case ParamType::Float:
        case ParamType::Int: return param.decl.arraySize == 2 ? 2 : param.decl.arraySize == 1 ? 1 : 0;
        case ParamType::Color:
        case ParamType::Point:
        case ParamType::Vector:
        case ParamType::Normal: return param.decl.arraySize == 1 ? 3 : 0;
        default: return 0;
    }
}

PrimvarSet shapePrimvars(ParamList const& params, size_t corners, size_t elements) {
    // RenderMan for Maya records each shape's kind ("mesh", "subdiv") in a string it calls primtype: nothing reads it.
    if (Param const* kind = params.find("primtype"); kind && kind->decl.type == ParamType::String) params.ignore("primtype");
    PrimvarSet set;
    for (Param const& p : params.all()) {
        if (isGeometryParameter(p.name())) continue;
        int components = primvarComponents(p);
        if (components == 0 || p.floats.empty() || p.floats.size() % static_cast<size_t>(components) != 0) continue;
        size_t count = p.floats.size() / static_cast<size_t>(components);
        std::string const& cls = p.decl.storageClass;
        Primvar v;
        v.name = p.name();
        v.type = p.decl.type;
        v.components = components;
        if (count == 1) {
            v.detail = Primvar::Detail::Constant;
        } else if (corners > 0 && count == corners && (cls == "varying" || cls == "vertex")) {
            v.detail = Primvar::Detail::Varying;
        } else if (elements > 0 && count == elements && cls != "constant") {
            v.detail = Primvar::Detail::Uniform;
        } else {
            continue;
        }
        v.values = p.floats;
        p.used = true;
        set.add(std::move(v));
    }
    return set;
}

namespace {

/// s and t given apart, read as one pair.
class SeparateST final : public ParametricValues {
public:
    SeparateST(std::shared_ptr<ParametricValues const> s, std::shared_ptr<ParametricValues const> t)
        : m_s(std::move(s)), m_t(std::move(t)) {}
    void at(unsigned face, float u, float v, float* out) const override {
        m_s->at(face, u, v, &out[0]);
        m_t->at(face, u, v, &out[1]);
    }

private:
    std::shared_ptr<ParametricValues const> m_s, m_t;
};

}  // namespace

std::shared_ptr<ParametricValues const> parametricTextureCoordinates(PrimvarSet const& primvars) {
    auto varying = [&](char const* name, int components) -> std::shared_ptr<ParametricValues const> {
        Primvar const* var = primvars.find(name);
        if (!var || var->components != components || var->detail != Primvar::Detail::Varying) return nullptr;
        return var->parametric;
    };
    if (auto st = varying("st", 2)) return st;
    auto s = varying("s", 1), t = varying("t", 1);
    if (s && t) return std::make_shared<SeparateST const>(s, t);
    return nullptr;
}

void primvarAtCorners(Primvar const& var, float u, float v, float* out) {
    size_t const c = static_cast<size_t>(var.components);
    if (var.detail != Primvar::Detail::Varying || var.values.size() < 4 * c) {
        for (size_t k = 0; k < c; ++k) out[k] = var.values[k];
        return;
    }
    // Corners in RenderMan's order: (0,0) (1,0) (0,1) (1,1).
    for (size_t k = 0; k < c; ++k)
        out[k] = (1 - u) * (1 - v) * var.values[k] + u * (1 - v) * var.values[c + k] + (1 - u) * v * var.values[2 * c + k] +
                 u * v * var.values[3 * c + k];
}

}  // namespace bxdflab
