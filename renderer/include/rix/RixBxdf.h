// RixBxdf.h — the Bxdf plugin interface. Including this file (plus
// RixShadingUtils.h for the helpers) is all a Bxdf plugin needs.
//
// A Bxdf plugin is a shared object (e.g. diffuse.so) with two parts:
//
//  1. A FACTORY (derived from RixBxdfFactory): one per plugin. It declares the
//     parameter table, looks up its lobes at render begin, and, for every
//     batch of shade points, evaluates the parameters and builds a Bxdf
//     (BeginScatter) that the integrator uses and then returns (EndScatter).
//
//  2. A BXDF (derived from RixBxdf): one per batch. It answers the integrator's
//     questions about scattering at each point of the batch:
//       GenerateSample          "pick a direction Ln for me, and tell me its weight and pdf"
//       EvaluateSample          "here is a direction Ln: what are the weight and pdf?"
//       EvaluateSamplesAtIndex  the same, for many directions at ONE point
//       EmitLocal               "does the surface itself glow?"
//
// THE WEIGHT CONVENTION (the whole renderer relies on it):
//     W     = f(Vn, Ln) * |cos(theta_L)|     the BRDF times the cosine, NOT divided by the pdf
//     FPdf  = pdf of generating Ln given Vn, per unit solid angle
//     RPdf  = pdf of generating Vn given Ln (the reverse direction)
// The integrator forms Li * W / FPdf. A Lambertian surface with cosine
// sampling returns W = albedo * cos/pi, FPdf = cos(theta_L)/pi, RPdf = cos(theta_V)/pi.
//
// Every plugin exports a create/destroy pair with C linkage:
//     RIX_BXDFPLUGINCREATE  { return new MyFactory(); }
//     RIX_BXDFPLUGINDESTROY { delete static_cast<MyFactory*>(bxdf); }
#pragma once

#include <vector>

#include "RiTypesHelper.h"
#include "RixBxdfLobe.h"
#include "RixInterfaces.h"
#include "RixRNG.h"
#include "RixShading.h"

/// Where a Bxdf's EvaluateSample can return something other than zero: which
/// sides of the surface V and L lie on, told by the geometric normal ("outside"
/// is the side Ngn points to). The renderer's integrators take it at its word:
/// a direction outside the domain gets no light, whatever EvaluateSample says,
/// and a (non-discrete) sample GenerateSample makes there is dropped. The
/// values are RenderMan's (bits to combine with |).
enum RixBXEvaluateDomain {
    k_RixBXEmptyDomain = 0,      ///< scatters nothing (emits, or makes only discrete samples)
    k_RixBXOutsideReflect = 1,   ///< V and L both outside (a closed opaque object)
    k_RixBXOutsideTransmit = 2,  ///< V outside, L inside
    k_RixBXInsideReflect = 4,    ///< V and L both inside
    k_RixBXInsideTransmit = 8,   ///< V inside, L outside
    k_RixBXVolume = 16,          ///< a volume: no side, no surface cosine
    k_RixBXReflect = k_RixBXOutsideReflect | k_RixBXInsideReflect,     ///< reflection on either side (two-sided)
    k_RixBXTransmit = k_RixBXOutsideTransmit | k_RixBXInsideTransmit,
    k_RixBXOutside = k_RixBXOutsideReflect | k_RixBXOutsideTransmit,   ///< light from the outside only
    k_RixBXInside = k_RixBXInsideReflect | k_RixBXInsideTransmit,
    k_RixBXBoth = k_RixBXReflect | k_RixBXTransmit,                    ///< every pair of sides
};

/// Which light transport the integrator is computing (direct from lights,
/// or indirect from other surfaces). Most Bxdfs ignore it.
enum RixBXTransportTrait {
    k_RixBXDirectLighting = 1,
    k_RixBXIndirectLighting = 2,
    k_RixBXAllTransport = 3,
};

class RixBxdfFactory;
class RixOpacity;
class RixVolumeIntegrator;
/// RenderMan 25's post-lighting stage: named so that factories written for it
/// (BeginPostLighting returning null) compile; this renderer never calls them.
class RixPostLighting;

/// One batch's scattering function. Built by the factory in BeginScatter, in
/// memory from the shading context's pool: it must not own heap memory (its
/// destructor is not called; the pool is simply released).
class RixBxdf {
public:
    RixBxdf(RixShadingContext const* sc, RixBxdfFactory* factory) : shadingCtx(sc), bxdfFactory(factory) {}
    virtual ~RixBxdf() = default;

