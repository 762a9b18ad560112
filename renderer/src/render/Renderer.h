// Drives a render: loads the scene's plugins, builds the acceleration
// structure, works out which effects the scene calls for, then renders tiles
// in parallel. Within a tile, camera hits are grouped by Bxdf instance and
// each group is shaded as one batch (one RixShadingContext, numPts > 1).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accel/RayTracer.h"
#include "core/Diagnostics.h"
#include "integrate/IntegratorServices.h"
#include "render/Film.h"
#include "scene/Scene.h"
#include "shade/PluginLoader.h"

namespace bxdflab {

struct RenderSettings {
    int spp = 0;        ///< 0: the scene's PixelSamples / Hider maxsamples
    float pixelVariance = -1.0f;  ///< below 0: the scene's PixelVariance (0: no adaptive sampling)
    int threads = 0;    ///< 0: all cores
    uint32_t seed = 0;  ///< sample-sequence seed
    bool progress = false;
    std::string pluginPath;  ///< --plugin-path
    int tileSize = 16;
    WholeSpheres wholeSpheres = WholeSpheres::Exact;  ///< see RayTracer
};

struct RenderStats {
    double setupSeconds = 0, renderSeconds = 0;
    int threads = 0, spp = 0, width = 0, height = 0;
    float pixelVariance = 0;  ///< above 0: a pixel stops sampling once its relative variance is at most this
    struct SamplesTaken {
        int least = 0, most = 0;
        double mean = 0;
    } samplesTaken;  ///< camera samples per pixel (all spp without adaptive sampling)
    uint64_t cameraRays = 0, shadowRays = 0, indirectRays = 0;
    uint64_t shadePoints = 0, batches = 0;
    uint64_t presencePoints = 0;  ///< hits a Bxdf was asked how present they are (cut-outs)
    uint64_t surfacePoints = 0, parameterPoints = 0, tangentPoints = 0;  ///< points each builtin group was computed for
    uint64_t patternEvaluations = 0, patternPoints = 0, textureLookups = 0;  ///< shading networks' work
    uint64_t nonFiniteSamples = 0;
    uint64_t invalidPdfSamples = 0;  ///< pdfs a Bxdf must not return (see RixIntegratorContext::CountInvalidPdf)
    double peakMemoryMB = 0;         ///< the process's peak resident memory so far (MiB)
    /// The finished image at a glance (an empty or black image says something went wrong).
    struct ImageSummary {
        float meanRgb[3] = {0, 0, 0}, maxRgb[3] = {0, 0, 0};
        double litFraction = 0;  ///< pixels whose luminance exceeds 1e-3
    } image;
    EffectReport effects;
    std::vector<std::string> plugins;
    std::string integrator;
    nlohmann::json toJson(Diagnostics const& diagnostics) const;
};

class Renderer {
public:
    /// Loads plugins and builds everything needed to render; throws
    /// RenderError / RibError on bad input (missing plugin, bad parameters).
    Renderer(Scene& scene, RenderSettings settings, Diagnostics& diagnostics);
    ~Renderer();

    /// Renders the whole image; can be called more than once.
    Film render();
    RenderStats const& stats() const { return m_stats; }
    /// The ray tracer (tools may observe the rays it traces).
    RayTracer& tracer();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    RenderStats m_stats;
};

}  // namespace bxdflab
