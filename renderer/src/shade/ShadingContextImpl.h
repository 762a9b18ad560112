// The renderer's RixShadingContext: a batch of hits on one Bxdf instance.
//
// Builtins are computed lazily, in three groups, the first time anyone (a
// plugin or the integrator) asks for one of them:
//   surface group    P, Nn, Ngn, biasR        (one Shape::basics call per point)
//   parameter group  u, v, s, t               (one Shape::parameters call per point)
//   tangent group    dPdu, dPdv, Tn, du, dv   (one Shape::tangents call per point)
// Vn and VLen come straight from the rays. The counters record how many
// points each group was computed for, which the tests and stats use to prove
// that nothing was computed that no one needed.
#pragma once

#include <atomic>
#include <string>
#include <utility>
#include <vector>

#include "RixShading.h"
#include "scene/Scene.h"
#include "RixPattern.h"
#include "shade/BatchMemory.h"
#include "shade/BxdfInstance.h"
#include "shade/MemoryArena.h"
#include "shade/PatternInstance.h"

namespace bxdflab {

/// What an EvalParam call asks for (the arguments of RixShadingContext::Param).
struct ParamQuery {
    int id;
    int arrayIndex;
    RixSCType wanted;
    size_t elementSize;
    void const* dflt;
    bool promote;
};

/// EvalParam for a node's own (RIB or default) value of a parameter over a
/// batch of numPts points, ignoring connections (shared by every
/// RixShadingContext the renderer builds, the probe's included).
RixSCDetail evalUniformParam(NodeParams const& node, ParamQuery const& query, void const** result, int numPts,
                             BatchMemory& memory);

/// numPts values of a primvar's type, each `fill` (or zeros without one):
/// GetPrimVar's answer before the shapes give theirs.
float* primvarValues(RixSCType wanted, void const* fill, int numPts, BatchMemory& memory);

/// Whether a builtin is one float per point (the others are three).
bool isFloatBuiltin(RixShadingContext::BuiltinId id);

/// Whether a coordinate-system name means world space, where shading happens
/// here ("current", "world", "common").
bool namesWorldSpace(std::string const& space);

struct BuiltinCounters {
    std::atomic<uint64_t> surfacePoints{0};  ///< points whose surface group was computed
    std::atomic<uint64_t> parameterPoints{0};  ///< points whose parameter group was computed
    std::atomic<uint64_t> tangentPoints{0};  ///< points whose tangent group was computed
};

class ShadingContextImpl final : public RixShadingContext {
public:
    /// `hits` must stay valid for the context's life; `pixelSpread` is the
    /// angle one pixel subtends (for du/dv).
    ShadingContextImpl(Scene const& scene, BxdfInstance const& material, HitRecord const* hits, int count,
                       float pixelSpread, MemoryArena& arena, RixInterface* messages, BuiltinCounters& counters,
                       RixTexture* textures = nullptr);

    RixInterface* GetRixInterface(RixInterfaceId id) const override {
        return id == k_RixMessages ? m_messages : id == k_RixTexture ? m_textures : nullptr;
    }
    RixTexture* textures() const { return m_textures; }
    BxdfInstance const& material() const { return m_material; }
    /// What GetBxdf() and Id() answer.
    void setBxdf(RixBxdf* bxdf) { m_bxdf = bxdf; }
    void setId(int id) { m_id = id; }
    HitRecord const& hit(int i) const { return m_hits[i]; }
    /// The shape point i lies on.
    Shape const& shape(int i) const { return *m_scene.shapes[m_hits[i].geomID]; }
    /// Output `output` of `pattern` for this batch, or nullptr when the
    /// pattern did not compute it. The pattern runs on first use (its own
    /// connected inputs first) and its outputs are kept for the batch.
    RixPattern::OutputSpecification const* patternOutput(PatternInstance const& pattern, int output) const;
    /// EvalParam of `node`'s parameter `id` in this batch: a connected
    /// parameter's pattern output, else the node's own value.
    RixSCDetail evalParam(NodeParams const& node, int id, int arrayIndex, RixSCType wanted, size_t elementSize,
                          void const** result, void const* dflt, bool promote) const;

protected:
    int Builtin(BuiltinId id, RixSCType wanted, void const** result) const override;
    RixSCDetail Param(int id, int arrayIndex, RixSCType wanted, size_t elementSize, void const** result,
                      void const* dflt, bool promote) const override;
    void* Allocate(size_t bytes, size_t alignment) const override { return m_memory.allocate(bytes, alignment); }
    int ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const override;
    int TransformValues(TransformInterpretation interpretation, RtUString const fromSpace, RtUString const toSpace,
                        RtFloat3* values, RtFloat* radius) const override;
    RixSCDetail PrimVar(RtUString const name, RixSCType wanted, void const** result, RtFloat const** radius,
                        void const* fill) const override;

private:
    friend class PatternContext;
    struct PatternOutputs {
        PatternInstance const* pattern;
        int count;
        RixPattern::OutputSpecification const* outputs;
    };
    /// A parameter's values from a primvar of the same name, where the shapes
    /// carry one (the parameter's own value elsewhere): k_RixSCVarying, or
    /// k_RixSCInvalidDetail when no shape in the batch has it.
    RixSCDetail primvarOverride(NodeParams const& node, int id, RixSCType wanted, size_t elementSize,
                                void const** result, void const* dflt) const;
    void computeSurfaceGroup() const;
    void computeParameterGroup() const;
    void computeTangentGroup() const;
    void computeView() const;

    Scene const& m_scene;
    BxdfInstance const& m_material;
    HitRecord const* m_hits;
    float m_pixelSpread;
    mutable BatchMemory m_memory;  ///< everything the context hands out
    RixInterface* m_messages;
    BuiltinCounters& m_counters;
    mutable void* m_builtins[k_numBuiltins] = {};
    RixTexture* m_textures;
    mutable std::vector<PatternOutputs> m_patternOutputs;  ///< patterns run in this batch
};

}  // namespace bxdflab
