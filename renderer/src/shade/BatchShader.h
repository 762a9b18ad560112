// Turns a set of ray hits into shading batches: groups the hits by Bxdf
// instance (a counting sort that keeps their order), and for each group
// builds its RixShadingContext, asks the plugin for its Bxdf (BeginScatter),
// hands the batch to a visitor, and ends it (EndScatter). Camera hits and
// every bounce of the path tracer go through here; so do the presence
// queries of cut-out surfaces (BeginOpacity), batched the same way.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "RixBxdf.h"
#include "core/Diagnostics.h"
#include "scene/Scene.h"
#include "shade/BxdfInstance.h"
#include "shade/MemoryArena.h"
#include "shade/ShadingContextImpl.h"

namespace bxdflab {

/// One batch: the context, its Bxdf, its random numbers, and which of the
/// input hits (by index) its points are.
struct ShadeGroup {
    ShadingContextImpl const& ctx;
    RixBxdf& bxdf;
    RixRNG& rng;
    int const* source;  ///< source[j]: index in the input of point j
};

struct ShadingCounters {
    BuiltinCounters builtins;
    std::atomic<uint64_t> shadePoints{0};
    std::atomic<uint64_t> batches{0};
    std::atomic<uint64_t> presencePoints{0};  ///< hits whose presence a Bxdf was asked for
};

class BatchShader {
public:
    BatchShader(Scene const& scene, std::vector<std::unique_ptr<BxdfInstance>> const& materials, float pixelSpread,
                ShadingCounters& counters, Diagnostics& diagnostics, RixTexture* textures = nullptr)
        : m_scene(scene), m_materials(materials), m_pixelSpread(pixelSpread), m_counters(counters),
          m_diagnostics(diagnostics), m_textures(textures) {}

    using Visitor = std::function<void(ShadeGroup&)>;
    /// Shades hits[0..count) that hit something; samples[i] is hit i's place
    /// in its random sequence. Memory the visitor allocates from the context
    /// is released when its group ends.
    void shade(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count, MemoryArena& arena,
               Visitor const& visit) const;
    /// presence[i]: how present the point hits[i] is (RixOpacity::GetPresence,
    /// in [0, 1]); 1 for a miss and for every Bxdf that does not compute presence.
    void presence(HitRecord const* hits, int count, MemoryArena& arena, float* presence) const;
    /// Whether some Bxdf of the scene computes presence (k_ComputesPresence).
    bool anyPresence() const;

private:
    /// The hits by material: order[starts[m]..starts[m + 1]) are the indices
    /// of material m's hits, in input order (order lives in the arena).
    struct Groups {
        std::vector<int> starts;
        int* order = nullptr;
    };
    Groups group(HitRecord const* hits, int count, MemoryArena& arena) const;

    Scene const& m_scene;
    std::vector<std::unique_ptr<BxdfInstance>> const& m_materials;
    float m_pixelSpread;
    ShadingCounters& m_counters;
    Diagnostics& m_diagnostics;
    RixTexture* m_textures;
};

}  // namespace bxdflab
