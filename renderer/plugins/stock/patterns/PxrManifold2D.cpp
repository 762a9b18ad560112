// PxrManifold2D — places a 2-D texture on a surface: it turns the surface's
// texture coordinates (s, t) into the coordinates a PxrTexture reads, by a
// flip of either axis (invertS, invertT), a rotation, a scale and an offset:
//
//   (s', t') = scale * rotate(angle) * (s, t) + offset
//
// Connect its "result" to a texture's "manifold":
//   Pattern "PxrManifold2D" "place" "float scaleS" [4] "float scaleT" [4]
//   Pattern "PxrTexture" "tex" "string filename" ["maple.tx"] "reference struct manifold" ["place:result"]
//
// primvarS and primvarT name float primvars to read in place of s and t (a
// second set of texture coordinates, say); a name the surface does not carry
// leaves s or t as it is.
//
// RenderMan's manifold is a struct (a point Q and its filter radius); here it
// travels as one point: (s', t', filter width in s't' units).
#include <cmath>

#include "PatternHelpers.h"

namespace {

class PxrManifold2D : public stockpatterns::StockPattern {
public:
    enum {
        k_angle, k_scaleS, k_scaleT, k_offsetS, k_offsetT, k_invertS, k_invertT, k_primvarS, k_primvarT,
        k_result
    };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("angle"), k_RixSCFloat),   // degrees, counter-clockwise
            RixSCParamInfo(RtUString("scaleS"), k_RixSCFloat),  // repeats across s
            RixSCParamInfo(RtUString("scaleT"), k_RixSCFloat),
            RixSCParamInfo(RtUString("offsetS"), k_RixSCFloat),
            RixSCParamInfo(RtUString("offsetT"), k_RixSCFloat),
            RixSCParamInfo(RtUString("invertS"), k_RixSCInteger),  // 1: use 1 - s
            RixSCParamInfo(RtUString("invertT"), k_RixSCInteger),  // 1: use 1 - t
            RixSCParamInfo(RtUString("primvarS"), k_RixSCString),  // "": the surface's s
            RixSCParamInfo(RtUString("primvarT"), k_RixSCString),
            RixSCParamInfo(RtUString("result"), k_RixSCPoint, k_RixSCOutput),
            RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtFloat const zero = 0.0f, one = 1.0f;
        RtInt const noInvert = 0;
        RtFloat const *angle, *scaleS, *scaleT, *offsetS, *offsetT;
        RtInt const *invertS, *invertT;
        sCtx->EvalParam(k_angle, -1, &angle, &zero, true);
        sCtx->EvalParam(k_scaleS, -1, &scaleS, &one, true);
        sCtx->EvalParam(k_scaleT, -1, &scaleT, &one, true);
        sCtx->EvalParam(k_offsetS, -1, &offsetS, &zero, true);
        sCtx->EvalParam(k_offsetT, -1, &offsetT, &zero, true);
        sCtx->EvalParam(k_invertS, -1, &invertS, &noInvert, true);
        sCtx->EvalParam(k_invertT, -1, &invertT, &noInvert, true);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(1);
        int count = 0;
        RtPoint3* result = stockpatterns::addVaryingOutput<RtPoint3>(sCtx, out, count, k_result);
        RtPoint3* st = stockpatterns::stManifold(sCtx);
        readCoordinate(sCtx, k_primvarS, st, &RtPoint3::x);
        readCoordinate(sCtx, k_primvarT, st, &RtPoint3::y);
        for (int i = 0; i < sCtx->numPts; ++i) {
            float s = invertS[i] ? 1.0f - st[i].x : st[i].x;
            float t = invertT[i] ? 1.0f - st[i].y : st[i].y;
            float radians = angle[i] * 3.14159265f / 180.0f;
            float c = std::cos(radians), n = std::sin(radians);
            float rs = c * s - n * t, rt = n * s + c * t;
            // The footprint grows with the larger scale (an upper bound that never under-filters).
            float width = st[i].z * std::max(std::fabs(scaleS[i]), std::fabs(scaleT[i]));
            result[i] = RtPoint3(scaleS[i] * rs + offsetS[i], scaleT[i] * rt + offsetT[i], width);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }

private:
    /// Replaces one coordinate of `st` by the float primvar the string parameter `id` names, if the surface
    /// has it.
    static void readCoordinate(RixShadingContext const* sCtx, int id, RtPoint3* st,
                               float RtPoint3::*coordinate) {
        RtUString const noName;
        RtUString const* name;
        sCtx->EvalParam(id, -1, &name, &noName);
        if (name->Empty()) return;
        RtFloat const* values;
        if (sCtx->GetPrimVar(*name, &values) == k_RixSCInvalidDetail) return;
        for (int i = 0; i < sCtx->numPts; ++i) st[i].*coordinate = values[i];
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrManifold2D)