    /// Where this Bxdf scatters (see RixBXEvaluateDomain).
    virtual RixBXEvaluateDomain GetEvaluateDomain() = 0;

    /// The union of all lobes this Bxdf can produce (may be empty, e.g. for
    /// a purely emissive surface: then the integrator never samples it).
    virtual void GetAggregateLobeTraits(RixBXLobeTraits* lobes) = 0;
    RixBXLobeTraits GetAllLobeTraits() {
        RixBXLobeTraits lobes;
        GetAggregateLobeTraits(&lobes);
        return lobes;
    }

    /// Radiance the surface emits toward Vn, per point. Return false (and leave
    /// result untouched) when the surface does not emit.
    virtual bool EmitLocal(RtColorRGB* result) { PIXAR_ARGUSED(result); return false; }

    /// For every point i: choose a direction Ln[i], tag it with the lobe that
    /// produced it (lobeSampled[i], SetValid(true) on success), write its weight
    /// into that lobe's array in W, and its pdfs into FPdf[i], RPdf[i].
    /// All arrays have numPts entries. lobesWanted[i] restricts which lobes may be sampled.
    virtual void GenerateSample(RixBXTransportTrait transportTrait, RixBXLobeTraits const* lobesWanted,
                                RixRNG* rng, RixBXLobeSampled* lobeSampled, RtVector3* Ln,
                                RixBXLobeWeights& W, float* FPdf, float* RPdf,
                                RtColorRGB* compTrans = nullptr) = 0;

    /// For every point i: evaluate the given direction Ln[i]. Add each lobe's
    /// weight to W, set lobesEvaluated[i] to the lobes that contributed (and
    /// SetValid(true)), and write the pdfs GenerateSample would have used.
    virtual void EvaluateSample(RixBXTransportTrait transportTrait, RixBXLobeTraits const* lobesWanted,
                                RixRNG* rng, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                RixBXLobeWeights& W, float* FPdf, float* RPdf) = 0;

    /// Like EvaluateSample, but for numSamples directions at the single point
    /// `index`: Ln, W's arrays, FPdf, RPdf and lobesEvaluated have numSamples entries.
    virtual void EvaluateSamplesAtIndex(RixBXTransportTrait transportTrait, RixBXLobeTraits const& lobesWanted,
                                        RixRNG* rng, int index, int numSamples,
                                        RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                        RixBXLobeWeights& W, float* FPdf, float* RPdf) = 0;

    /// Optional answers to questions about the material.
    enum BxdfProperty { k_Albedo = 0, k_MaterialIor };
    virtual RixSCDetail GetProperty(BxdfProperty property, void const** result) const {
        PIXAR_ARGUSED(property); PIXAR_ARGUSED(result);
        return k_RixSCInvalidDetail;
    }
    virtual void Release() {}

    /// The shading context this Bxdf was made for, and the factory that made it.
    RixShadingContext const* GetShadingCtx() const { return shadingCtx; }
    RixBxdfFactory* GetBxdfFactory() const { return bxdfFactory; }

protected:
    RixShadingContext const* shadingCtx;
    RixBxdfFactory* bxdfFactory;
};

/// The plugin's factory: one object per loaded plugin.
class RixBxdfFactory : public RixShadingPlugin {
public:
    /// Hints that let the renderer skip work. The default, k_TriviallyOpaque,
    /// says "fully opaque, no presence, no interior": no opacity work is done.
    enum InstanceHints {
        k_TriviallyOpaque = 0,
        k_ComputesPresence = 1 << 0,
        k_ComputesOpacity = 1 << 1,
        k_ComputesInterior = 1 << 2,
        k_InteriorTransmission = 1 << 3,
    };
    virtual int GetInstanceHints(RtPointer instanceData) const {
        PIXAR_ARGUSED(instanceData);
        return k_TriviallyOpaque;
    }

