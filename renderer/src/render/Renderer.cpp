#include "render/Renderer.h"

#include <sys/resource.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <iomanip>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "accel/RayTracer.h"
#include "integrate/ShutterTime.h"
#include "core/CrashReport.h"
#include "core/ImageFiles.h"
#include "core/PixelFilter.h"
#include "core/RenderManNames.h"
#include "render/SampleSchedule.h"
#include "scene/Camera.h"
#include "scene/PatternReach.h"
#include "scene/lights/HeadLight.h"
#include "shade/BatchShader.h"
#include "shade/BxdfInstance.h"
#include "shade/MemoryArena.h"
#include "shade/PatternInstance.h"
#include "shade/PluginSearchPath.h"
#include "shade/PresenceTracer.h"
#include "shade/ShadingContextImpl.h"
#include "shade/StandInMaterials.h"

namespace bxdflab {
namespace {

using Clock = std::chrono::steady_clock;
constexpr uint32_t kLensDomain = 0x6c656e73u;  ///< the lens's numbers: "lens"
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// Peak resident memory of this process so far, in MiB (Linux reports KiB).
double peakResidentMB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// At most this many shade points are in flight per tile (bounds memory at any spp).
constexpr int kMaxPointsPerChunk = 4096;

/// Tiles grow (up to 4x) at low spp so a chunk still holds about
/// kMaxPointsPerChunk samples: the same batch sizes, and the same memory, at any spp.
int tileSizeFor(int baseSize, int spp) {
    int size = baseSize;
    while (size < 4 * baseSize && size * size * spp < kMaxPointsPerChunk) size *= 2;
    return size;
}

struct PixelXY {
    int x, y;
};

/// Per-worker state: memory, ray counts, shading-time counters.
struct Worker {
    Worker() { crashreport::prepareThread(); }  // made on the thread that uses it, which runs plugin code
    MemoryArena arena;
    std::vector<PixelXY> pixels;  ///< the tile's pixels that take the next samples
    std::vector<HitRecord> hits;
    std::vector<Vec3> rayOrigins, rayDirections;
    std::vector<float> rayNear, rayFar;  ///< where Clipping's planes cut the camera rays (when they do)
    std::vector<float> rayTimes;         ///< when in the shutter each camera ray is traced (when it stays open)
    std::vector<RixRNG::SampleCtx> samples;
    std::vector<RtColorRGB> radiance, groupRadiance;
    std::vector<float> alpha;
    std::vector<float> filterWeight;  ///< each camera sample's weight under the pixel filter
    std::vector<float> depth, surface;  ///< what displays of the surface (z, P, N, ...) record, per sample
};

class ProgressBar {
public:
    ProgressBar(bool enabled, int total) : m_enabled(enabled), m_total(total) {}
    void tick() {
        int done = ++m_done;
        if (!m_enabled) return;
        int percent = 100 * done / m_total;
        std::lock_guard<std::mutex> guard(m_lock);
        if (percent == m_shown) return;
        m_shown = percent;
        int bar = percent / 4;
        std::fprintf(stderr, "\rrendering [%s%s] %3d%%", std::string(static_cast<size_t>(bar), '#').c_str(),
                     std::string(static_cast<size_t>(25 - bar), ' ').c_str(), percent);
        if (done == m_total) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    bool m_enabled;
    int m_total;
    std::atomic<int> m_done{0};
    std::mutex m_lock;
    int m_shown = -1;
};

}  // namespace

namespace {

void summarise(Film const& film, RenderStats::ImageSummary& out) {
    std::vector<float> const rgba = film.rgba();
    size_t const pixels = rgba.size() / 4;
    double sum[3] = {0, 0, 0};
    size_t lit = 0;
    for (size_t p = 0; p < pixels; ++p) {
        float const* c = &rgba[4 * p];
        for (int k = 0; k < 3; ++k) {
            sum[k] += c[k];
            out.maxRgb[k] = std::max(out.maxRgb[k], c[k]);
        }
        lit += 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2] > 1e-3f;
    }
    for (int k = 0; k < 3; ++k) out.meanRgb[k] = pixels ? static_cast<float>(sum[k] / static_cast<double>(pixels)) : 0.0f;
    out.litFraction = pixels ? static_cast<double>(lit) / static_cast<double>(pixels) : 0.0;
}

/// The fewest, the most and the mean number of samples the film's pixels took.
void countSamplesTaken(Film const& film, RenderStats::SamplesTaken& out) {
    out = {};
    long long total = 0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            int const n = film.samplesTaken(x, y);
            out.least = x == 0 && y == 0 ? n : std::min(out.least, n);
            out.most = std::max(out.most, n);
            total += n;
        }
    long long const pixels = static_cast<long long>(film.width()) * film.height();
    out.mean = pixels > 0 ? static_cast<double>(total) / static_cast<double>(pixels) : 0.0;
}

/// A camera transform that puts every shape behind the camera is a common
/// mistake (and the sign of a right-handed export): say so, rather than
/// leaving an empty image to explain itself.
void warnIfNothingInFront(RayTracer const& tracer, Scene const& scene, Diagnostics& diagnostics) {
    Vec3 lower, upper;
    tracer.cameraBounds(lower, upper);
    if (!(lower.x <= upper.x)) return;  // nothing the camera can see at all
    float nearest = -kInfinity;
    for (int corner = 0; corner < 8; ++corner) {
        Vec3 p(corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z);
        nearest = std::max(nearest, transformPoint(scene.camera.worldToCamera, p).z);
    }
    if (nearest <= 0.0f)
        diagnostics.warn("every shape is behind the camera (at negative camera z): the image will be empty. RenderMan's "
                         "camera looks down +z; a camera transform from a right-handed program may need Scale 1 1 -1");
}

}  // namespace

