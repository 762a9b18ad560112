// PxrPathTracer: unidirectional path tracing. At every surface a path
// reaches it (1) adds the surface's emission, (2) samples the lights
// directly (next-event estimation), and (3) samples the Bxdf: a sampled
// direction that reaches a light adds that light (weighted against the
// light samples by MIS), and otherwise the path continues to the surface
// it hits. Continuing paths are traced and shaded batch by batch, grouped
// by Bxdf like camera hits.
//
// As in RenderMan, every surface also bounds the bounces a path takes on from
// it, by kind (RIB: Attribute "trace" "int maxdiffusedepth" [1]
// "int maxspeculardepth" [2], the defaults): a path keeps a diffuse and a
// specular limit, each min(the limit so far, its bounces of that kind so far +
// the surface's value). A Bxdf sample of a specular lobe continues the path
// only while its specular bounces are below the specular limit; a sample of
// any other lobe, while its diffuse bounces are below the diffuse limit. A
// sample that may not continue still looks for the light it reaches.
//
// Parameters
//   int maxPathLength    [10]  surfaces a path may visit (1 = direct lighting only)
//   int maxIndirectBounces     RenderMan 23's name for the same limit, counted in
//                              bounces: N bounces is maxPathLength N + 1 (0 = direct only)
//   int numLightSamples  [1]   light samples per light at every vertex
//   int numBxdfSamples   [1]   Bxdf samples at every vertex (the first continues the path)
//   int numIndirectSamples [1] paths each camera hit continues (each also a Bxdf sample there)
//   int allowCaustics    [0]   0: once a path has bounced off a diffuse lobe, a specular
//                              bounce does not continue it (caustics are noisy for a path tracer)
//   int useTraceDepth    [1]   PxrUnified's switch, read so that this integrator can stand in
//                              for it: 0 ignores the trace depths (PxrUnified's default)
//   int rouletteDepth    [4]   the path length (vertices) from which Russian roulette may end a path
//   float rouletteThreshold    unwritten: roulette weighs every path, which survives with
//                              probability min(0.95, its largest throughput channel); written: only
//                              paths whose largest channel is below it, surviving with that channel
//                              over the threshold (RenderMan's exporters write 0.2; 0 turns it off)
//   float clampLuminance       unwritten: no clamping; written (RenderMan's exporters write 10):
//   int clampDepth       [2]   what each ray from the clampDepth-th on brings back to the pixel is
//                              scaled down to at most this luminance (fewer fireflies, less light)
// Roulette compensates the survivors, so it adds noise and no bias; clamping adds bias.
// RenderMan's other parameters are read where this integrator already does what they
// ask (sampleMode "bxdf", whose numDiffuseSamples and the like RenderMan ignores too)
// and warned about where it does not.
#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "RixBxdfScratch.h"
#include "common/DirectLighting.h"
#include "common/Params.h"

using namespace bxdflab;

namespace {

/// Where a path stands as it reaches a surface.
struct PathState {
    RtColorRGB throughput = RtColorRGB(1.0f);  ///< the path's weight so far
    bool diffusePath = false;                  ///< it has bounced off a diffuse lobe
    int diffuseBounces = 0, specularBounces = 0;
    int diffuseLimit = INT_MAX, specularLimit = INT_MAX;  ///< the trace-depth limits so far
};

/// A trace-depth limit at a surface: the limit so far, or fewer when the surface asks for fewer.
int limitHere(int limitSoFar, int bouncesSoFar, int surfaceLimit) {
    return static_cast<int>(
        std::min<long long>(limitSoFar, static_cast<long long>(bouncesSoFar) + surfaceLimit));
}

/// How paths end early and how bright a bounce may be (see the parameters above).
struct PathLimits {
    int rouletteDepth = 4;
    float rouletteThreshold = -1.0f;  ///< below 0: every path meets the roulette
    int clampDepth = 2;
    float clampLuminance = -1.0f;     ///< at or below 0: no clamping
};

/// `radiance` scaled down, if need be, to a luminance of at most `limit`.
RtColorRGB clampedTo(RtColorRGB const& radiance, float limit) {
    float const luminance = radiance.Luminance();
    return luminance > limit ? radiance * (limit / luminance) : radiance;
}

class PathTracer : public RixIntegrator {
public:
    PathTracer(int maxPathLength, int numLightSamples, int numBxdfSamples, int numIndirectSamples,
               bool allowCaustics, bool useTraceDepth, PathLimits limits)
        : m_maxPathLength(maxPathLength),
          m_numLightSamples(numLightSamples),
          m_numBxdfSamples(numBxdfSamples),
          m_numIndirectSamples(numIndirectSamples),
          m_allowCaustics(allowCaustics),
          m_useTraceDepth(useTraceDepth),
          m_limits(limits) {}

