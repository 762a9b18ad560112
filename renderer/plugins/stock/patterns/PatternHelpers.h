// Small helpers the stock patterns share: allocating an output, and the
// texture coordinates of a shading context with their filter footprint.
#pragma once

#include <algorithm>
#include <cmath>

#include "RixPattern.h"

namespace stockpatterns {

/// The stock patterns need no set-up, clean-up or render-time messages: only
/// their parameter table and ComputeOutputParams differ.
class StockPattern : public RixPattern {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
};

/// Exports the create/destroy pair the renderer looks up in a pattern plugin.
#define STOCK_PATTERN_PLUGIN(Pattern)           \
    RIX_PATTERNCREATE {                         \
        PIXAR_ARGUSED(hint);                    \
        return new Pattern();                   \
    }                                           \
    RIX_PATTERNDESTROY { delete static_cast<Pattern*>(pattern); }

/// The three outputs of a pattern that hands one value out as every type
/// (outputAsEveryType): write it last in the parameter table, before the end.
#define STOCK_PATTERN_OUTPUTS_OF_EVERY_TYPE                              \
    RixSCParamInfo(RtUString("resultF"), k_RixSCFloat, k_RixSCOutput),   \
        RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput), \
        RixSCParamInfo(RtUString("resultP"), k_RixSCPoint, k_RixSCOutput)

/// Adds output `paramId` with one value per point to `out` (which has room)
/// and returns the array to fill.
template <typename T>
T* addVaryingOutput(RixShadingContext const* sCtx, RixPattern::OutputSpecification* out, int& count, int paramId) {
    RixShadingContext::Allocator pool(sCtx);
    T* values = pool.AllocForPattern<T>(sCtx->numPts);
    out[count].paramId = paramId;
    out[count].detail = k_RixSCVarying;
    out[count].value = values;
    ++count;
    return values;
}

/// The texture coordinates of every point as a manifold: (s, t, footprint),
/// the footprint being the width of the ray's footprint in st units (taken
/// from du and dv, which assumes st runs like uv, as it does by default).
inline RtPoint3* stManifold(RixShadingContext const* sCtx) {
    RtFloat const *s, *t, *du, *dv;
    sCtx->GetBuiltinVar(RixShadingContext::k_s, &s);
    sCtx->GetBuiltinVar(RixShadingContext::k_t, &t);
    sCtx->GetBuiltinVar(RixShadingContext::k_du, &du);
    sCtx->GetBuiltinVar(RixShadingContext::k_dv, &dv);
    RixShadingContext::Allocator pool(sCtx);
    RtPoint3* q = pool.AllocFor<RtPoint3>(sCtx->numPts);
    for (int i = 0; i < sCtx->numPts; ++i) q[i] = RtPoint3(s[i], t[i], std::max(du[i], dv[i]));
    return q;
}

/// The manifold a texture pattern reads at: its connected one (`manifoldId`),
/// else the surface's own s and t.
inline RtPoint3 const* manifoldOf(RixShadingContext const* sCtx, int manifoldId) {
    RtPoint3 const* manifold = nullptr;
    if (sCtx->EvalParam(manifoldId, -1, &manifold) != k_RixSCVarying) manifold = stManifold(sCtx);
    return manifold;
}

/// Reads 3 channels of `filename` into `rgb` at `n` manifold points (s, t,
/// footprint), footprints widened by `blur`; with invertT, t runs up the image
/// (t = 0 is its bottom row). False when the file cannot be read: then every
/// point has lookup.missingColor.
inline bool readTexture(RixShadingContext const* sCtx, RtUString filename, RixTexture::TxParams const& lookup,
                        RtPoint3 const* manifold, int n, bool invertT, float blur, RtColorRGB* rgb) {
    RixShadingContext::Allocator pool(sCtx);
    RtFloat2* st = pool.AllocFor<RtFloat2>(n);
    RtFloat* width = pool.AllocFor<RtFloat>(n);
    for (int i = 0; i < n; ++i) {
        st[i] = RtFloat2(manifold[i].x, invertT ? 1.0f - manifold[i].y : manifold[i].y);
        width[i] = manifold[i].z + blur;
    }
    auto* textures = static_cast<RixTexture*>(sCtx->GetRixInterface(k_RixTexture));
    if (textures) return textures->Texture(filename, lookup, n, st, width, 3, &rgb[0].r) == 0;
    for (int i = 0; i < n; ++i) rgb[i] = lookup.missingColor;  // a program without textures (a probe)
    return false;
}

}  // namespace stockpatterns

namespace stockpatterns {

/// Outputs the same values (1 or 3 floats per point) as a float (the first),
/// a colour and a point, at the table rows given: what PxrPrimvar and
/// PxrVariable hand on, whatever type the value had.
inline void outputAsEveryType(RixShadingContext const* sCtx, float const* values, int components, int floatRow,
                              int colorRow, int pointRow, RtInt* numOutputs, RixPattern::OutputSpecification** outputs) {
    RixShadingContext::Allocator pool(sCtx);
    RixPattern::OutputSpecification* out = pool.AllocForPattern<RixPattern::OutputSpecification>(3);
    int count = 0;
    RtFloat* f = addVaryingOutput<RtFloat>(sCtx, out, count, floatRow);
    RtColorRGB* rgb = addVaryingOutput<RtColorRGB>(sCtx, out, count, colorRow);
    RtPoint3* p = addVaryingOutput<RtPoint3>(sCtx, out, count, pointRow);
    for (int i = 0; i < sCtx->numPts; ++i) {
        float const* v = values + i * components;
        float y = components == 3 ? v[1] : v[0], z = components == 3 ? v[2] : v[0];
        f[i] = v[0];
        rgb[i] = RtColorRGB(v[0], y, z);
        p[i] = RtPoint3(v[0], y, z);
    }
    *numOutputs = count;
    *outputs = out;
}

}  // namespace stockpatterns
