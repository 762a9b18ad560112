// What the patterns that bend normals (PxrNormalMap, PxrBump) share.
#pragma once

#include "PatternHelpers.h"

namespace stockpatterns {

/// The six rows that say how a bump pattern reads its image, written in its
/// parameter table in this order (its enum must follow the same order).
#define STOCK_PATTERN_IMAGE_READING_PARAMS                                                                \
    RixSCParamInfo(RtUString("firstChannel"), k_RixSCInteger),                                            \
        RixSCParamInfo(RtUString("atlasStyle"), k_RixSCInteger),                                          \
        RixSCParamInfo(RtUString("invertT"), k_RixSCInteger),                                             \
        RixSCParamInfo(RtUString("blur"), k_RixSCFloat), /* widens the filter, in texture units */        \
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
            messages->Warning("%s: texture atlases (atlasStyle %d) are not read here; \"%s\" is read as one image",
                              pattern, *atlasStyle, filename.CStr());
    ImageReading reading;
    reading.lookup.firstChannel = *firstChannel;
    reading.invertT = *invertT != 0;
    reading.blur = *blur > 0.0f ? *blur : 0.0f;
    return reading;
}

/// A pattern whose one output, resultN, is a bent normal per point. Its
/// ComputeOutputParams starts every point at the surface's own normal and
/// hands the points to bend(), which bends the ones it can.
class BentNormalPattern : public StockPattern {
public:
    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, RixPattern::OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) final {
        RixShadingContext::Allocator pool(sCtx);
        RixPattern::OutputSpecification* out = pool.AllocForPattern<RixPattern::OutputSpecification>(1);
        int count = 0;
        RtNormal3* result = addVaryingOutput<RtNormal3>(sCtx, out, count, resultRow());
        *numOutputs = count;
        *outputs = out;
        RtNormal3 const* Nn;
        sCtx->GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
        for (int i = 0; i < sCtx->numPts; ++i) result[i] = Nn[i];
        bend(sCtx, Nn, result);
        return 0;
    }

protected:
    /// The row of resultN in the parameter table.
    virtual int resultRow() const = 0;
    /// Bends result (the surface's normals Nn on entry) where the pattern's parameters say.
    virtual void bend(RixShadingContext const* sCtx, RtNormal3 const* Nn, RtNormal3* result) = 0;
};

/// A bent normal n of a surface whose own normal is `surface`, turned toward
/// the viewer (V) just enough to face them (n.V = `least` on the side the
/// surface faces) where the surface faces them and n would not: a Bxdf would
/// otherwise shade that point from behind. Left as it is where the surface
/// itself is seen edge-on.
inline RtNormal3 facingViewer(RtNormal3 n, RtNormal3 const& surface, RtVector3 const& V, float least = 0.01f) {
    float const side = surface.Dot(V) >= 0.0f ? 1.0f : -1.0f;
    if (side * surface.Dot(V) <= least) return n;
    float const facing = side * n.Dot(V);
    if (facing >= least) return n;
    n = n + V * (side * (least - facing));
    return Normalize(n);
}

}  // namespace stockpatterns