    void DescribeEffects(int numLights, RixEffects& effects) const override {
        effects.Simulate("camera rays");
        effects.Simulate("emission (EmitLocal) at every path vertex");
        if (numLights == 0) {
            effects.Skip("light sampling and shadow rays", "the scene has no lights");
        } else if (m_numLightSamples > 0) {
            effects.Simulate(("light sampling (" + std::to_string(m_numLightSamples) + " per light per vertex)").c_str());
            effects.Simulate("shadow rays");
        } else {
            effects.Skip("light sampling", "numLightSamples is 0");
        }
        effects.Simulate(("bxdf sampling (" + std::to_string(m_numBxdfSamples) + " per vertex, MIS)").c_str());
        if (m_maxPathLength > 1) {
            effects.Simulate(("indirect rays (" + std::to_string(m_numIndirectSamples) +
                              " per camera hit; paths of up to " + std::to_string(m_maxPathLength) + " vertices" +
                              (m_useTraceDepth ? ", within each surface's trace depths)" : ")"))
                                 .c_str());
            std::string roulette = "Russian roulette from vertex " + std::to_string(m_limits.rouletteDepth);
            if (m_limits.rouletteThreshold == 0.0f)
                effects.Skip("Russian roulette", "rouletteThreshold is 0");
            else
                effects.Simulate((m_limits.rouletteThreshold > 0.0f
                                      ? roulette + ", for paths below " + std::to_string(m_limits.rouletteThreshold)
                                      : roulette)
                                     .c_str());
            if (m_limits.clampLuminance > 0.0f)
                effects.Simulate(("clamping what each ray from depth " + std::to_string(m_limits.clampDepth) +
                                  " brings back to luminance " + std::to_string(m_limits.clampLuminance))
                                     .c_str());
        } else {
            effects.Skip("indirect rays", "maxPathLength is 1");
        }
        if (m_allowCaustics)
            effects.Simulate("caustics");
        else
            effects.Skip("caustics", "allowCaustics is 0");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        PathState* paths = pool.AllocFor<PathState>(n);
        for (int i = 0; i < n; ++i) paths[i] = PathState();
        vertex(ctx, bxdf, rng, ictx, paths, radiance, 1);
        if (clamps(1))
            for (int i = 0; i < n; ++i) radiance[i] = clampedTo(radiance[i], m_limits.clampLuminance);
    }

private:
    /// Shades one batch of path vertices; paths[i] is where path i stands on arriving.
    void vertex(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                PathState const* paths, RtColorRGB* radiance, int depth) {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        RtColorRGB* throughput = pool.AllocFor<RtColorRGB>(n);
        for (int i = 0; i < n; ++i) throughput[i] = paths[i].throughput;

        // 1. Emission. Emissive surfaces are not sampled as lights, so a path
        //    that reaches one simply adds what it emits.
        if (!addEmission(ctx, bxdf, ictx, throughput, radiance)) return;

        // Camera hits continue numIndirectSamples paths each, deeper vertices one. Each
        // continuing ray is also one of the vertex's Bxdf samples of the light it reaches.
        int const continuations = depth == 1 ? m_numIndirectSamples : 1;
        int const bxdfSamples = std::max(m_numBxdfSamples, continuations);

        // 2. Next-event estimation.
        addLightSamples(ctx, bxdf, rng, ictx, m_numLightSamples, bxdfSamples, throughput, radiance);

        // 3. Bxdf samples: light they reach directly, and where the path goes next.
        int const lightSamples = ictx.GetNumLights() == 0 ? 0 : m_numLightSamples;
        float const nL = static_cast<float>(lightSamples);
        float const nB = static_cast<float>(bxdfSamples);
        bool const continues = depth < m_maxPathLength;
        // This surface's trace depths, folded into each path's limits.
        int* diffuseLimit = pool.AllocFor<int>(n);
        int* specularLimit = pool.AllocFor<int>(n);
        for (int i = 0; continues && i < n; ++i) {
            RixTraceDepth const here = m_useTraceDepth ? ictx.TraceDepth(ctx, i) : RixTraceDepth{INT_MAX, INT_MAX};
            diffuseLimit[i] = limitHere(paths[i].diffuseLimit, paths[i].diffuseBounces, here.maxDiffuse);
            specularLimit[i] = limitHere(paths[i].specularLimit, paths[i].specularBounces, here.maxSpecular);
        }
        RixBxdfScratch q(ctx);
        // The continuation rays (the first `continuations` Bxdf samples of each point).
        int const most = n * continuations;
        int* index = pool.AllocFor<int>(most);
        RtVector3* dir = pool.AllocFor<RtVector3>(most);
        bool* shade = pool.AllocFor<bool>(most);
        RixRNG::SampleCtx* samples = pool.AllocFor<RixRNG::SampleCtx>(most);
        LobeWeight* weight = pool.AllocFor<LobeWeight>(most);      // f / FPdf
        PathState* next = pool.AllocFor<PathState>(most);          // the path after the bounce
        float* misWeightPdf = pool.AllocFor<float>(most);          // FPdf, for the MIS weight of a light hit
        bool* discrete = pool.AllocFor<bool>(most);
        int rays = 0;
        // The other Bxdf samples only look for light: one shadow ray each, a round's traced together.
        ShadowRays look(pool, n);
        RixLightHit* lookHits = pool.AllocFor<RixLightHit>(n);

        for (int s = 0; s < bxdfSamples; ++s) {
            q.generate(bxdf, rng, ictx);
            look.count = 0;
            for (int i = 0; i < n; ++i) {
                if (!q.lobeSampled[i].GetValid() || !(q.FPdf[i] > 0.0f)) continue;
                RtVector3 L = q.Ln[i];
                if (!std::isfinite(L.x) || !std::isfinite(L.y) || !std::isfinite(L.z) || L.IsZero()) {
                    ictx.CountNonFinite();
                    continue;
                }
                L.Normalize();
                LobeWeight const lobes = LobeWeight::at(q.W, i);
                RtColorRGB const& f = lobes.all;
                if (f.IsBlack()) continue;
                bool const specular = q.lobeSampled[i].GetSpecular();
                if (!m_allowCaustics && paths[i].diffusePath && specular) continue;  // a caustic
                bool const withinDepth = continues && (specular ? paths[i].specularBounces < specularLimit[i]
                                                                : paths[i].diffuseBounces < diffuseLimit[i]);
                if (s >= continuations || !withinDepth) {
                    look.add(i, L, 0.0f, lobes * throughput[i]);  // the light is found along the ray
                    continue;
                }
                RtColorRGB carried = throughput[i] * f / (q.FPdf[i] * static_cast<float>(continuations));
                bool survives = true;
                if (float p = survivalProbability(carried, depth + 1); p < 1.0f) {
                    // Russian roulette: end weak paths early, boost the survivors.
                    survives = rng.DrawSample1D(i) < p;
                    if (survives) carried /= p;
                }
                index[rays] = i;
                dir[rays] = L;
                shade[rays] = survives && std::isfinite(carried.r) && std::isfinite(carried.g) && std::isfinite(carried.b);
                // Each further path from a point draws numbers of its own.
                samples[rays] =
                    s == 0 ? rng.sampleCtxArray[i] : rng.sampleCtxArray[i].NewDomain(static_cast<uint32_t>(s));
                weight[rays] = lobes / q.FPdf[i];
                next[rays].throughput = carried;
                next[rays].diffusePath = paths[i].diffusePath || q.lobeSampled[i].GetDiffuse();
                next[rays].diffuseBounces = paths[i].diffuseBounces + (specular ? 0 : 1);
                next[rays].specularBounces = paths[i].specularBounces + (specular ? 1 : 0);
                next[rays].diffuseLimit = diffuseLimit[i];
                next[rays].specularLimit = specularLimit[i];
                misWeightPdf[rays] = q.FPdf[i];
                discrete[rays] = q.lobeSampled[i].GetDiscrete();
                ++rays;
            }
            addLightsFound(ctx, ictx, q, look, lookHits, lightSamples, bxdfSamples, radiance);
        }
        if (rays == 0) return;

        // 4. Trace the continuations: those reaching a light add it (MIS-weighted);
        //    those reaching a surface are shaded there, batch by batch.
        RixLightHit* lightHits = pool.AllocFor<RixLightHit>(rays);
        ictx.TraceIndirect(ctx, rays, index, dir, shade, samples, lightHits, [&](RixShadeBatch& batch) {
            int m = batch.ctx.numPts;
            RixShadingContext::Allocator childPool(&batch.ctx);
            PathState* childPaths = childPool.AllocFor<PathState>(m);
            RtColorRGB* childRadiance = childPool.AllocFor<RtColorRGB>(m);
            for (int j = 0; j < m; ++j) {
                childPaths[j] = next[batch.source[j]];
                childRadiance[j] = RtColorRGB(0.0f);
            }
            vertex(batch.ctx, batch.bxdf, batch.rng, ictx, childPaths, childRadiance, depth + 1);
            bool const clamp = clamps(depth + 1);
            for (int j = 0; j < m; ++j)
                radiance[index[batch.source[j]]] +=
                    clamp ? clampedTo(childRadiance[j], m_limits.clampLuminance) : childRadiance[j];
        });
        for (int k = 0; k < rays; ++k) {
            if (!lightHits[k].hit) continue;
            float w = discrete[k] ? 1.0f : RixPowerHeuristic(nB, misWeightPdf[k], nL, lightHits[k].pdf);
            RtColorRGB const lit = weight[k].litBy(lightHits[k].diffuse, lightHits[k].specular);
            accumulate(ictx, radiance[index[k]], throughput[index[k]] * lit * lightHits[k].radiance * (w / nB));
        }
    }

