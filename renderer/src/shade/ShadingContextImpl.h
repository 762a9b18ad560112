// The renderer's RixShadingContext: a batch of hits on one Bxdf instance.
//
// Builtins are computed lazily, in two groups, the first time anyone (a
// plugin or the integrator) asks for one of them:
//   surface group   P, Nn, Ngn, u, v, s, t   (one Shape::basics call per point)
//   tangent group   dPdu, dPdv, Tn, du, dv   (one Shape::tangents call per point)
// Vn and VLen come straight from the rays. The counters record how many
// points each group was computed for, which the tests and stats use to prove
// that nothing was computed that no one needed.
#pragma once

#include <atomic>

#include "RixShading.h"
#include "scene/Scene.h"
#include "shade/BxdfInstance.h"
#include "shade/MemoryArena.h"

namespace bxdflab {

/// EvalParam for a Bxdf instance's parameters over a batch of numPts points
/// (shared by every RixShadingContext the renderer builds).
RixSCDetail evalInstanceParam(BxdfInstance const& material, int id, int arrayIndex, RixSCType wanted,
                              size_t elementSize, void const** result, void const* dflt, bool promote, int numPts,
                              MemoryArena& arena);

struct BuiltinCounters {
    std::atomic<uint64_t> surfacePoints{0};  ///< points whose surface group was computed
    std::atomic<uint64_t> tangentPoints{0};  ///< points whose tangent group was computed
};

class ShadingContextImpl final : public RixShadingContext {
public:
    /// `hits` must stay valid for the context's life; `pixelSpread` is the
    /// angle one pixel subtends (for du/dv).
    ShadingContextImpl(Scene const& scene, BxdfInstance const& material, HitRecord const* hits, int count,
                       float pixelSpread, MemoryArena& arena, RixInterface* messages, BuiltinCounters& counters);

    RixInterface* GetRixInterface(RixInterfaceId id) const override {
        return id == k_RixMessages ? m_messages : nullptr;
    }
    BxdfInstance const& material() const { return m_material; }
    /// What GetBxdf() and Id() answer.
    void setBxdf(RixBxdf* bxdf) { m_bxdf = bxdf; }
    void setId(int id) { m_id = id; }
    HitRecord const& hit(int i) const { return m_hits[i]; }
    /// Error bounds of P, for spawning rays (computed with the surface group).
    Vec3 const* pError() const;

protected:
    int Builtin(BuiltinId id, RixSCType wanted, void const** result) const override;
    RixSCDetail Param(int id, int arrayIndex, RixSCType wanted, size_t elementSize, void const** result,
                      void const* dflt, bool promote) const override;
    void* Allocate(size_t bytes, size_t alignment) const override { return m_arena.allocate(bytes, alignment); }
    RixSCDetail PrimVar(RtUString const name, RixSCType wanted, void const** result, RtFloat const** radius) const override;

private:
    void computeSurfaceGroup() const;
    void computeTangentGroup() const;
    void computeView() const;

    Scene const& m_scene;
    BxdfInstance const& m_material;
    HitRecord const* m_hits;
    float m_pixelSpread;
    MemoryArena& m_arena;
    RixInterface* m_messages;
    BuiltinCounters& m_counters;
    mutable void* m_builtins[k_numBuiltins] = {};
    mutable Vec3* m_pError = nullptr;
};

}  // namespace bxdflab
