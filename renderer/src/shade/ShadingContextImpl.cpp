#include "shade/ShadingContextImpl.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "core/Error.h"
#include "shade/ParamTypes.h"

namespace bxdflab {
namespace {

bool isTriple(RixSCType type) {
    return type == k_RixSCPoint || type == k_RixSCVector || type == k_RixSCNormal || type == k_RixSCColor;
}

void const* replicate(void const* value, size_t elementSize, int count, BatchMemory& memory) {
    auto* out = static_cast<std::byte*>(memory.allocate(elementSize * static_cast<size_t>(count), 16));
    for (int i = 0; i < count; ++i) std::memcpy(out + elementSize * static_cast<size_t>(i), value, elementSize);
    return out;
}

}  // namespace

bool isFloatBuiltin(RixShadingContext::BuiltinId id) {
    switch (id) {
        case RixShadingContext::k_VLen:
        case RixShadingContext::k_u:
        case RixShadingContext::k_v:
        case RixShadingContext::k_du:
        case RixShadingContext::k_dv:
        case RixShadingContext::k_s:
        case RixShadingContext::k_t:
        case RixShadingContext::k_time:
        case RixShadingContext::k_biasR:
        case RixShadingContext::k_PRadius: return true;
        default: return false;
    }
}

RixSCDetail evalUniformParam(NodeParams const& node, ParamQuery const& query, void const** result, int numPts,
                             BatchMemory& memory) {
    int const id = query.id, arrayIndex = query.arrayIndex;
    RixSCType const wanted = query.wanted;
    size_t const elementSize = query.elementSize;
    void const* const dflt = query.dflt;
    bool const promote = query.promote;
    auto fallback = [&](RixSCDetail detail) {
        *result = promote && dflt ? replicate(dflt, elementSize, numPts, memory) : dflt;
        return detail;
    };
    ParamValue const* value = node.value(id);
    if (!value) return fallback(k_RixSCInvalidDetail);
    // Points, vectors and normals are interchangeable; colours are not.
    bool typeOk = value->type == wanted || (isTriple(value->type) && isTriple(wanted) && value->type != k_RixSCColor &&
                                            wanted != k_RixSCColor);
    if (!typeOk) return fallback(k_RixSCInvalidDetail);
    if (!value->set) return fallback(k_RixSCUniform);

    size_t index = arrayIndex > 0 ? static_cast<size_t>(arrayIndex) : 0;
    void const* source = nullptr;
    switch (value->type) {
        case k_RixSCInteger:
            if (index < value->ints.size()) source = &value->ints[index];
            break;
        case k_RixSCString:
            if (index < value->strings.size()) source = &value->strings[index];
            break;
        default: {
            size_t floatsPerItem = elementSize / sizeof(float);
            if ((index + 1) * floatsPerItem <= value->floats.size()) source = &value->floats[index * floatsPerItem];
        }
    }
    if (!source) return fallback(k_RixSCInvalidDetail);
    *result = promote ? replicate(source, elementSize, numPts, memory) : source;
    return k_RixSCUniform;
}

ShadingContextImpl::ShadingContextImpl(Scene const& scene, BxdfInstance const& material, HitRecord const* hits,
                                       int count, float pixelSpread, MemoryArena& arena, RixInterface* messages,
                                       BuiltinCounters& counters, RixTexture* textures)
    : m_scene(scene),
      m_material(material),
      m_hits(hits),
      m_pixelSpread(pixelSpread),
      m_memory(arena),
      m_messages(messages),
      m_counters(counters),
      m_textures(textures) {
    numPts = count;
}

void ShadingContextImpl::computeSurfaceGroup() const {
    auto* P = m_memory.allocArray<RtPoint3>(static_cast<size_t>(numPts));
    auto* Nn = m_memory.allocArray<RtNormal3>(static_cast<size_t>(numPts));
    auto* Ngn = m_memory.allocArray<RtNormal3>(static_cast<size_t>(numPts));
    auto* biasR = m_memory.allocArray<float>(static_cast<size_t>(numPts));
    for (int i = 0; i < numPts; ++i) {
        SurfaceBasics b = m_scene.shapes[m_hits[i].geomID]->basics(m_hits[i]);
        P[i] = toRt(b.P);
        Nn[i] = toRt(b.N);
        Ngn[i] = toRt(b.Ng);
        // P's error bound projected on the normal: the offset that clears it.
        biasR[i] = glm::dot(glm::abs(b.Ng), b.pError);
    }
    m_builtins[k_P] = P;
    m_builtins[k_Po] = P;  // nothing is displaced
    m_builtins[k_Nn] = Nn;
    m_builtins[k_Non] = Nn;  // nothing is displaced
    m_builtins[k_Ngn] = Ngn;
    m_builtins[k_biasR] = biasR;
    m_counters.surfacePoints.fetch_add(static_cast<uint64_t>(numPts), std::memory_order_relaxed);
}

void ShadingContextImpl::computeParameterGroup() const {
    float* uvst[4];
    for (auto& array : uvst) array = m_memory.allocArray<float>(static_cast<size_t>(numPts));
    for (int i = 0; i < numPts; ++i) {
        Shape const& shape = *m_scene.shapes[m_hits[i].geomID];
        SurfaceParameters p = shape.parameters(m_hits[i]);
        if (shape.hasTextureCoordinates) {  // TextureCoordinates: (s, t) between four corners
            float const* c = shape.textureCoordinates;
            float u = p.u, v = p.v;
            p.s = (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[2] + (1 - u) * v * c[4] + u * v * c[6];
            p.t = (1 - u) * (1 - v) * c[1] + u * (1 - v) * c[3] + (1 - u) * v * c[5] + u * v * c[7];
        }
        uvst[0][i] = p.u;
        uvst[1][i] = p.v;
        uvst[2][i] = p.s;
        uvst[3][i] = p.t;
    }
    m_builtins[k_u] = uvst[0];
    m_builtins[k_v] = uvst[1];
    m_builtins[k_s] = uvst[2];
    m_builtins[k_t] = uvst[3];
    m_counters.parameterPoints.fetch_add(static_cast<uint64_t>(numPts), std::memory_order_relaxed);
}

void ShadingContextImpl::computeView() const {
    auto* Vn = m_memory.allocArray<RtVector3>(static_cast<size_t>(numPts));
    auto* VLen = m_memory.allocArray<float>(static_cast<size_t>(numPts));
    auto* PRadius = m_memory.allocArray<float>(static_cast<size_t>(numPts));
    for (int i = 0; i < numPts; ++i) {
        float len = glm::length(m_hits[i].dir);
        Vn[i] = toRt(-m_hits[i].dir / len);
        VLen[i] = m_hits[i].t * len;
        PRadius[i] = VLen[i] * m_pixelSpread;  // the ray cone's radius at P, as du and dv take it
    }
    m_builtins[k_Vn] = Vn;
    m_builtins[k_VLen] = VLen;
    m_builtins[k_PRadius] = PRadius;
}

void ShadingContextImpl::computeTangentGroup() const {
    if (!m_builtins[k_Nn]) computeSurfaceGroup();
    if (!m_builtins[k_VLen]) computeView();
    auto const* Nn = static_cast<RtNormal3 const*>(m_builtins[k_Nn]);
    auto const* VLen = static_cast<float const*>(m_builtins[k_VLen]);
    auto* dPdu = m_memory.allocArray<RtVector3>(static_cast<size_t>(numPts));
    auto* dPdv = m_memory.allocArray<RtVector3>(static_cast<size_t>(numPts));
    auto* Tn = m_memory.allocArray<RtVector3>(static_cast<size_t>(numPts));
    auto* du = m_memory.allocArray<float>(static_cast<size_t>(numPts));
    auto* dv = m_memory.allocArray<float>(static_cast<size_t>(numPts));
    for (int i = 0; i < numPts; ++i) {
        SurfaceTangents t = m_scene.shapes[m_hits[i].geomID]->tangents(m_hits[i]);
        dPdu[i] = toRt(t.dPdu);
        dPdv[i] = toRt(t.dPdv);
        Vec3 n = toVec3(Nn[i]);
        Tn[i] = toRt(safeNormalize(t.dPdu - n * glm::dot(n, t.dPdu)));
        // The parametric change across the pixel footprint (ray-cone estimate).
        float footprint = VLen[i] * m_pixelSpread;
        float lu = glm::length(t.dPdu), lv = glm::length(t.dPdv);
        du[i] = lu > 0.0f ? footprint / lu : 0.0f;
        dv[i] = lv > 0.0f ? footprint / lv : 0.0f;
    }
    m_builtins[k_dPdu] = dPdu;
    m_builtins[k_dPdv] = dPdv;
    m_builtins[k_Tn] = Tn;
    m_builtins[k_du] = du;
    m_builtins[k_dv] = dv;
    m_counters.tangentPoints.fetch_add(static_cast<uint64_t>(numPts), std::memory_order_relaxed);
}

int ShadingContextImpl::Builtin(BuiltinId id, RixSCType wanted, void const** result) const {
    *result = nullptr;
    if (id < 0 || id >= k_numBuiltins) return 1;
    if (isFloatBuiltin(id) ? wanted != k_RixSCFloat : !isTriple(wanted)) return 1;
    if (!m_builtins[id]) {
        switch (id) {
            case k_Vn:
            case k_VLen:
            case k_PRadius: computeView(); break;
            case k_Tn:
            case k_dPdu:
            case k_dPdv:
            case k_du:
            case k_dv: computeTangentGroup(); break;
            case k_u:
            case k_v:
            case k_s:
            case k_t: computeParameterGroup(); break;
            case k_dPdtime: {
                auto* velocity = m_memory.allocArray<RtVector3>(static_cast<size_t>(numPts));
                for (int i = 0; i < numPts; ++i)
                    velocity[i] = toRt(m_scene.shapes[m_hits[i].geomID]->velocity(m_hits[i]));
                m_builtins[id] = velocity;
                break;
            }
            case k_time: {
                auto* time = m_memory.allocArray<RtFloat>(static_cast<size_t>(numPts));
                for (int i = 0; i < numPts; ++i) time[i] = m_hits[i].time;
                m_builtins[id] = time;
                break;
            }
            default: computeSurfaceGroup(); break;
        }
    }
    *result = m_builtins[id];
    return 0;
}

RixSCDetail ShadingContextImpl::Param(int id, int arrayIndex, RixSCType wanted, size_t elementSize,
                                      void const** result, void const* dflt, bool promote) const {
    return evalParam(m_material.params(), id, arrayIndex, wanted, elementSize, result, dflt, promote);
}

int ShadingContextImpl::ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo,
                                  int* arrayLength) const {
    return m_material.params().describe(id, type, cinfo, arrayLength);
}

RixSCDetail ShadingContextImpl::evalParam(NodeParams const& node, int id, int arrayIndex, RixSCType wanted,
                                          size_t elementSize, void const** result, void const* dflt,
                                          bool promote) const {
    ParamConnection const* link = node.connection(id);
    ParamValue const* declared = node.value(id);
    if (link && declared && connectable(declared->type, wanted)) {
        if (RixPattern::OutputSpecification const* out = patternOutput(*link->pattern, link->output)) {
            if (out->detail == k_RixSCVarying) {
                *result = out->value;
                return k_RixSCVarying;
            }
            *result = promote ? replicate(out->value, elementSize, numPts, m_memory) : out->value;
            return k_RixSCUniform;
        }
    }
    if (!link && !m_scene.primvarNames.empty() &&
        primvarOverride(node, id, wanted, elementSize, result, dflt) == k_RixSCVarying)
        return k_RixSCVarying;
    return evalUniformParam(node, {id, arrayIndex, wanted, elementSize, dflt, promote}, result, numPts, m_memory);
}

RixSCDetail ShadingContextImpl::primvarOverride(NodeParams const& node, int id, RixSCType wanted, size_t elementSize,
                                                void const** result, void const* dflt) const {
    bool const numeric = wanted == k_RixSCFloat || wanted == k_RixSCColor || isTriple(wanted);
    char const* name = node.name(id);
    if (!numeric || !*name || !m_scene.primvarNames.count(name)) return k_RixSCInvalidDetail;
    int const components = static_cast<int>(elementSize / sizeof(float));
    void const* own = nullptr;
    evalUniformParam(node, {id, -1, wanted, elementSize, dflt, false}, &own, numPts, m_memory);
    float* values = m_memory.allocArray<float>(static_cast<size_t>(numPts * components));
    bool found = false;
    for (int i = 0; i < numPts; ++i) {
        float* out = values + i * components;
        Shape const& shape = *m_scene.shapes[m_hits[i].geomID];
        Primvar const* var = shape.primvars.find(name);
        if (var && var->components == components) {
            shape.primvar(*var, m_hits[i], out);
            found = true;
        } else if (own) {
            std::memcpy(out, own, elementSize);
        } else {
            std::fill(out, out + components, 0.0f);
        }
    }
    if (!found) return k_RixSCInvalidDetail;
    *result = values;
    return k_RixSCVarying;
}

/// The context a pattern computes in: the same points, builtins, primvars and
/// memory as the Bxdf's context; its own parameters.
class PatternContext final : public RixShadingContext {
public:
    PatternContext(ShadingContextImpl const& parent, PatternInstance const& pattern)
        : m_parent(parent), m_pattern(pattern) {
        numPts = parent.numPts;
        scTraits = parent.scTraits;
        m_id = parent.Id();
    }
    RixInterface* GetRixInterface(RixInterfaceId id) const override {
        if (id == k_RixMessages) return &m_pattern.plugin().messages();
        return m_parent.GetRixInterface(id);
    }

protected:
    int Builtin(BuiltinId id, RixSCType wanted, void const** result) const override {
        return m_parent.Builtin(id, wanted, result);
    }
    RixSCDetail Param(int id, int arrayIndex, RixSCType wanted, size_t elementSize, void const** result,
                      void const* dflt, bool promote) const override {
        return m_parent.evalParam(m_pattern.params(), id, arrayIndex, wanted, elementSize, result, dflt, promote);
    }
    void* Allocate(size_t bytes, size_t alignment) const override { return m_parent.Allocate(bytes, alignment); }
    int ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const override {
        return m_pattern.params().describe(id, type, cinfo, arrayLength);
    }
    RixSCDetail PrimVar(RtUString const name, RixSCType wanted, void const** result, RtFloat const** radius,
                        void const* fill) const override {
        return m_parent.PrimVar(name, wanted, result, radius, fill);
    }
    int TransformValues(TransformInterpretation interpretation, RtUString const fromSpace, RtUString const toSpace,
                        RtFloat3* values, RtFloat* radius) const override {
        return m_parent.TransformValues(interpretation, fromSpace, toSpace, values, radius);
    }

private:
    ShadingContextImpl const& m_parent;
    PatternInstance const& m_pattern;
};

namespace {

std::string patternFault(PatternInstance const& pattern, std::string const& what) {
    return "plugin \"" + pattern.plugin().name() + "\" (Pattern \"" + pattern.handle() + "\" at " +
           pattern.where().str() + ", loaded from " + pattern.plugin().path() + ") " + what;
}

}  // namespace

RixPattern::OutputSpecification const* ShadingContextImpl::patternOutput(PatternInstance const& pattern,
                                                                         int output) const {
    // An output left uncomputed (k_RixSCInvalidDetail, as RenderMan's patterns mark
    // those nothing reads) is as good as absent: the parameter keeps its own value.
    auto pick = [output](PatternOutputs const& done) -> RixPattern::OutputSpecification const* {
        for (int k = 0; k < done.count; ++k)
            if (done.outputs[k].paramId == output && done.outputs[k].detail != k_RixSCInvalidDetail)
                return &done.outputs[k];
        return nullptr;
    };
    for (PatternOutputs const& done : m_patternOutputs)
        if (done.pattern == &pattern) return pick(done);

    PatternContext ctx(*this, pattern);
    RtInt count = 0;
    RixPattern::OutputSpecification* outputs = nullptr;
    try {
        int status = pattern.plugin().pattern()->ComputeOutputParams(&ctx, &count, &outputs, pattern.instanceData(),
                                                                     nullptr);
        if (status != 0) count = 0;  // a pattern that declines: its connections use their own values
    } catch (PluginFault const&) {
        throw;
    } catch (std::exception const& e) {
        throw PluginFault(patternFault(pattern, std::string("threw while computing its outputs: ") + e.what()));
    } catch (...) {
        throw PluginFault(patternFault(pattern, "threw something that is not a std::exception"));
    }
    auto const& table = pattern.plugin().paramTable();
    if (count < 0 || count > static_cast<int>(table.size()) || (count > 0 && !outputs))
        throw PluginFault(patternFault(pattern, "returned " + std::to_string(count) + " outputs" +
                                                    (outputs ? "" : " and no OutputSpecification array") +
                                                    " from ComputeOutputParams"));
    for (int k = 0; k < count; ++k) {
        auto const& out = outputs[k];
        bool rowOk = out.paramId >= 0 && out.paramId < static_cast<int>(table.size()) &&
                     table[static_cast<size_t>(out.paramId)].access == k_RixSCOutput;
        bool const computed = out.detail != k_RixSCInvalidDetail;
        bool const detailOk = out.detail == k_RixSCUniform || out.detail == k_RixSCVarying;
        if (!rowOk || (computed && (!out.value || !detailOk)))
            throw PluginFault(patternFault(pattern, "returned output " + std::to_string(k) + " with " +
                                                        (!rowOk ? "paramId " + std::to_string(out.paramId) +
                                                                      ", which is not an output of its table"
                                                                : !out.value ? "no values" : "an invalid detail")));
    }
    pattern.counters().evaluations.fetch_add(1, std::memory_order_relaxed);
    pattern.counters().points.fetch_add(static_cast<uint64_t>(numPts), std::memory_order_relaxed);
    m_patternOutputs.push_back({&pattern, count, outputs});
    return pick(m_patternOutputs.back());
}

namespace {

/// Whether a primvar of this type answers a GetPrimVar for `wanted`.
bool primvarMatches(Primvar const& var, RixSCType wanted) {
    switch (wanted) {
        case k_RixSCFloat: return var.components == 1;
        case k_RixSCFloat2: return var.components == 2;
        case k_RixSCColor: return var.type == ParamType::Color;
        case k_RixSCVector:
        case k_RixSCPoint:
        case k_RixSCNormal: return var.components == 3 && var.type != ParamType::Color;
        default: return false;
    }
}

}  // namespace

float* primvarValues(RixSCType wanted, void const* fill, int numPts, BatchMemory& memory) {
    int const components = valuesPerElement(wanted);
    float* values = memory.allocArray<float>(static_cast<size_t>(numPts * components));
    for (int i = 0; i < numPts; ++i)
        for (int c = 0; c < components; ++c)
            values[i * components + c] = fill ? static_cast<float const*>(fill)[c] : 0.0f;
    return values;
}

RixSCDetail ShadingContextImpl::PrimVar(RtUString const name, RixSCType wanted, void const** result,
                                        RtFloat const** radius, void const* fill) const {
    *result = nullptr;
    int const components = valuesPerElement(wanted);
    std::string const wantedName = name.CStr() ? name.CStr() : "";
    float* values = primvarValues(wanted, fill, numPts, m_memory);
    // Primvars here have no filter width: a radius asked for is zero, made only once there is a value.
    auto zeroRadius = [&] {
        if (radius) *radius = primvarValues(k_RixSCFloat, nullptr, numPts, m_memory);
    };
    if (wanted == k_RixSCFloat2 && wantedName == "st") {
        // Every surface has texture coordinates, as in RenderMan: the builtins
        // k_s and k_t already are its st primvar, its TextureCoordinates or its (u, v).
        float const *s, *t;
        Builtin(k_s, k_RixSCFloat, reinterpret_cast<void const**>(&s));
        Builtin(k_t, k_RixSCFloat, reinterpret_cast<void const**>(&t));
        for (int i = 0; i < numPts; ++i) {
            values[2 * i] = s[i];
            values[2 * i + 1] = t[i];
        }
        *result = values;
        zeroRadius();
        return k_RixSCVarying;
    }
    bool found = false, uniform = true;
    Shape const* first = nullptr;
    for (int i = 0; i < numPts; ++i) {
        Shape const& shape = *m_scene.shapes[m_hits[i].geomID];
        Primvar const* var = shape.primvars.find(wantedName);
        if (!var || !primvarMatches(*var, wanted)) {
            uniform = false;
            continue;
        }
        shape.primvar(*var, m_hits[i], values + i * components);
        found = true;
        uniform = uniform && var->detail == Primvar::Detail::Constant && (!first || first == &shape);
        first = &shape;
    }
    if (!found && !fill) {
        if (radius) *radius = nullptr;
        return k_RixSCInvalidDetail;
    }
    *result = values;
    zeroRadius();
    return !found ? k_RixSCInvalidDetail : uniform ? k_RixSCUniform : k_RixSCVarying;
}

bool namesWorldSpace(std::string const& space) {
    return space == "current" || space == "world" || space == "common";
}

namespace {

/// The transform from coordinate system `space` to world space for points of
/// `shape`, or nothing for a space this renderer does not know.
std::optional<Mat4> spaceToWorld(std::string const& space, Scene const& scene, Shape const& shape) {
    if (namesWorldSpace(space)) return Mat4(1.0f);
    if (space == "object") return shape.objectToWorld;
    if (space == "camera") return glm::inverse(scene.camera.worldToCamera);
    auto named = scene.coordinateSystems.find(space);
    if (named != scene.coordinateSystems.end()) return named->second;
    return std::nullopt;
}

}  // namespace

int ShadingContextImpl::TransformValues(TransformInterpretation interpretation, RtUString const fromSpace,
                                        RtUString const toSpace, RtFloat3* values, RtFloat* radius) const {
    std::string const from = fromSpace.CStr(), to = toSpace.CStr();
    if (numPts == 0) return 0;
    Shape const& firstShape = *m_scene.shapes[m_hits[0].geomID];
    if (!spaceToWorld(from, m_scene, firstShape) || !spaceToWorld(to, m_scene, firstShape)) return 1;
    // A batch is mostly one shape: the matrices are worked out again only when it changes.
    Shape const* matricesOf = nullptr;
    Mat4 fromTo(1.0f);
    Mat3 forNormals(1.0f);
    float lengthScale = 1.0f;
    for (int i = 0; i < numPts; ++i) {
        Shape const& shape = *m_scene.shapes[m_hits[i].geomID];
        if (&shape != matricesOf) {
            fromTo = glm::inverse(*spaceToWorld(to, m_scene, shape)) * *spaceToWorld(from, m_scene, shape);
            forNormals = glm::transpose(glm::inverse(Mat3(fromTo)));
            lengthScale = std::cbrt(std::abs(glm::determinant(Mat3(fromTo))));  // a radius: the mean scale
            matricesOf = &shape;
        }
        Vec3 const v = toVec3(values[i]);
        values[i] = toRt(interpretation == k_AsPoints    ? transformPoint(fromTo, v)
                         : interpretation == k_AsVectors ? Mat3(fromTo) * v
                                                         : forNormals * v);
        if (radius) radius[i] *= lengthScale;
    }
    return 0;
}

}  // namespace bxdflab