    /// The chance that a path carrying `throughput` goes on to a path of `length` vertices (1: roulette
    /// does not take part).
    float survivalProbability(RtColorRGB const& throughput, int length) const {
        if (length < m_limits.rouletteDepth || m_limits.rouletteThreshold == 0.0f) return 1.0f;
        float const strongest = throughput.ChannelMax();
        if (m_limits.rouletteThreshold < 0.0f) return RixMin(0.95f, strongest);
        return strongest < m_limits.rouletteThreshold ? strongest / m_limits.rouletteThreshold : 1.0f;
    }

    /// Whether what a ray of this depth (the camera ray's is 1) brings back is clamped.
    bool clamps(int rayDepth) const { return m_limits.clampLuminance > 0.0f && rayDepth >= m_limits.clampDepth; }

    int m_maxPathLength;
    int m_numLightSamples;
    int m_numBxdfSamples;
    int m_numIndirectSamples;
    bool m_allowCaustics;
    bool m_useTraceDepth;
    PathLimits m_limits;
};

/// Reads RenderMan's parameters that ask for what this integrator does anyway (so that an
/// exporter's full parameter list renders without a warning for each), and warns where one
/// asks for something else.
void readRenderManDefaults(RixParameterList const* params, RixMessages* messages) {
    std::string const sampleMode = ReadString(params, "sampleMode", "bxdf");
    if (sampleMode != "bxdf")
        messages->Warning("sampleMode \"%s\" is read as \"bxdf\": each camera hit continues numIndirectSamples "
                          "paths, whichever lobes its Bxdf samples (numDiffuseSamples and the like are not used)",
                          sampleMode.c_str());
    // In "bxdf" mode RenderMan ignores the per-lobe counts as well.
    for (char const* perLobe :
         {"numDiffuseSamples", "numSpecularSamples", "numSubsurfaceSamples", "numRefractionSamples"})
        HasParam(params, perLobe);
    // Volumes' continuation rays and opacity events: this renderer's paths have neither.
    for (char const* unneeded : {"maxContinuationLength", "maxNonStochasticOpacityEvents", "accumOpacity",
                                 "imagePlaneSubset"})
        HasParam(params, unneeded);
}

}  // namespace