struct Renderer::Impl {
    Scene& scene;
    RenderSettings settings;
    Diagnostics& diagnostics;
    PluginLoader loader;
    std::unique_ptr<TextureService> textures;             // only when a pattern is used
    PatternCounters patternCounters;
    std::vector<std::unique_ptr<PatternInstance>> patterns;  // by Scene::patterns index; null: not used
    std::vector<std::unique_ptr<BxdfInstance>> materials;
    std::unique_ptr<RayTracer> tracer;
    std::unique_ptr<Camera> camera;
    PixelFilter pixelFilter;
    std::unique_ptr<IntegratorPlugin> integratorPlugin;
    RixIntegrator* integrator = nullptr;
    std::unique_ptr<Light> headlight;
    std::vector<Light const*> shadingLights;  // what next-event estimation samples
    std::vector<Light const*> cameraLights;   // lights the camera sees directly
    ShadingCounters counters;
    std::unique_ptr<BatchShader> shader;
    std::unique_ptr<PresenceTracer> rays;  // the tracer, seeing through cut-outs
    SurfaceRecord surfaceRecord;           // what displays of the surface need from each camera hit
    bool shutterOpens = false;             // the shutter stays open a while: camera rays get times
    SampleSchedule schedule;               // how many samples each pixel takes (adaptive under PixelVariance)
    std::atomic<uint64_t> nonFinite{0};
    std::atomic<uint64_t> invalidPdf{0};

    Impl(Scene& s, RenderSettings const& rs, Diagnostics& d)
        : scene(s),
          settings(rs),
          diagnostics(d),
          loader(pluginSearchPath({rs.pluginPath, s.pluginSearchPath, s.file}), d) {}

    /// Loads the patterns the materials' connections reach (and only those),
    /// and the texture service if any is used.
    void loadPatterns(std::vector<MaterialDesc> const& usedMaterials);
    /// Every loaded Bxdf and pattern plugin, each once, in order of first use.
    std::vector<ShadingPlugin*> usedPlugins() const;
    void renderTile(int tileX, int tileY, Film& film, Worker& worker);
    /// Samples first..end-1 of each pixel in worker.pixels, into the film.
    void renderSamples(int first, int end, Film& film, Worker& worker, RayCounts& counts);
    void shadeChunk(Worker& worker, int count, Film& film);
    /// What displays of the surface need from each camera sample's hit (before shading).
    void recordSurfaces(Worker& worker, int count, SurfaceRecord const& record) const;
};

void Renderer::Impl::loadPatterns(std::vector<MaterialDesc> const& usedMaterials) {
    std::vector<char> const reached = patternsReached(usedMaterials, scene.patterns);
    std::vector<std::set<std::string>> const read = outputsRead(usedMaterials, scene.patterns);

    patterns.resize(scene.patterns.size());
    auto patternOf = [this](int index) -> PatternInstance const* { return patterns[static_cast<size_t>(index)].get(); };
    // A missing plugin is said once, in full, at its first Pattern; exporters write
    // one Pattern per object, and the same five-line message per object is noise.
    struct Missing {
        PatternDesc const* first;
        int more;
    };
    std::map<std::string, Missing> missing;
    for (size_t i = 0; i < reached.size(); ++i) {
        if (!reached[i]) continue;
        PatternDesc const& desc = scene.patterns[i];
        ShadingPlugin* plugin = nullptr;
        if (auto known = missing.find(desc.plugin); known != missing.end()) {
            ++known->second.more;
            continue;
        }
        try {
            plugin = &loader.pattern(desc.plugin, desc.where);
        } catch (RenderError const& e) {
            // Like a missing texture: the render goes on, and says what it lacks. RenderMan runs
            // a pattern of an OSL shader's name as OSL, which has no C++ plugin to find here.
            std::string why = e.message();  // its place is desc.where, said once at the start of the warning
            if (!desc.oslShader.empty())
                why = "\"" + desc.plugin + "\" is the OSL shader " + desc.oslShader +
                      ", and this renderer runs only patterns written in C++ with the Rix API (a " + desc.plugin +
                      ".so on the plugin search path)";
            else if (isRenderMansOwnName(desc.plugin))
                why = "\"" + desc.plugin + "\" is one of RenderMan's patterns, which this renderer does not have: " + why;
            diagnostics.warn(desc.where, "Pattern \"" + desc.handle + "\" cannot be used (" + why +
                                             "); the parameters connected to it keep their own values");
            missing.emplace(desc.plugin, Missing{&desc, 0});
            continue;
        }
        patterns[i] = std::make_unique<PatternInstance>(desc, read[i], *plugin, patternOf, patternCounters, diagnostics);
        if (!textures) {
            textures = openTextures(diagnostics);
            if (textures) textures->setLocator(scene.textureLocator());
        }
    }
    for (auto const& [name, absent] : missing)
        if (absent.more > 0)
            diagnostics.warn(absent.first->where, std::to_string(absent.more) + " more Pattern" + (absent.more > 1 ? "s" : "") +
                                                      " of the missing plugin \"" + name +
                                                      "\" cannot be used either; the parameters connected to them keep "
                                                      "their own values");
}

