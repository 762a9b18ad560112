// The renderer's side of the integrator plugin API (RixIntegrator.h): what
// an integrator can ask while it shades a batch, and the record of which
// effects a render simulates. One IntegratorServices per worker and chunk.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "RixIntegrator.h"
#include "accel/RayTracer.h"
#include "integrate/SplatTarget.h"
#include "scene/Camera.h"
#include "shade/BatchShader.h"
#include "shade/PresenceTracer.h"
#include "scene/Scene.h"

namespace bxdflab {

/// Which effects a render simulates and which it skips (and why).
struct EffectReport : RixEffects {
    std::vector<std::string> simulated;
    std::vector<std::pair<std::string, std::string>> skipped;  ///< effect, reason
    void Simulate(const char* effect) override { simulated.emplace_back(effect); }
    void Skip(const char* effect, const char* reason) override { skipped.emplace_back(effect, reason); }
    void simulate(std::string const& effect) { simulated.push_back(effect); }
    void skip(std::string const& effect, std::string const& reason) { skipped.emplace_back(effect, reason); }
};

class IntegratorServices final : public RixIntegratorContext {
public:
    IntegratorServices(PresenceTracer const& tracer, std::vector<Light const*> lights, BatchShader const& shader,
                       MemoryArena& arena)
        : m_tracer(tracer), m_lights(std::move(lights)), m_shader(shader), m_arena(arena) {
        for (Light const* light : m_lights) m_finiteLights |= !light->isDelta() && !light->isInfinite();
    }

    int GetNumLights() const override { return static_cast<int>(m_lights.size()); }
    RixLightSample SampleLight(int light, RtPoint3 const& P, RtFloat2 const& xi) const override;
    bool Illuminates(int light, RixShadingContext const& ctx, int i) const override;
    RixTraceDepth TraceDepth(RixShadingContext const& ctx, int i) const override;
    bool Unoccluded(RixShadingContext const& ctx, int i, RtVector3 const& dir, float distance) override;
    RixLightHit VisibleLight(RixShadingContext const& ctx, int i, RtVector3 const& dir) override;
    void Unoccluded(RixShadingContext const& ctx, int count, int const* indices, RtVector3 const* dirs,
                    float const* distances, bool* clear) override;
    void VisibleLights(RixShadingContext const& ctx, int count, int const* indices, RtVector3 const* dirs,
                       RixLightHit* hits) override;
    void TraceIndirect(RixShadingContext const& ctx, int count, int const* indices, RtVector3 const* dirs,
                       bool const* shade, RixRNG::SampleCtx const* samples, RixLightHit* lightHits,
                       std::function<void(RixShadeBatch&)> const& visit) override;
    bool CanEmit(int light) const override { return m_lights[static_cast<size_t>(light)]->canEmit(); }
    RixLightEmission SampleEmission(int light, RtFloat2 const& xiPosition, RtFloat2 const& xiDirection) const override;
    RixEmissionPdf EmissionPdf(int light, RtPoint3 const& P, RtPoint3 const& receiver) const override;
    void TraceEmitted(int count, RixLightEmission const* rays, RixRNG::SampleCtx const* samples,
                      std::function<void(RixShadeBatch&)> const& visit) override;
    bool CanConnectCamera() const override { return m_camera && m_camera->perspective(); }
    RixCameraConnection ConnectCamera(RixShadingContext const& ctx, int i, bool testVisibility) override;
    void SplatCamera(RixCameraConnection const& where, RtColorRGB const& value) override;
    void CountLightPaths(int count) override {
        if (m_film) m_film->countSplatPaths(static_cast<uint64_t>(count));
    }
    /// Light tracing: the camera to join points to, the film they add to, and
    /// the lights the camera sees (which hide what lies behind them).
    void connectCamera(Camera const& camera, SplatTarget& film, std::vector<Light const*> const& cameraLights) {
        m_camera = &camera;
        m_film = &film;
        m_cameraLights = &cameraLights;
    }
    void CountNonFinite() override { ++m_nonFinite; }
    void CountInvalidPdf() override { ++m_invalidPdf; }

    /// Light linking: the scene whose shapes say which of these lights (the scene's own, in its
    /// order) light them. Without it every light lights every point (a headlight, say).
    void linkLights(Scene const& scene) { m_linkedScene = scene.lightLinks.empty() ? nullptr : &scene; }

    /// Shades hits as batches grouped by Bxdf (camera hits use this too).
    void shade(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count, BatchShader::Visitor const& visit);
    RayCounts& rayCounts() { return m_counts; }
    uint64_t takeNonFinite() { return std::exchange(m_nonFinite, 0); }
    uint64_t takeInvalidPdf() { return std::exchange(m_invalidPdf, 0); }

private:
    /// The nearest light along a ray, closer than maxDistance (not tested for occlusion).
    RixLightHit lightAlong(Vec3 const& origin, Vec3 const& dir, float maxDistance) const;
    /// Whether the nearest light along the ray, closer than maxDistance, emits along `toward`
    /// where the ray meets it. A camera path ends at a light whose lit face it meets and passes
    /// a dark back; shadow rays (toward = -dir) and light subpaths (toward = dir) are stopped
    /// where that path would be, so every strategy sees the same segments clear.
    bool lightEmitsAcross(Vec3 const& from, Vec3 const& dir, float maxDistance, Vec3 const& toward) const;
    /// Shades hits, and hands each batch to visit while remembering its hits (for Illuminates).
    void shadeBatches(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count,
                      BatchShader::Visitor const& visit);
    /// The batch being integrated that ctx is, or null when ctx is none of them.
    ShadingContextImpl const* batchOf(RixShadingContext const& ctx) const;
    /// A light reached from point i of ctx that does not light it sends it nothing.
    void unlinkedSendNothing(RixShadingContext const& ctx, int i, RixLightHit& hit) const {
        if (hit.hit && !Illuminates(hit.light, ctx, i)) hit.radiance = RtColorRGB(0.0f);
    }

    PresenceTracer const& m_tracer;  ///< every query sees through cut-outs
    std::vector<Light const*> m_lights;
    bool m_finiteLights = false;  ///< some light has a shape a ray can meet
    BatchShader const& m_shader;
    MemoryArena& m_arena;
    Camera const* m_camera = nullptr;
    SplatTarget* m_film = nullptr;
    std::vector<Light const*> const* m_cameraLights = nullptr;
    Scene const* m_linkedScene = nullptr;
    /// The batches being integrated, innermost last (a batch's context knows the shapes it shades).
    std::vector<ShadingContextImpl const*> m_batches;
    RayCounts m_counts;
    uint64_t m_nonFinite = 0;
    uint64_t m_invalidPdf = 0;
};

}  // namespace bxdflab
