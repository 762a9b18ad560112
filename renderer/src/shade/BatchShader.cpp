#include "shade/BatchShader.h"

namespace bxdflab {
namespace {

std::string faultOf(BxdfInstance const& material, std::string const& what) {
    return "plugin \"" + material.plugin().name() + "\" (Bxdf \"" + material.handle() + "\" at " + material.where().str() +
           ", loaded from " + material.plugin().path() + ") threw while shading: " + what +
           " (the integrator, or this Bxdf's own code; a Bxdf must not throw)";
}

}  // namespace

void BatchShader::shade(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count, MemoryArena& arena,
                        Visitor const& visit) const {
    size_t numMaterials = m_materials.size();
    MemoryArena::Mark outer = arena.mark();
    // Counting sort by material keeps each group in input order, which keeps renders deterministic.
    std::vector<int> starts(numMaterials + 1, 0);
    for (int i = 0; i < count; ++i)
        if (hits[i].hit()) ++starts[static_cast<size_t>(m_scene.shapes[hits[i].geomID]->material) + 1];
    for (size_t m = 0; m < numMaterials; ++m) starts[m + 1] += starts[m];
    int* order = arena.allocArray<int>(static_cast<size_t>(std::max(1, starts[numMaterials])));
    std::vector<int> fill(starts.begin(), starts.end() - 1);
    for (int i = 0; i < count; ++i)
        if (hits[i].hit()) order[fill[static_cast<size_t>(m_scene.shapes[hits[i].geomID]->material)]++] = i;

    for (size_t m = 0; m < numMaterials; ++m) {
        int begin = starts[m], n = starts[m + 1] - starts[m];
        if (n == 0) continue;
        MemoryArena::Mark groupStart = arena.mark();
        auto* groupHits = arena.allocArray<HitRecord>(static_cast<size_t>(n));
        auto* groupSamples = arena.allocArray<RixRNG::SampleCtx>(static_cast<size_t>(n));
        for (int j = 0; j < n; ++j) {
            groupHits[j] = hits[order[begin + j]];
            groupSamples[j] = samples[order[begin + j]];
        }
        BxdfInstance const& material = *m_materials[m];
        ShadingContextImpl ctx(m_scene, material, groupHits, n, m_pixelSpread, arena, &material.plugin().messages(),
                               m_counters.builtins, m_textures);
        RixRNG rng(groupSamples, n);
        RixBxdfFactory* factory = material.plugin().factory();
        try {
            RixBxdf* bxdf = factory->BeginScatter(&ctx, RixBXLobeTraits::All(), k_RixSCScatterQuery, nullptr,
                                                  material.instanceData());
            ctx.setBxdf(bxdf);
            ctx.setId(static_cast<int>(m));
            if (!bxdf) {
                m_diagnostics.warn("plugin \"" + material.plugin().name() +
                                   "\": BeginScatter returned null; its surfaces render black");
            } else {
                ShadeGroup group{ctx, *bxdf, rng, order + begin};
                visit(group);
                factory->EndScatter(bxdf);
            }
        } catch (PluginFault const&) {
            throw;  // from a batch shaded deeper down the path: already named
        } catch (std::exception const& e) {
            throw PluginFault(faultOf(material, e.what()));
        } catch (...) {
            throw PluginFault(faultOf(material, "an exception that is not a std::exception"));
        }
        arena.release(groupStart);
        m_counters.shadePoints.fetch_add(static_cast<uint64_t>(n), std::memory_order_relaxed);
        m_counters.batches.fetch_add(1, std::memory_order_relaxed);
    }
    arena.release(outer);
}

}  // namespace bxdflab
