// Small helpers the stock patterns share: allocating an output, and the
// texture coordinates of a shading context with their filter footprint.
#pragma once

#include <algorithm>
#include <cmath>

#include "RixPattern.h"
#include "RixPredefinedStrings.hpp"

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

/// The four rows of a colour result, in this order: resultRGB and its channels resultR, resultG and
/// resultB as floats (for a presence or a mix amount). Write them where the enum has four ids in a row.
#define STOCK_PATTERN_COLOR_OUTPUTS                                          \
    RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput),     \
        RixSCParamInfo(RtUString("resultR"), k_RixSCFloat, k_RixSCOutput),   \
        RixSCParamInfo(RtUString("resultG"), k_RixSCFloat, k_RixSCOutput),   \
        RixSCParamInfo(RtUString("resultB"), k_RixSCFloat, k_RixSCOutput)

/// Those four outputs, added to `out` (which has room), filled point by point with set().
class ColorOutputs {
public:
    ColorOutputs(RixShadingContext const* sCtx, RixPattern::OutputSpecification* out, int& count, int resultRGBRow)
        : m_rgb(addVaryingOutput<RtColorRGB>(sCtx, out, count, resultRGBRow)),
          m_r(addVaryingOutput<RtFloat>(sCtx, out, count, resultRGBRow + 1)),
          m_g(addVaryingOutput<RtFloat>(sCtx, out, count, resultRGBRow + 2)),
          m_b(addVaryingOutput<RtFloat>(sCtx, out, count, resultRGBRow + 3)) {}

    void set(int i, RtColorRGB const& c) {
        m_rgb[i] = c;
        m_r[i] = c.r;
        m_g[i] = c.g;
        m_b[i] = c.b;
    }
    RtColorRGB* rgb() const { return m_rgb; }

private:
    RtColorRGB* m_rgb;
    RtFloat *m_r, *m_g, *m_b;
};

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

/// Whether parameter `paramId` is connected: an input fed by a pattern, or an output a connection reads
/// (so that a costly output can be skipped).
inline bool isConnected(RixShadingContext const* sCtx, int paramId) {
    RixSCConnectionInfo how = k_RixSCDefaultValue;
    sCtx->GetParamInfo(paramId, nullptr, &how);
    return how == k_RixSCNetworkValue;
}
inline bool isOutputRead(RixShadingContext const* sCtx, int paramId) { return isConnected(sCtx, paramId); }

/// Each point's position in object space (its shape's own coordinates, before any transformation),
/// where solid patterns are laid so that they stay on the object as it moves.
inline RtPoint3 const* objectPositions(RixShadingContext const* sCtx) {
    RtPoint3 const* P;
    sCtx->GetBuiltinVar(RixShadingContext::k_P, &P);
    RixShadingContext::Allocator pool(sCtx);
    RtPoint3* object = pool.AllocFor<RtPoint3>(sCtx->numPts);
    for (int i = 0; i < sCtx->numPts; ++i) object[i] = P[i];
    sCtx->Transform(RixShadingContext::k_AsPoints, Rix::k_current, Rix::k_object, object);
    return object;
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
/// (t = 0 is its bottom row). With `alpha`, the fourth channel too (1 where the
/// file has no fourth). False when the file cannot be read: then every point has
/// lookup.missingColor (and `alpha` is left alone).
inline bool readTexture(RixShadingContext const* sCtx, RtUString filename, RixTexture::TxParams const& lookup,
                        RtPoint3 const* manifold, int n, bool invertT, float blur, RtColorRGB* rgb,
                        RtFloat* alpha = nullptr) {
    RixShadingContext::Allocator pool(sCtx);
    RtFloat2* st = pool.AllocFor<RtFloat2>(n);
    RtFloat* width = pool.AllocFor<RtFloat>(n);
    for (int i = 0; i < n; ++i) {
        st[i] = RtFloat2(manifold[i].x, invertT ? 1.0f - manifold[i].y : manifold[i].y);
        width[i] = manifold[i].z + blur;
    }
    auto* textures = static_cast<RixTexture*>(sCtx->GetRixInterface(k_RixTexture));
    if (!textures) {
        for (int i = 0; i < n; ++i) rgb[i] = lookup.missingColor;  // a program without textures (a probe)
        return false;
    }
    if (!alpha) return textures->Texture(filename, lookup, n, st, width, 3, &rgb[0].r) == 0;
    RtFloat* rgba = pool.AllocFor<RtFloat>(4 * static_cast<size_t>(n));
    bool const found = textures->Texture(filename, lookup, n, st, width, 4, rgba) == 0;
    for (int i = 0; i < n; ++i) {
        rgb[i] = RtColorRGB(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
        if (found) alpha[i] = rgba[4 * i + 3];
    }
    return found;
}

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

/// The six rows that say how an image pattern (PxrTexture, PxrNormalMap, PxrBump) reads
/// its image, written in its parameter table in this order (its enum must follow the same order).
#define STOCK_PATTERN_IMAGE_READING_PARAMS                                                                 \
    RixSCParamInfo(RtUString("firstChannel"), k_RixSCInteger),                                             \
        RixSCParamInfo(RtUString("atlasStyle"), k_RixSCInteger),                                           \
        RixSCParamInfo(RtUString("invertT"), k_RixSCInteger),                                              \
        RixSCParamInfo(RtUString("blur"), k_RixSCFloat),   /* widens the filter, in texture units */       \
        RixSCParamInfo(RtUString("lerp"), k_RixSCInteger), /* lerp, filter: the texture system's choice */ \
        RixSCParamInfo(RtUString("filter"), k_RixSCInteger)

/// How to read the image, from those rows (the first at `firstRow`).
struct ImageReading {
    RixTexture::TxParams lookup;
    bool invertT;
    float blur;
};

/// The rows' values, with one warning where an atlas (a UDIM set) is asked
/// for: `filename` is then read as one image.
inline ImageReading imageReading(RixShadingContext const* sCtx, int firstRow, char const* pattern,
                                 RtUString filename) {
    RtInt const zero = 0, one = 1;
    RtFloat const sharp = 0.0f;
    RtInt const *firstChannel, *atlasStyle, *invertT;
    RtFloat const* blur;
    sCtx->EvalParam(firstRow, -1, &firstChannel, &zero);
    sCtx->EvalParam(firstRow + 1, -1, &atlasStyle, &zero);
    sCtx->EvalParam(firstRow + 2, -1, &invertT, &one);
    sCtx->EvalParam(firstRow + 3, -1, &blur, &sharp);
    if (*atlasStyle != 0)
        if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
            messages->Warning(
                "%s: texture atlases (atlasStyle %d) are not read here; \"%s\" is read as one image", pattern,
                *atlasStyle, filename.CStr());
    ImageReading reading;
    reading.lookup.firstChannel = *firstChannel;
    reading.invertT = *invertT != 0;
    reading.blur = *blur > 0.0f ? *blur : 0.0f;
    return reading;
}

}  // namespace stockpatterns
