#include "shade/BatchShader.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {
namespace {

std::string faultOf(BxdfInstance const& material, std::string const& what) {
    return "plugin \"" + material.plugin().name() + "\" (Bxdf \"" + material.handle() + "\" at " + material.where().str() +
           ", loaded from " + material.plugin().path() + ") threw while shading: " + what +
           " (the integrator, or this Bxdf's own code; a Bxdf must not throw)";
}

/// Runs `work`, naming the plugin in any exception it lets out.
template <typename Work>
void naming(BxdfInstance const& material, Work&& work) {
    try {
        work();
    } catch (PluginFault const&) {
        throw;  // from a batch shaded deeper down the path: already named
    } catch (std::exception const& e) {
        throw PluginFault(faultOf(material, e.what()));
    } catch (...) {
        throw PluginFault(faultOf(material, "an exception that is not a std::exception"));
    }
}

}  // namespace

BatchShader::Groups BatchShader::group(HitRecord const* hits, int count, MemoryArena& arena) const {
    // Counting sort by material keeps each group in input order, which keeps renders deterministic.
    size_t const numMaterials = m_materials.size();
    Groups groups;
    groups.starts.assign(numMaterials + 1, 0);
    for (int i = 0; i < count; ++i)
        if (hits[i].hit()) ++groups.starts[static_cast<size_t>(m_scene.shapes[hits[i].geomID]->material) + 1];
    for (size_t m = 0; m < numMaterials; ++m) groups.starts[m + 1] += groups.starts[m];
    groups.order = arena.allocArray<int>(static_cast<size_t>(std::max(1, groups.starts[numMaterials])));
    std::vector<int> fill(groups.starts.begin(), groups.starts.end() - 1);
    for (int i = 0; i < count; ++i)
        if (hits[i].hit()) groups.order[fill[static_cast<size_t>(m_scene.shapes[hits[i].geomID]->material)]++] = i;
    return groups;
}

void BatchShader::shade(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count, MemoryArena& arena,
                        Visitor const& visit) const {
    MemoryArena::Mark outer = arena.mark();
    Groups const groups = group(hits, count, arena);
    for (size_t m = 0; m < m_materials.size(); ++m) {
        int begin = groups.starts[m], n = groups.starts[m + 1] - groups.starts[m];
        if (n == 0) continue;
        MemoryArena::Mark groupStart = arena.mark();
        auto* groupHits = arena.allocArray<HitRecord>(static_cast<size_t>(n));
        auto* groupSamples = arena.allocArray<RixRNG::SampleCtx>(static_cast<size_t>(n));
        for (int j = 0; j < n; ++j) {
            groupHits[j] = hits[groups.order[begin + j]];
            groupSamples[j] = samples[groups.order[begin + j]];
        }
        BxdfInstance const& material = *m_materials[m];
        ShadingContextImpl ctx(m_scene, material, groupHits, n, m_pixelSpread, arena, &material.plugin().messages(),
                               m_counters.builtins, m_textures);
        RixRNG rng(groupSamples, n);
        RixBxdfFactory* factory = material.plugin().factory();
        naming(material, [&] {
            RixBxdf* bxdf = factory->BeginScatter(&ctx, RixBXLobeTraits::All(), k_RixSCScatterQuery, nullptr,
                                                  material.instanceData());
            ctx.setBxdf(bxdf);
            ctx.setId(static_cast<int>(m));
            if (!bxdf) {
                m_diagnostics.warn("plugin \"" + material.plugin().name() +
                                   "\": BeginScatter returned null; its surfaces render black");
            } else {
                ShadeGroup group{ctx, *bxdf, rng, groups.order + begin};
                visit(group);
                factory->EndScatter(bxdf);
            }
        });
        arena.release(groupStart);
        m_counters.shadePoints.fetch_add(static_cast<uint64_t>(n), std::memory_order_relaxed);
        m_counters.batches.fetch_add(1, std::memory_order_relaxed);
    }
    arena.release(outer);
}

bool BatchShader::anyPresence() const {
    return std::any_of(m_materials.begin(), m_materials.end(), [](std::unique_ptr<BxdfInstance> const& material) {
        return (material->hints() & RixBxdfFactory::k_ComputesPresence) != 0;
    });
}

void BatchShader::presence(HitRecord const* hits, int count, MemoryArena& arena, float* presence) const {
    std::fill(presence, presence + count, 1.0f);
    MemoryArena::Mark outer = arena.mark();
    Groups const groups = group(hits, count, arena);
    for (size_t m = 0; m < m_materials.size(); ++m) {
        int begin = groups.starts[m], n = groups.starts[m + 1] - groups.starts[m];
        BxdfInstance const& material = *m_materials[m];
        if (n == 0 || !(material.hints() & RixBxdfFactory::k_ComputesPresence)) continue;
        MemoryArena::Mark groupStart = arena.mark();
        auto* groupHits = arena.allocArray<HitRecord>(static_cast<size_t>(n));
        for (int j = 0; j < n; ++j) groupHits[j] = hits[groups.order[begin + j]];
        ShadingContextImpl ctx(m_scene, material, groupHits, n, m_pixelSpread, arena, &material.plugin().messages(),
                               m_counters.builtins, m_textures);
        ctx.setId(static_cast<int>(m));
        float* values = arena.allocArray<float>(static_cast<size_t>(n));
        std::fill(values, values + n, 1.0f);
        bool partly = false;
        naming(material, [&] {
            RixOpacity* opacity = material.plugin().factory()->BeginOpacity(&ctx, k_RixSCPresenceQuery, nullptr,
                                                                            material.instanceData());
            if (!opacity) return;  // fully present
            partly = opacity->GetPresence(values);
            opacity->Release();
        });
        // Out of range is clamped; a value that is not a number leaves the point present.
        if (partly)
            for (int j = 0; j < n; ++j)
                presence[groups.order[begin + j]] = std::isnan(values[j]) ? 1.0f : std::clamp(values[j], 0.0f, 1.0f);
        arena.release(groupStart);
        m_counters.presencePoints.fetch_add(static_cast<uint64_t>(n), std::memory_order_relaxed);
    }
    arena.release(outer);
}

}  // namespace bxdflab
