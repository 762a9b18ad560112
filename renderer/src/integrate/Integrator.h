// Integrators turn Bxdfs and lights into pixel values. The renderer hands an
// integrator one batch of shade points at a time (all on the same Bxdf), with
// the Bxdf already built by the plugin's BeginScatter; the integrator adds
// the radiance leaving each point toward the camera.
//
// New integrators (path tracer, validation, debugging) implement this
// interface and register a name in IntegratorRegistry.cpp.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "RixBxdf.h"
#include "accel/RayTracer.h"
#include "core/Diagnostics.h"
#include "scene/Scene.h"
#include "render/BatchShader.h"
#include "shade/ShadingContextImpl.h"

namespace bxdflab {

/// Which effects a render simulates and which it skips (and why).
struct EffectReport {
    std::vector<std::string> simulated;
    std::vector<std::pair<std::string, std::string>> skipped;  ///< effect, reason
    void simulate(std::string effect) { simulated.push_back(std::move(effect)); }
    void skip(std::string effect, std::string reason) { skipped.emplace_back(std::move(effect), std::move(reason)); }
};

/// The light a ray hits first, if any.
struct LightHit {
    Light const* light = nullptr;
    float distance = kInfinity;
    RtColorRGB radiance;
    float pdf = 0.0f;  ///< the pdf the light's own sampling gives this direction
};

/// What the renderer offers an integrator while it shades one batch. One
/// instance per worker thread; not shared.
class IntegratorServices {
public:
    IntegratorServices(RayTracer const& tracer, std::vector<Light const*> lights, BatchShader const& shader,
                       MemoryArena& arena)
        : m_tracer(tracer), m_lights(std::move(lights)), m_shader(shader), m_arena(arena) {}

    /// Lights that next-event estimation samples.
    std::vector<Light const*> const& lights() const { return m_lights; }

    /// Is the segment from surface point P (error bound pError, normal Ng)
    /// toward wi, up to `distance`, free of occluders?
    bool unoccluded(Vec3 const& P, Vec3 const& pError, Vec3 const& Ng, Vec3 const& wi, float distance);

    /// The nearest light along a ray leaving P toward dir, if it is not
    /// blocked by geometry.
    LightHit visibleLight(Vec3 const& P, Vec3 const& pError, Vec3 const& Ng, Vec3 const& dir);

    /// The nearest light along a ray from `origin` closer than maxDistance
    /// (occlusion by geometry is the caller's business).
    LightHit lightAlong(Vec3 const& origin, Vec3 const& dir, float maxDistance) const;

    /// The first surface an indirect ray leaving surface point P toward dir hits.
    HitRecord traceIndirect(Vec3 const& P, Vec3 const& pError, Vec3 const& Ng, Vec3 const& dir);

    /// Shades hits as batches grouped by Bxdf (see BatchShader).
    void shade(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count, BatchShader::Visitor const& visit) {
        m_shader.shade(hits, samples, count, m_arena, visit);
    }

    /// Counts a non-finite contribution (a Bxdf bug); the contribution is dropped.
    void countNonFinite() { ++m_nonFinite; }

    RayCounts& rayCounts() { return m_counts; }
    uint64_t takeNonFinite() { return std::exchange(m_nonFinite, 0); }

private:
    RayTracer const& m_tracer;
    std::vector<Light const*> m_lights;
    BatchShader const& m_shader;
    MemoryArena& m_arena;
    RayCounts m_counts;
    uint64_t m_nonFinite = 0;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual std::string name() const = 0;
    /// Lights this integrator adds of its own (PxrDefault's headlight).
    virtual std::vector<Light const*> extraLights() const { return {}; }
    /// States which effects this integrator will simulate for the scene.
    virtual void describeEffects(Scene const& scene, EffectReport& report) const = 0;
    /// Adds to radiance[i] the light leaving point i of the batch toward the viewer.
    virtual void integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                           RtColorRGB* radiance) = 0;
};

/// The integrator the scene asks for (Integrator "name" ...), configured from
/// its parameters. Throws a located RibError for an unknown name.
std::unique_ptr<Integrator> makeIntegrator(IntegratorDesc const& desc, Scene const& scene, Vec3 const& cameraPosition,
                                           Diagnostics& diagnostics);

}  // namespace bxdflab