std::vector<ShadingPlugin*> Renderer::Impl::usedPlugins() const {
    std::vector<ShadingPlugin*> plugins;
    auto add = [&plugins](ShadingPlugin& plugin) {
        if (std::find(plugins.begin(), plugins.end(), &plugin) == plugins.end()) plugins.push_back(&plugin);
    };
    for (auto const& pattern : patterns)
        if (pattern) add(pattern->plugin());
    for (auto const& material : materials) add(material->plugin());
    return plugins;
}

Renderer::Renderer(Scene& scene, RenderSettings settings, Diagnostics& diagnostics)
    : m_impl(std::make_unique<Impl>(scene, settings, diagnostics)) {
    auto start = Clock::now();
    Impl& r = *m_impl;

    // Plugins: one instance per Bxdf statement; each plugin hears RenderBegin once.
    // RenderMan's own materials that are not on the search path get a stock stand-in.
    std::set<std::string> standInsWarned, cutOutsWarned;
    std::vector<MaterialDesc> used;
    for (MaterialDesc const& material : scene.materials) {
        std::optional<StandIn> standIn;
        if (!r.loader.has(material.plugin)) standIn = standInFor(material, scene.patterns);
        if (standIn && standInsWarned.insert(material.plugin).second) {
            diagnostics.warn(material.where, "Bxdf \"" + material.plugin + "\" is one of RenderMan's materials and no " +
                                                 material.plugin + ".so is on the plugin search path: rendered as " +
                                                 standIn->note);
            m_stats.effects.skip("material " + material.plugin, "rendered as " + standIn->note);
        }
        if (standIn && standIn->cutOut && cutOutsWarned.insert(material.plugin).second)
            diagnostics.warn(material.where, "Bxdf \"" + material.plugin + "\" \"" + material.handle +
                                                 "\": its presence (a cut-out) is not rendered by the stand-in; the "
                                                 "surface is opaque");
        used.push_back(standIn ? standIn->material : material);
    }
    r.loadPatterns(used);
    auto patternOf = [&r](int index) -> PatternInstance const* { return r.patterns[static_cast<size_t>(index)].get(); };
    for (MaterialDesc const& material : used) {
        ShadingPlugin& plugin = r.loader.bxdf(material.plugin, material.where);
        r.materials.push_back(std::make_unique<BxdfInstance>(material, plugin, diagnostics, patternOf));
    }
    for (ShadingPlugin* plugin : r.usedPlugins()) {
        plugin->plugin()->Synchronize(plugin->context(), k_RixSCRenderBegin, nullptr);
        m_stats.plugins.push_back(plugin->name() + " (" + plugin->path() + ")");
    }

    r.camera = std::make_unique<Camera>(scene.camera, scene.xres, scene.yres, scene.pixelAspect,
                                        scene.shutterOpen, scene.shutterClose);
    IntegratorDesc integrator = scene.integrator;
    bool const renderMansGlobalIllumination =
        integrator.name == "PxrUnified" || integrator.name == "PxrUPBP" || integrator.name == "PxrVPL";
    if (renderMansGlobalIllumination && !r.loader.has(integrator.name)) {
        // RenderMan's other global-illumination integrators (PxrUnified,
        // PxrUPBP, PxrVPL) compute the same image: the path tracer stands in, with
        // the path length the scene asked for. They ignore the objects' trace depths
        // (PxrUnified unless its useTraceDepth is 1).
        IntegratorDesc standIn;
        standIn.name = "PxrPathTracer";
        standIn.handle = integrator.handle;
        standIn.where = integrator.where;
        bool traceDepthGiven = false;
        for (Param const& p : integrator.params.all()) {
            bool const useTraceDepth = integrator.name == "PxrUnified" && p.name() == "useTraceDepth";
            if (p.name() == "maxPathLength" || useTraceDepth) standIn.params.add(p);
            traceDepthGiven = traceDepthGiven || useTraceDepth;
        }
        if (!traceDepthGiven) standIn.params.add(intParam("useTraceDepth", 0));
        diagnostics.warn(integrator.where, "Integrator \"" + integrator.name + "\" is one of RenderMan's and no " +
                                               integrator.name + ".so is on the plugin search path: PxrPathTracer renders "
                                               "the same light transport instead (with its maxPathLength)");
        m_stats.effects.skip("integrator " + integrator.name, "PxrPathTracer stands in");
        integrator = standIn;
    }
    if (integrator.name == "PxrVisualize" && !r.loader.has(integrator.name)) {
        // RenderMan's debugging view is PxrVisualizer; the name without its "r" is a slip worth rendering.
        diagnostics.warn(integrator.where,
                         "Integrator \"PxrVisualize\": RenderMan's integrator is spelled "
                         "\"PxrVisualizer\", which renders instead");
        integrator.name = "PxrVisualizer";
    }
    r.integratorPlugin = r.loader.integrator(integrator.name, integrator.params, integrator.where);
    r.integrator = &r.integratorPlugin->integrator();
    m_stats.plugins.insert(m_stats.plugins.begin(), r.integratorPlugin->name() + " (" + r.integratorPlugin->path() + ")");
    if (r.camera->moves() && r.integrator->WantsLightTracing()) {
        // Light subpaths are joined to the camera where it stands as the shutter opens.
        r.camera->holdStill();
        diagnostics.warn(integrator.where,
                         "Integrator \"" + integrator.name +
                             "\" joins light paths to a camera that holds still: the camera's "
                             "motion is not rendered");
        m_stats.effects.skip("camera motion",
                             integrator.name + " joins light paths to a camera that holds still");
    }
    if (r.camera->hasLens()) {
        if (r.integrator->WantsLightTracing()) {
            // Light subpaths are joined to a pinhole; a lens would need them joined to
            // points on it, with their own weights. Without that, no depth of field.
            r.camera->removeLens();
            diagnostics.warn(integrator.where, "Integrator \"" + integrator.name +
                                                   "\" joins light paths to a pinhole camera: depth of field is not rendered");
            m_stats.effects.skip("depth of field", integrator.name + " joins light paths to a pinhole camera");
        } else {
            m_stats.effects.simulate("depth of field");
        }
    }
    PixelFilterDesc const& filter = scene.pixelFilter;
    if (PixelFilter const applied(filter.name, filter.xwidth, filter.ywidth); !applied.isUnitBox()) {
        std::ostringstream named;
        named << "pixel filter " << filter.name << " " << filter.xwidth << " x " << filter.ywidth;
        if (r.integrator->WantsLightTracing()) {
            // Light subpaths land in one pixel each; filtering them too would spread them over its
            // neighbours.
            diagnostics.warn(integrator.where, "Integrator \"" + integrator.name +
                                                   "\" adds light subpaths to the pixel they land in: the " +
                                                   named.str() + " is not applied (a box one pixel wide is)");
            m_stats.effects.skip(named.str(), integrator.name + " adds light subpaths to one pixel each");
        } else {
            r.pixelFilter = applied;
            m_stats.effects.simulate(named.str());
        }
    }
    if (r.integrator->WantsHeadlight()) {
        r.headlight = std::make_unique<HeadLight>(r.camera->position());
        r.shadingLights.push_back(r.headlight.get());
        // RenderMan does the same, silently; a file written for lights it no longer
        // runs (classic LightSource shaders) would look lit from the camera without a word.
        if (!scene.lights.empty()) {
            std::string const unused = scene.lights.size() == 1 ? "its light is"
                                                                : "its " + std::to_string(scene.lights.size()) + " lights are";
            diagnostics.info((scene.integrator.given ? "Integrator \"" + scene.integrator.name + "\" lights"
                                                     : std::string("the scene names no Integrator, so PxrDefault lights")) +
                             " it from the camera, as in RenderMan, and " + unused +
                             " not used; Integrator \"PxrDirectLighting\" \"d\" (or \"PxrPathTracer\") before WorldBegin "
                             "renders with them");
        } else if (scene.unrenderableLights > 0) {
            // Its lights were warned about one by one; what lights the image instead is said here.
            diagnostics.info(std::string(scene.unrenderableLights == 1 ? "the scene's one light is not"
                                                                       : "none of the scene's lights is") +
                             " one this renderer can render, so it is lit from the camera only (the headlight "
                             "PxrDefault gives every scene); the image shows its shapes, not its lighting");
        }
    } else {
        for (auto const& light : scene.lights) r.shadingLights.push_back(light.get());
    }
    // The lights camera rays must test: those visible to the camera, less
    // those that lie wholly outside its view.
    for (auto const& light : scene.lights) {
        if (!light->visibility.camera) continue;
        Vec3 center;
        float radius;
        // (A lens sees beyond the pinhole's frustum: then every light is tested.)
        if (!r.camera->hasLens() && light->boundingSphere(center, radius) && !r.camera->mightSee(center, radius)) continue;
        r.cameraLights.push_back(light.get());
    }
    r.tracer = std::make_unique<RayTracer>(scene, settings.wholeSpheres);
    warnIfNothingInFront(*r.tracer, scene, diagnostics);
    r.shader = std::make_unique<BatchShader>(scene, r.materials, r.camera->pixelSpread(), r.counters, diagnostics,
                                             r.textures.get());
    r.rays = std::make_unique<PresenceTracer>(*r.tracer, *r.shader);

    // What this render will and will not simulate.
    EffectReport& effects = m_stats.effects;
    r.integrator->DescribeEffects(static_cast<int>(r.shadingLights.size()), effects);
    if (r.rays->active())
        effects.simulate("presence (cut-outs): rays pass the points a Bxdf's RixOpacity says are absent");
    else
        effects.skip("presence", "no Bxdf computes it (k_ComputesPresence)");
    for (auto const& m : r.materials) {
        if (!(m->hints() & ~RixBxdfFactory::k_ComputesPresence)) continue;
        diagnostics.warn("plugin \"" + m->plugin().name() + "\" (Bxdf \"" + m->handle() + "\" at " + m->where().str() +
                         ") asks for coloured opacity or interior computation, which this renderer does not do; "
                         "its shadows are opaque and it has no interior");
    }
    for (std::string const& dropped : scene.dropped) effects.skip("dropped at load", dropped);
    if (r.tracer->passesBackFaces()) effects.simulate("one-sided surfaces (Sides 1): camera rays pass their backs");
    std::vector<DisplayLayout> layouts = {scene.display.layout};
    for (DisplayDesc const& display : scene.moreDisplays) layouts.push_back(display.layout);
    r.surfaceRecord = SurfaceRecord(layouts);
    if (r.surfaceRecord.any())
        effects.simulate("displays of the surface the camera sees (depth, position, normals, parameters)");
    size_t const moving = static_cast<size_t>(
        std::count_if(scene.shapes.begin(), scene.shapes.end(), [](auto const& shape) { return shape->moves(); }));
    r.shutterOpens = scene.shutterClose > scene.shutterOpen;
    if (moving > 0 || r.camera->moves()) {
        std::string const shapes = std::to_string(moving) + (moving == 1 ? " shape moves" : " shapes move");
        effects.simulate("motion blur: " + (r.camera->moves() ? "the camera and " + shapes : shapes) +
                         " while the shutter is open");
    } else {
        effects.skip("motion blur", r.shutterOpens ? "the shutter is open, but nothing in the scene moves"
                                                   : "the shutter does not open (Shutter)");
    }

    m_stats.integrator = r.integratorPlugin->name();
    m_stats.width = scene.xres;
    m_stats.height = scene.yres;
    m_stats.spp = settings.spp > 0 ? settings.spp : scene.spp;
    m_stats.pixelVariance = settings.pixelVariance >= 0.0f ? settings.pixelVariance : scene.pixelVariance;
    r.schedule = sampleSchedule(m_stats.spp, m_stats.pixelVariance, scene.minSamples, scene.minExtraSamples,
                                scene.darkFalloff);
    std::string const everyPixel =
        "every pixel takes " + std::to_string(m_stats.spp) + (m_stats.spp == 1 ? " sample" : " samples");
    if (r.schedule.adaptive() && r.integrator->WantsLightTracing()) {
        // Light subpaths land in whichever pixel they reach, so no pixel's value is its own samples' alone.
        diagnostics.warn(integrator.where, "Integrator \"" + integrator.name +
                                               "\" adds light subpaths to the pixels they land in: PixelVariance is "
                                               "not applied, and " + everyPixel);
        effects.skip("adaptive sampling", integrator.name + " adds light subpaths to the pixels they land in");
        r.schedule = sampleSchedule(m_stats.spp, 0.0f, scene.minSamples, scene.minExtraSamples, scene.darkFalloff);
    } else if (!r.schedule.adaptive()) {
        effects.skip("adaptive sampling", m_stats.pixelVariance > 0.0f
                                              ? "minsamples reaches maxsamples, so " + everyPixel
                                              : "no PixelVariance above 0 is set, so " + everyPixel);
    }
    m_stats.threads = settings.threads > 0 ? settings.threads
                                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    m_stats.setupSeconds = secondsSince(start);
}

