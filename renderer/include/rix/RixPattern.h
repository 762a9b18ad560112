// RixPattern.h — pattern plugins: nodes that compute values per shade point
// (a texture lookup, a procedural wood grain, a mix of two colours) and feed
// them to a Bxdf's parameters, or to another pattern's.
//
// In RIB, a pattern node is declared with a handle, and a parameter is
// connected to one of its outputs with the "reference" type:
//
//   Pattern "PxrTexture" "grain" "string filename" ["maple.tx"]
//   Bxdf "diffuse" "board" "reference color diffuseColor" ["grain:resultRGB"]
//
// The Bxdf reads diffuseColor with EvalParam exactly as before; because the
// parameter is connected, the result is k_RixSCVarying: one value per point.
// The renderer runs a pattern only when some Bxdf asks for a parameter
// connected to it, at most once per shading context.
//
// A pattern declares its inputs AND its outputs in its parameter table (outputs
// with access k_RixSCOutput) and computes the outputs in ComputeOutputParams.
#pragma once

#include "RixShading.h"

class RixBakeContext;

class RixPattern : public RixShadingPlugin {
public:
    /// One computed output: which parameter of the table it is, and its values.
    struct OutputSpecification {
        RtInt paramId = -1;                      ///< the output's row in the parameter table
        RixSCDetail detail = k_RixSCInvalidDetail;  ///< k_RixSCVarying: numPts values; k_RixSCUniform: one
        RtPointer value = nullptr;               ///< the values, in memory from the context's pool
    };
    /// The name RenderMan 22 and later give it: either may be written.
    using OutputSpec = OutputSpecification;

    /// Computes the outputs for the context's points. Allocate the
    /// OutputSpecification array and the value arrays from the context's pool:
    ///
    ///   RixShadingContext::Allocator pool(sCtx);
    ///   OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(1);
    ///   RtColorRGB* rgb = pool.AllocForPattern<RtColorRGB>(sCtx->numPts);
    ///   out[0].paramId = k_resultRGB; out[0].detail = k_RixSCVarying; out[0].value = rgb;
    ///   *numOutputs = 1; *outputs = out;
    ///
    /// Read your inputs with sCtx->EvalParam (they may be connected too).
    /// An output nothing reads may be skipped: sCtx->GetParamInfo(id, &type,
    /// &cinfo) on an output answers k_RixSCNetworkValue when a connection reads
    /// it; hand the others back with detail k_RixSCInvalidDetail and no value.
    /// `ignoredParamTable` is RenderMan's; this renderer passes nullptr. Return 0.
    virtual int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                                    RtPointer instanceData, RixSCParamInfo const* ignoredParamTable) = 0;

    /// RenderMan's texture baking, which this renderer does not do: it never
    /// calls these, and a pattern written for RenderMan may override them.
    struct Bake2dSpec;
    struct Bake3dSpec;
    virtual bool Bake2dOutput(RixBakeContext const* bakeCtx, Bake2dSpec& spec, RtPointer instanceData) {
        PIXAR_ARGUSED(bakeCtx); PIXAR_ARGUSED(spec); PIXAR_ARGUSED(instanceData);
        return false;
    }
    virtual bool Bake3dOutput(RixBakeContext const* bakeCtx, Bake3dSpec& spec, RtPointer instanceData) {
        PIXAR_ARGUSED(bakeCtx); PIXAR_ARGUSED(spec); PIXAR_ARGUSED(instanceData);
        return false;
    }
};

/// Write `RIX_PATTERNCREATE { return new MyPattern(); }` in your plugin.
#define RIX_PATTERNCREATE extern "C" PRMANEXPORT RixPattern* CreateRixPattern(const char* hint RIX_MAYBE_UNUSED)
/// Write `RIX_PATTERNDESTROY { delete static_cast<MyPattern*>(pattern); }` in your plugin.
#define RIX_PATTERNDESTROY extern "C" PRMANEXPORT void DestroyRixPattern(RixPattern* pattern)