    /// Builds the Bxdf for one batch: evaluate the parameters (sCtx->EvalParam),
    /// allocate the Bxdf from the context's pool and placement-new it.
    virtual RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                  RixSCShadingMode shadingMode, void* parentData,
                                  RtPointer instanceData) = 0;
    /// The integrator is done with the Bxdf (its memory is reclaimed with the context).
    virtual void EndScatter(RixBxdf* bxdf) = 0;

    /// Presence (cut-outs). Called only for instances whose GetInstanceHints
    /// include k_ComputesPresence, with mode k_RixSCPresenceQuery, for a batch
    /// of points that rays have hit: return a RixOpacity (allocated from the
    /// context's pool, like a Bxdf) whose GetPresence says how present each
    /// point is, or null for "fully present". A ray that meets an absent point
    /// goes on as if the surface were not there. See RixOpacity below.
    virtual RixOpacity* BeginOpacity(RixShadingContext const* sCtx, RixSCShadingMode mode,
                                     void* parentData, RtPointer instanceData) {
        PIXAR_ARGUSED(sCtx); PIXAR_ARGUSED(mode); PIXAR_ARGUSED(parentData); PIXAR_ARGUSED(instanceData);
        return nullptr;
    }
    /// The renderer is done with the RixOpacity (RixOpacity::Release calls this).
    virtual void EndOpacity(RixOpacity* opacity) { PIXAR_ARGUSED(opacity); }

    // Features this renderer does not use; the defaults do nothing, so plugins
    // may override them with null implementations or leave them out.
    virtual RixVolumeIntegrator* BeginInterior(RixShadingContext const* sCtx, RixSCShadingMode mode,
                                               void* parentData, RtPointer instanceData) {
        PIXAR_ARGUSED(sCtx); PIXAR_ARGUSED(mode); PIXAR_ARGUSED(parentData); PIXAR_ARGUSED(instanceData);
        return nullptr;
    }
    virtual RixVolumeIntegrator* BeginSubsurface(RixShadingContext const* sCtx, RixSCShadingMode mode,
                                                 void* parentData, RtPointer instanceData) {
        PIXAR_ARGUSED(sCtx); PIXAR_ARGUSED(mode); PIXAR_ARGUSED(parentData); PIXAR_ARGUSED(instanceData);
        return nullptr;
    }
    virtual void EndInterior(RixVolumeIntegrator* vol) { PIXAR_ARGUSED(vol); }
    virtual void EndSubsurface(RixVolumeIntegrator* vol) { PIXAR_ARGUSED(vol); }
    virtual float GetIndexOfRefraction(RtPointer instanceData) const { PIXAR_ARGUSED(instanceData); return 1.0f; }
    /// Which parameters vary over the shutter, for motion-blurred volumes: none here.
    virtual void RegisterTemporalVolumeParams(RtPointer instanceData, std::vector<RtInt>& paramIds) const {
        PIXAR_ARGUSED(instanceData);
        PIXAR_ARGUSED(paramIds);
    }
};

/// How present a batch's points are, made by RixBxdfFactory::BeginOpacity.
/// Presence is the chance that a ray meeting the point stops there: 1 fully
/// present, 0 absent (a hole in a leaf's texture), values between for soft,
/// antialiased edges. The renderer draws one random number per hit, so a
/// point of presence 0.3 stops 30% of the rays that reach it, whatever their
/// kind (camera, indirect or shadow); the others go on to what lies behind.
/// Presence does not change how a present point scatters light.
class RixOpacity {
public:
    RixOpacity(RixShadingContext const* sCtx, RixBxdfFactory* factory) : shadingCtx(sCtx), bxdfFactory(factory) {}
    virtual ~RixOpacity() {}
    RixBxdfFactory* GetBxdfFactory() { return bxdfFactory; }
    RixShadingContext const* GetShadingCtx() { return shadingCtx; }

    /// Writes shadingCtx->numPts presence values in [0, 1] to `result`, or
    /// returns false to say "every point is fully present" (result unread).
    virtual bool GetPresence(float* result) = 0;
    /// Coloured opacity for shadow rays: this renderer does not call it
    /// (Bxdfs that ask for it get a warning, and their shadows are opaque).
    virtual bool GetOpacity(RtColorRGB* result) = 0;
    virtual void Release() {
        if (bxdfFactory) bxdfFactory->EndOpacity(this);
    }

protected:
    RixShadingContext const* shadingCtx;
    RixBxdfFactory* bxdfFactory;
};

/// Write `RIX_BXDFPLUGINCREATE { return new MyFactory(); }` in your plugin.
#define RIX_BXDFPLUGINCREATE extern "C" PRMANEXPORT RixBxdfFactory* CreateRixBxdfFactory(const char* hint RIX_MAYBE_UNUSED)
/// Write `RIX_BXDFPLUGINDESTROY { delete static_cast<MyFactory*>(bxdf); }` in your plugin.
#define RIX_BXDFPLUGINDESTROY extern "C" PRMANEXPORT void DestroyRixBxdfFactory(RixBxdfFactory* bxdf)