Renderer::~Renderer() {
    if (!m_impl) return;
    for (ShadingPlugin* plugin : m_impl->usedPlugins())
        plugin->plugin()->Synchronize(plugin->context(), k_RixSCRenderEnd, nullptr);
    // Instance data is freed before the plugins unload.
    m_impl->materials.clear();
    m_impl->patterns.clear();
}

void Renderer::Impl::renderTile(int tileX, int tileY, Film& film, Worker& w) {
    int const size = tileSizeFor(settings.tileSize, schedule.most);
    int x0 = tileX * size, y0 = tileY * size;
    int x1 = std::min(x0 + size, scene.xres), y1 = std::min(y0 + size, scene.yres);
    w.pixels.clear();
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) w.pixels.push_back({x, y});
    RayCounts counts;
    int taken = schedule.first;
    renderSamples(0, taken, film, w, counts);
    while (taken < schedule.most) {
        // Whether a pixel goes on depends on its own samples alone, and so on no thread count.
        auto settled = [&](PixelXY const& p) {
            return schedule.settled(film.largestVarianceOfMean(p.x, p.y), film.brightness(p.x, p.y));
        };
        w.pixels.erase(std::remove_if(w.pixels.begin(), w.pixels.end(), settled), w.pixels.end());
        if (w.pixels.empty()) break;
        int const next = std::min(schedule.most, taken + schedule.step);
        renderSamples(taken, next, film, w, counts);
        taken = next;
    }
    tracer->counters().add(counts);
}

