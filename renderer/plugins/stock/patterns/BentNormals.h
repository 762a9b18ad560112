// What the patterns that bend normals (PxrNormalMap, PxrBump) share.
#pragma once

#include "PatternHelpers.h"

namespace stockpatterns {

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
