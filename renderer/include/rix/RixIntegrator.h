// RixIntegrator.h — the integrator plugin interface.
//
// An integrator turns Bxdfs and lights into pixel values. Like a Bxdf it is a
// shared object the renderer loads by name (`Integrator "PxrDirectLighting" ...`
// loads PxrDirectLighting.so from the plugin search path). The renderer hands
// it one batch of shade points at a time, all on the same Bxdf, with the Bxdf
// already built (BeginScatter); Integrate adds to radiance[i] the light leaving
// point i toward the viewer. Everything else an integrator needs (lights,
// shadow rays, tracing further bounces) it asks of the RixIntegratorContext.
#pragma once

#include <functional>

#include "RixBxdf.h"
#include "RixShadingUtils.h"

/// A direction toward a light, as the light itself samples it.
struct RixLightSample {
    RtVector3 wi;              ///< unit direction from the shade point toward the light
    float distance = 0.0f;     ///< to the sampled point on the light (infinite for distant/dome lights)
    RtColorRGB radiance;       ///< arriving along -wi (black when the light faces away)
    float pdf = 0.0f;          ///< per unit solid angle; 1 for delta lights
    bool delta = false;        ///< no Bxdf sample can ever find this direction
    bool shadows = true;       ///< false: the light casts no shadows (a classic light without a shadow map,
                               ///< a RIS light with enableShadows 0); ask Unoccluded with distance 0, which is
                               ///< always clear
    float diffuse = 1.0f;      ///< the light's "diffuse" and "specular" multipliers (non-physical artist
    float specular = 1.0f;     ///< controls): what the Bxdf's diffuse lobes take of this light is multiplied
                               ///< by diffuse, what its specular lobes take by specular (user lobes: by 1)
};

/// The light a ray reaches (before any surface), if any.
struct RixLightHit {
    bool hit = false;
    float distance = 0.0f;
    RtColorRGB radiance;
    float pdf = 0.0f;          ///< the pdf that light's own sampling gives this direction
    int light = -1;            ///< which light (as numbered for SampleLight)
    float diffuse = 1.0f;      ///< that light's diffuse and specular multipliers, as in RixLightSample
    float specular = 1.0f;
};

/// A ray leaving a light: the first step of a light subpath, for
/// bidirectional integrators (PxrVCM). Lights at infinity cannot start one.
struct RixLightEmission {
    bool valid = false;        ///< false: the light sends nothing (black, or not a finite light)
    RtPoint3 P;                ///< the point on the light
    RtNormal3 N;               ///< the light's unit normal at P; zero for a point light
    RtVector3 dir;             ///< unit direction of the ray
    RtColorRGB radiance;       ///< leaving P along dir (a point light's radiant intensity)
    float pdfArea = 0.0f;      ///< per unit area of the light; 1 for a point light (it has no area)
    float pdfDir = 0.0f;       ///< per unit solid angle around dir
    bool deltaPosition = false;  ///< a point light: no ray can ever reach it
    float diffuse = 1.0f;      ///< the light's diffuse and specular multipliers, as in RixLightSample: they
    float specular = 1.0f;     ///< apply at the first surface the ray reaches
};

/// The densities with which light at point P of a light reaches a receiver:
/// SampleEmission's (the point, then the direction toward the receiver), and
/// SampleLight's from the receiver.
struct RixEmissionPdf {
    float pdfArea = 0.0f;
    float pdfDir = 0.0f;
    float cosine = 1.0f;       ///< |N . dir| at P (1 for a point light)
    float pdfLightSample = 0.0f;  ///< SampleLight's pdf (per unit solid angle at the receiver); 1 for a point light
};

/// A shade point seen from the camera, for light subpaths joined to it (light tracing).
struct RixCameraConnection {
    bool hit = false;          ///< the point is in the image (and unoccluded, when that was asked)
    RtVector3 dir;             ///< unit, from the point toward the eye
    float distance = 0.0f;
    float importance = 0.0f;   ///< a light path's W * throughput times this is what it adds to the pixel it lands in
    float pdfArea = 0.0f;      ///< density (per unit area at the point) of a camera ray reaching it, for MIS
    int pixelX = -1, pixelY = -1;  ///< the pixel it lands in
};