void Renderer::Impl::renderSamples(int first, int end, Film& film, Worker& w, RayCounts& counts) {
    int const pixels = static_cast<int>(w.pixels.size());
    int const chunk = std::max(1, std::min(end - first, kMaxPointsPerChunk / pixels));
    for (int s0 = first; s0 < end; s0 += chunk) {
        int s1 = std::min(end, s0 + chunk);
        int count = pixels * (s1 - s0);
        w.hits.resize(static_cast<size_t>(count));
        w.rayOrigins.resize(static_cast<size_t>(count));
        w.rayDirections.resize(static_cast<size_t>(count));
        w.samples.resize(static_cast<size_t>(count));
        w.radiance.assign(static_cast<size_t>(count), RtColorRGB(0.0f));
        w.alpha.assign(static_cast<size_t>(count), 0.0f);
        w.filterWeight.resize(static_cast<size_t>(count));

        // Camera rays, pixel by pixel and sample by sample: this order fixes
        // each pixel's sample sequence, whatever the thread count.
        int k = 0;
        uint32_t const seedHash = RixRNG::Hash(settings.seed + 0x5bd1e995u);
        bool const lens = camera->hasLens();
        for (auto const [x, y] : w.pixels) {
            uint32_t patternid = RixRNG::Hash(static_cast<uint32_t>(y * scene.xres + x) ^ seedHash);
            for (int s = s0; s < s1; ++s, ++k) {
                RixRNG::SampleCtx& sample = w.samples[static_cast<size_t>(k)];
                sample = {patternid, static_cast<uint32_t>(s), 0, -1.0f};
                RtFloat2 const jitter = RixRNG::Sample2D(sample);
                Vec2 const offset =
                    pixelFilter.sample(jitter.x, jitter.y, w.filterWeight[static_cast<size_t>(k)]);
                float const rasterX = static_cast<float>(x) + offset.x,
                            rasterY = static_cast<float>(y) + offset.y;
                Vec3& org = w.rayOrigins[static_cast<size_t>(k)];
                Vec3& dir = w.rayDirections[static_cast<size_t>(k)];
                if (lens) {
                    // Numbers of their own, so the integrator's draws are those of a pinhole render.
                    RixRNG::SampleCtx onLens = sample.NewDomain(kLensDomain);
                    camera->generateRay(rasterX, rasterY, RixRNG::Sample2D(onLens), org, dir);
                } else {
                    camera->generateRay(rasterX, rasterY, org, dir);
                }
            }
        }
        // Times come from numbers of their own, so drawing them changes no other number.
        float const* times = nullptr;
        if (shutterOpens) {
            w.rayTimes.resize(static_cast<size_t>(count));
            for (size_t i = 0; i < static_cast<size_t>(count); ++i) w.rayTimes[i] = shutterTime(w.samples[i]);
            times = w.rayTimes.data();
        }
        float const* clipNear = nullptr;
        float const* clipFar = nullptr;
        if (camera->clips()) {
            w.rayNear.resize(static_cast<size_t>(count));
            w.rayFar.resize(static_cast<size_t>(count));
            for (size_t i = 0; i < static_cast<size_t>(count); ++i)
                camera->clipRange(w.rayDirections[i], w.rayNear[i], w.rayFar[i]);
            clipNear = w.rayNear.data();
            clipFar = w.rayFar.data();
        }
        if (camera->moves())  // each ray from where the camera is at its moment
            for (size_t i = 0; i < static_cast<size_t>(count); ++i) {
                float const stretch = camera->moveRay(w.rayTimes[i], w.rayOrigins[i], w.rayDirections[i]);
                if (clipNear) {
                    w.rayNear[i] *= stretch;
                    w.rayFar[i] *= stretch;
                }
            }
        tracer->intersectCoherent(w.rayOrigins.data(), w.rayDirections.data(), count, RayKind::Camera,
                                  w.hits.data(), counts, clipNear, clipFar, times);
        rays->passAbsent(w.hits.data(), count, clipFar, RayKind::Camera, counts, w.arena);
        if (clipFar)  // a one-sided back passed on the way may have let the ray on past the far plane
            for (size_t i = 0; i < static_cast<size_t>(count); ++i)
                if (w.hits[i].hit() && w.hits[i].t > w.rayFar[i]) w.hits[i].forget();

        // Lights the camera sees directly, in front of any geometry.
        for (int i = 0; i < count; ++i) {
            HitRecord& hit = w.hits[static_cast<size_t>(i)];
            LightAlongRay seen =
                nearestLightAlong(cameraLights, hit.org, hit.dir, hit.hit() ? hit.t : kInfinity);
            if (seen.light) {
                w.radiance[static_cast<size_t>(i)] = seen.radiance;
                w.alpha[static_cast<size_t>(i)] = 1.0f;
                hit.forget();  // nothing to shade behind the light
            }
            if (hit.hit()) w.alpha[static_cast<size_t>(i)] = 1.0f;
        }

        if (film.surfaceRecord().any()) recordSurfaces(w, count, film.surfaceRecord());
        shadeChunk(w, count, film);

        // Into the film, in the fixed sample order; non-finite values are counted and dropped.
        k = 0;
        for (auto const [x, y] : w.pixels)
            for (int s = s0; s < s1; ++s, ++k) {
                RtColorRGB value = w.radiance[static_cast<size_t>(k)];
                if (!std::isfinite(value.r) || !std::isfinite(value.g) || !std::isfinite(value.b)) {
                    nonFinite.fetch_add(1, std::memory_order_relaxed);
                    value = RtColorRGB(0.0f);
                }
                film.addSample(x, y, value, w.alpha[static_cast<size_t>(k)],
                               w.filterWeight[static_cast<size_t>(k)]);
                if (film.surfaceRecord().any())
                    film.addSurface(x, y, w.depth[static_cast<size_t>(k)],
                                    w.surface.data() + static_cast<size_t>(k * film.surfaceRecord().width()));
            }
    }
}