RIX_INTEGRATORCREATE {
    int maxPathLength, lightSamples, bxdfSamples, caustics, useTraceDepth;
    if (!ReadInt(params, messages, "maxPathLength", 10, 1, 1000, maxPathLength) ||
        !ReadInt(params, messages, "numLightSamples", 1, 0, 4096, lightSamples) ||
        !ReadInt(params, messages, "numBxdfSamples", 1, 1, 4096, bxdfSamples) ||
        !ReadInt(params, messages, "allowCaustics", 0, 0, 1, caustics) ||
        !ReadInt(params, messages, "useTraceDepth", 1, 0, 1, useTraceDepth))
        return nullptr;
    if (HasParam(params, "maxIndirectBounces")) {
        int bounces;
        if (!ReadInt(params, messages, "maxIndirectBounces", 9, 0, 999, bounces)) return nullptr;
        maxPathLength = bounces + 1;
    }
    PathLimits limits;
    // Scenes turn roulette off with a depth no path reaches (a public one writes 10000000).
    if (!ReadInt(params, messages, "rouletteDepth", 4, 0, INT_MAX, limits.rouletteDepth) ||
        !ReadInt(params, messages, "clampDepth", 2, 0, INT_MAX, limits.clampDepth))
        return nullptr;
    if (HasParam(params, "rouletteThreshold"))
        limits.rouletteThreshold = std::max(0.0f, ReadFloat(params, "rouletteThreshold", 0.2f));
    if (HasParam(params, "clampLuminance")) limits.clampLuminance = ReadFloat(params, "clampLuminance", 10.0f);
    int indirectSamples;
    if (!ReadInt(params, messages, "numIndirectSamples", 1, 1, INT_MAX, indirectSamples)) return nullptr;
    int const mostIndirectSamples = 256;  // each is a ray per camera hit: more would only exhaust memory
    if (indirectSamples > mostIndirectSamples) {
        messages->Warning("numIndirectSamples %d is more than %d paths per camera hit; %d are traced",
                          indirectSamples, mostIndirectSamples, mostIndirectSamples);
        indirectSamples = mostIndirectSamples;
    }
    readRenderManDefaults(params, messages);
    return new PathTracer(maxPathLength, lightSamples, bxdfSamples, indirectSamples, caustics != 0, useTraceDepth != 0,
                          limits);
}

RIX_INTEGRATORDESTROY { delete integrator; }