/// A batch the renderer shaded on the integrator's behalf (a further bounce):
/// point j of ctx continues ray source[j] of the TraceIndirect call.
struct RixShadeBatch {
    RixShadingContext const& ctx;
    RixBxdf& bxdf;
    RixRNG& rng;
    int const* source;
};

/// What the renderer offers an integrator while it shades a batch.
class RixIntegratorContext {
public:
    virtual ~RixIntegratorContext() = default;

    /// The lights next-event estimation should sample.
    virtual int GetNumLights() const = 0;
    virtual RixLightSample SampleLight(int light, RtPoint3 const& P, RtFloat2 const& xi) const = 0;
    /// Light linking: does this light light point i of ctx? A RIB file can turn a light off for
    /// some shapes (Illuminate, or a classic light's attribute block); skip it at their points.
    /// VisibleLight(s) and TraceIndirect already give such a light no radiance there.
    virtual bool Illuminates(int light, RixShadingContext const& ctx, int i) const = 0;

    /// A shadow ray: is the way from point i of ctx toward dir, up to distance, clear? A light
    /// whose lit face lies in the way blocks it, as it ends a path that meets it. A distance of 0
    /// (or less) holds nothing: it is clear, and no ray is traced.
    virtual bool Unoccluded(RixShadingContext const& ctx, int i, RtVector3 const& dir, float distance) = 0;
    /// A shadow ray toward whichever light lies along dir from point i (hit = false if none, or blocked).
    virtual RixLightHit VisibleLight(RixShadingContext const& ctx, int i, RtVector3 const& dir) = 0;
    /// The same two questions for many points at once: ray k leaves point indices[k] of ctx toward
    /// dirs[k]. The renderer traces them together, which is faster than a call per ray; the answers
    /// are the ones the calls above would give. Unoccluded: clear[k] is whether the way is clear
    /// up to distances[k]. VisibleLights: hits[k] as VisibleLight gives it.
    virtual void Unoccluded(RixShadingContext const& ctx, int count, int const* indices, RtVector3 const* dirs,
                            float const* distances, bool* clear) = 0;
    virtual void VisibleLights(RixShadingContext const& ctx, int count, int const* indices, RtVector3 const* dirs,
                               RixLightHit* hits) = 0;

    /// The bounce limits of the surface at point i of ctx. RenderMan's path tracer keeps two
    /// limits along a path, diffuse and specular, each min(the limit so far, the bounces of that
    /// kind so far + this surface's value), and continues a path by a lobe's kind only while its
    /// count is below its limit (PxrPathTracer.cpp shows how). An integrator may ignore them.
    virtual RixTraceDepth TraceDepth(RixShadingContext const& ctx, int i) const = 0;

    /// Traces count rays leaving points indices[k] of ctx in directions dirs[k]. For every ray,
    /// lightHits[k] tells whether it reaches a light before any surface. Rays that hit a surface
    /// first and have shade[k] set are shaded, as batches grouped by Bxdf, and each batch is handed
    /// to visit; samples[k] is where ray k's point is in its random sequence (it carries on there).
    /// A null lightHits traces a light subpath's rays: lights add nothing to them, and a ray ends
    /// at a light only where a camera path crossing the same segment the other way would (at a
    /// light that emits along the ray; a light's dark back lets both through).
    virtual void TraceIndirect(RixShadingContext const& ctx, int count, int const* indices, RtVector3 const* dirs,
                               bool const* shade, RixRNG::SampleCtx const* samples, RixLightHit* lightHits,
                               std::function<void(RixShadeBatch&)> const& visit) = 0;