void Renderer::Impl::recordSurfaces(Worker& w, int count, SurfaceRecord const& record) const {
    size_t const width = static_cast<size_t>(record.width());
    w.depth.assign(static_cast<size_t>(count), kInfinity);
    w.surface.assign(static_cast<size_t>(count) * width, 0.0f);
    auto put = [&](float* values, Quantity quantity, Vec3 const& value) {
        int const offset = record.offset(quantity);
        if (offset >= 0)
            for (int c = 0; c < 3; ++c) values[offset + c] = value[c];
    };
    auto putOne = [&](float* values, Quantity quantity, float value) {
        int const offset = record.offset(quantity);
        if (offset >= 0) values[offset] = value;
    };
    bool const basics = record.offset(Quantity::P) >= 0 || record.offset(Quantity::N) >= 0 ||
                        record.offset(Quantity::Ng) >= 0;
    bool const parameters = record.offset(Quantity::S) >= 0 || record.offset(Quantity::T) >= 0 ||
                            record.offset(Quantity::U) >= 0 || record.offset(Quantity::V) >= 0;
    for (size_t i = 0; i < static_cast<size_t>(count); ++i) {
        HitRecord const& hit = w.hits[i];
        if (!hit.hit()) continue;
        float const time = w.rayTimes.empty() ? scene.shutterOpen : w.rayTimes[i];
        w.depth[i] = camera->depthAlong(hit.dir, hit.t, time);
        float* values = w.surface.data() + i * width;
        Shape const& shape = *scene.shapes[hit.geomID];
        if (basics) {
            SurfaceBasics const at = shape.basics(hit);
            put(values, Quantity::P, camera->pointToCamera(at.P, time));
            put(values, Quantity::N, camera->normalToCamera(at.N, time));
            put(values, Quantity::Ng, camera->normalToCamera(at.Ng, time));
        }
        if (parameters) {
            SurfaceParameters const at = shape.parameters(hit);
            putOne(values, Quantity::S, at.s);
            putOne(values, Quantity::T, at.t);
            putOne(values, Quantity::U, at.u);
            putOne(values, Quantity::V, at.v);
        }
    }
}

void Renderer::Impl::shadeChunk(Worker& w, int count, Film& film) {
    IntegratorServices services(*rays, shadingLights, *shader, w.arena);
    if (integrator->WantsLightTracing()) services.connectCamera(*camera, film, cameraLights);
    if (!headlight) services.linkLights(scene);
    services.shade(w.hits.data(), w.samples.data(), count, [&](ShadeGroup& group) {
        int n = group.ctx.numPts;
        w.groupRadiance.assign(static_cast<size_t>(n), RtColorRGB(0.0f));
        integrator->Integrate(group.ctx, group.bxdf, group.rng, services, w.groupRadiance.data());
        for (int j = 0; j < n; ++j) w.radiance[static_cast<size_t>(group.source[j])] += w.groupRadiance[static_cast<size_t>(j)];
    });
    w.arena.reset();
    tracer->counters().add(services.rayCounts());
    nonFinite.fetch_add(services.takeNonFinite(), std::memory_order_relaxed);
    invalidPdf.fetch_add(services.takeInvalidPdf(), std::memory_order_relaxed);
}

RayTracer& Renderer::tracer() { return *m_impl->tracer; }

Film Renderer::render() {
    Impl& r = *m_impl;
    auto start = Clock::now();
    int spp = m_stats.spp;
    // The stats describe this render alone, however many came before it.
    r.tracer->counters().reset();
    for (auto* counter : {&r.counters.shadePoints, &r.counters.batches, &r.counters.presencePoints,
                          &r.counters.builtins.surfacePoints,
                          &r.counters.builtins.parameterPoints, &r.counters.builtins.tangentPoints, &r.patternCounters.evaluations,
                          &r.patternCounters.points, &r.nonFinite, &r.invalidPdf})
        *counter = 0;
    uint64_t const lookupsBefore = r.textures ? r.textures->lookups() : 0;
    Film film(r.scene.xres, r.scene.yres);
    film.setFinish(r.scene.finish);
    if (r.integrator->WantsLightTracing()) film.enableSplats();
    if (r.pixelFilter.hasNegativeLobes()) film.enableNegativeLobes(r.pixelFilter.absoluteWeight());
    if (r.surfaceRecord.any()) film.enableSurface(r.surfaceRecord);
    int size = tileSizeFor(r.settings.tileSize, spp);
    int tilesX = (r.scene.xres + size - 1) / size, tilesY = (r.scene.yres + size - 1) / size;
    int tiles = tilesX * tilesY;
    ProgressBar progress(r.settings.progress, tiles);
    tbb::enumerable_thread_specific<Worker> workers;

    tbb::task_arena arena(m_stats.threads);
    arena.execute([&] {
        tbb::parallel_for(0, tiles, [&](int tile) {
            r.renderTile(tile % tilesX, tile / tilesX, film, workers.local());
            progress.tick();
        });
    });

    m_stats.renderSeconds = secondsSince(start);
    RayCounters const& rays = r.tracer->counters();
    m_stats.cameraRays = rays.camera.load();
    m_stats.shadowRays = rays.shadow.load();
    m_stats.indirectRays = rays.indirect.load();
    m_stats.shadePoints = r.counters.shadePoints.load();
    m_stats.batches = r.counters.batches.load();
    m_stats.presencePoints = r.counters.presencePoints.load();
    m_stats.surfacePoints = r.counters.builtins.surfacePoints.load();
    m_stats.parameterPoints = r.counters.builtins.parameterPoints.load();
    m_stats.tangentPoints = r.counters.builtins.tangentPoints.load();
    m_stats.patternEvaluations = r.patternCounters.evaluations.load();
    m_stats.patternPoints = r.patternCounters.points.load();
    m_stats.textureLookups = r.textures ? r.textures->lookups() - lookupsBefore : 0;
    m_stats.nonFiniteSamples = r.nonFinite.load();
    m_stats.invalidPdfSamples = r.invalidPdf.load();
    m_stats.peakMemoryMB = peakResidentMB();
    summarise(film, m_stats.image);
    countSamplesTaken(film, m_stats.samplesTaken);

    // Effects decided while shading: tangent frames are computed only on request.
    auto& effects = m_stats.effects;
    if (r.schedule.adaptive()) {
        RenderStats::SamplesTaken const& taken = m_stats.samplesTaken;
        std::ostringstream line;
        line << "adaptive sampling (PixelVariance " << m_stats.pixelVariance << "): pixels took " << taken.least
             << " to " << taken.most << " samples, " << std::fixed << std::setprecision(1) << taken.mean
             << " on average";
        effects.simulate(line.str());
    }
    if (m_stats.tangentPoints > 0)
        effects.simulate("tangent frames (dPdu, dPdv, Tn) for " + std::to_string(m_stats.tangentPoints) + " points");
    else
        effects.skip("tangent frames", "no plugin asked for Tn, dPdu, dPdv, du or dv");
    if (m_stats.nonFiniteSamples > 0)
        r.diagnostics.warn(std::to_string(m_stats.nonFiniteSamples) +
                           " non-finite (NaN or infinite) sample values were dropped; check the Bxdf for divisions by zero");
    if (m_stats.invalidPdfSamples > 0)
        r.diagnostics.warn(std::to_string(m_stats.invalidPdfSamples) +
                           " samples came with a pdf a Bxdf must not return (FPdf <= 0 or NaN on a valid sample, or a "
                           "negative or NaN FPdf from EvaluateSample) and were dropped; rixwarp and rixgrade show where");
    return film;
}