    /// Bidirectional integrators. CanEmit: can this light start light subpaths?
    /// SampleEmission chooses a point on it and a direction from two 2-D samples;
    /// EmissionPdf gives the densities of reaching `receiver` from P (see RixEmissionPdf).
    virtual bool CanEmit(int light) const = 0;
    virtual RixLightEmission SampleEmission(int light, RtFloat2 const& xiPosition, RtFloat2 const& xiDirection) const = 0;
    virtual RixEmissionPdf EmissionPdf(int light, RtPoint3 const& P, RtPoint3 const& receiver) const = 0;
    /// Traces count rays leaving lights. Those that reach a surface are shaded, as batches grouped
    /// by Bxdf, and each batch is handed to visit (point j continues ray source[j]); samples[k] is
    /// where ray k's random sequence starts. Lights add nothing to these rays; they end at one
    /// only as TraceIndirect's light subpath rays do.
    virtual void TraceEmitted(int count, RixLightEmission const* rays, RixRNG::SampleCtx const* samples,
                              std::function<void(RixShadeBatch&)> const& visit) = 0;

    /// Light tracing, for integrators whose WantsLightTracing() is true. CanConnectCamera: the
    /// camera is a pinhole (perspective). ConnectCamera: where point i of ctx lands in the image;
    /// with testVisibility, a shadow ray toward the eye too. SplatCamera adds value (a light path's
    /// contribution times the connection's importance) to the pixel the connection lands in;
    /// CountLightPaths tells how many light subpaths could add (the image gets their sum divided
    /// by that count).
    virtual bool CanConnectCamera() const = 0;
    virtual RixCameraConnection ConnectCamera(RixShadingContext const& ctx, int i, bool testVisibility) = 0;
    virtual void SplatCamera(RixCameraConnection const& where, RtColorRGB const& value) = 0;
    virtual void CountLightPaths(int count) = 0;

    /// Reports a NaN or infinite contribution (a Bxdf bug): counted in the render stats, then dropped.
    virtual void CountNonFinite() = 0;
    /// Reports a pdf a Bxdf should never return (a Bxdf bug): FPdf <= 0 or NaN for a sample it
    /// marked valid, or a negative or NaN FPdf from EvaluateSample. Counted in the render stats;
    /// the sample is dropped (its pdf taken as 0).
    virtual void CountInvalidPdf() = 0;
};

/// Which effects a render simulates and which it skips, for the stats.
class RixEffects {
public:
    virtual ~RixEffects() = default;
    virtual void Simulate(const char* effect) = 0;
    virtual void Skip(const char* effect, const char* reason) = 0;
};

class RixIntegrator {
public:
    virtual ~RixIntegrator() = default;
    /// True when the integrator lights the scene itself with a light at the camera
    /// (PxrDefault): the scene's lights are then not sampled.
    virtual bool WantsHeadlight() const { return false; }
    /// True when the integrator joins light subpaths to the camera (SplatCamera).
    virtual bool WantsLightTracing() const { return false; }
    /// States what the integrator will simulate given the number of lights it will sample.
    virtual void DescribeEffects(int numLights, RixEffects& effects) const = 0;
    /// Adds to radiance[i] the light leaving point i of the batch toward the viewer.
    virtual void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                           RtColorRGB* radiance) = 0;
};

/// Veach's power heuristic (beta = 2): the MIS weight of a sample from strategy
/// f (nf samples, density pdfF) against strategy g (ng samples, density pdfG).
PRMAN_INLINE float RixPowerHeuristic(float nf, float pdfF, float ng, float pdfG) {
    float f = nf * pdfF, g = ng * pdfG;
    if (std::isinf(f * f)) return 1.0f;
    float denominator = f * f + g * g;
    return denominator > 0.0f ? (f * f) / denominator : 0.0f;
}

/// Create an integrator from the RIB's parameters. Return null (after saying
/// why with messages->Error) when the parameters are unusable.
#define RIX_INTEGRATORCREATE \
    extern "C" PRMANEXPORT RixIntegrator* CreateRixIntegrator(RixParameterList const* params, RixMessages* messages)
#define RIX_INTEGRATORDESTROY extern "C" PRMANEXPORT void DestroyRixIntegrator(RixIntegrator* integrator)