nlohmann::json RenderStats::toJson(Diagnostics const& diagnostics) const {
    nlohmann::json skipped = nlohmann::json::array();
    for (auto const& [effect, reason] : effects.skipped) skipped.push_back({{"effect", effect}, {"reason", reason}});
    nlohmann::json warnings = nlohmann::json::array();
    for (auto const& entry : diagnostics.entries())
        if (entry.severity != Diagnostics::Severity::Info) warnings.push_back({{"message", entry.text}, {"count", entry.count}});
    return {
        {"wall_s", setupSeconds + renderSeconds},
        {"setup_s", setupSeconds},
        {"render_s", renderSeconds},
        {"threads", threads},
        {"spp", spp},
        {"pixel_variance", pixelVariance},
        {"samples_per_pixel", {{"least", samplesTaken.least}, {"mean", samplesTaken.mean}, {"most", samplesTaken.most}}},
        {"width", width},
        {"height", height},
        {"integrator", integrator},
        {"rays", {{"camera", cameraRays}, {"shadow", shadowRays}, {"indirect", indirectRays}}},
        {"shade_points", shadePoints},
        {"batches", batches},
        {"presence_points", presencePoints},
        {"builtins",
         {{"surface_points", surfacePoints}, {"parameter_points", parameterPoints}, {"tangent_points", tangentPoints}}},
        {"patterns", {{"evaluations", patternEvaluations}, {"points", patternPoints}, {"texture_lookups", textureLookups}}},
        {"nonfinite_samples", nonFiniteSamples},
        {"invalid_pdf_samples", invalidPdfSamples},
        {"peak_memory_mb", peakMemoryMB},
        {"image",
         {{"mean_rgb", {image.meanRgb[0], image.meanRgb[1], image.meanRgb[2]}},
          {"max_rgb", {image.maxRgb[0], image.maxRgb[1], image.maxRgb[2]}},
          {"lit_fraction", image.litFraction}}},
        {"effects", {{"simulated", effects.simulated}, {"skipped", skipped}}},
        {"plugins", plugins},
        {"warnings", warnings},
    };
}

}  // namespace bxdflab
