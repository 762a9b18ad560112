// A test pattern in the shape of RenderMan's manifold patterns: a struct
// output "result" (a point Q and its radius Qradius, declared between
// k_RixSCStructBegin and k_RixSCStructEnd rows), a struct input "manifold" of
// the same kind, and two float outputs it computes only when GetParamInfo says
// something reads them (the others are handed back as k_RixSCInvalidDetail).
//
//   Q = (s, t, 0) * scale, or the connected manifold's Q * scale, or, given
//       "string space", Po moved to that coordinate system (Transform) * scale,
//       as a point, or as a vector or a normal with "int transformAs" 1 or 2
//   resultS = Q.x, resultT = Q.y
#include "RixPattern.h"
#include "RixPredefinedStrings.hpp"

namespace {

enum {
    kResultS = 0,
    kResultT,
    kResultBegin,
    kResultQ,
    kResultQradius,
    kResultEnd,
    kScale,
    kManifoldBegin,
    kManifoldQ,
    kManifoldQradius,
    kManifoldEnd,
    kSpace,
    kTransformAs,
};

class ManifoldPattern : public RixPattern {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    RixSCParamInfo const* GetParamTable() override {
        RtUString const manifold("Manifold"), result("result"), input("manifold");
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("resultS"), k_RixSCFloat, k_RixSCOutput),
            RixSCParamInfo(RtUString("resultT"), k_RixSCFloat, k_RixSCOutput),
            RixSCParamInfo(manifold, result, k_RixSCStructBegin, k_RixSCOutput),
            RixSCParamInfo(RtUString("Q"), k_RixSCPoint, k_RixSCOutput),
            RixSCParamInfo(RtUString("Qradius"), k_RixSCFloat, k_RixSCOutput),
            RixSCParamInfo(manifold, result, k_RixSCStructEnd, k_RixSCOutput),
            RixSCParamInfo(RtUString("scale"), k_RixSCFloat),
            RixSCParamInfo(manifold, input, k_RixSCStructBegin),
            RixSCParamInfo(RtUString("Q"), k_RixSCPoint),
            RixSCParamInfo(RtUString("Qradius"), k_RixSCFloat),
            RixSCParamInfo(manifold, input, k_RixSCStructEnd),
            RixSCParamInfo(RtUString("space"), k_RixSCString),
            RixSCParamInfo(RtUString("transformAs"), k_RixSCInteger),
            RixSCParamInfo()};
        return table;
    }
    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpec** outputs, RtPointer,
                            RixSCParamInfo const*) override {
        int const n = sCtx->numPts;
        RtFloat const one = 1.0f;
        RtFloat const* scale;
        sCtx->EvalParam(kScale, -1, &scale, &one, true);

        RixShadingContext::Allocator pool(sCtx);
        RtPoint3* Q = pool.AllocForPattern<RtPoint3>(n);
        RtFloat* Qradius = pool.AllocForPattern<RtFloat>(n);
        RixSCType type;
        RixSCConnectionInfo cinfo;
        RtUString const* space;
        sCtx->EvalParam(kSpace, -1, &space, &Rix::k_empty);
        sCtx->GetParamInfo(kManifoldQ, &type, &cinfo);
        if (*space) {
            RtPoint3 const* Po;
            RtFloat const* footprint;
            sCtx->GetBuiltinVar(RixShadingContext::k_Po, &Po);
            sCtx->GetBuiltinVar(RixShadingContext::k_PRadius, &footprint);
            for (int i = 0; i < n; ++i) {
                Q[i] = Po[i];
                Qradius[i] = footprint[i];
            }
            RtInt const asPoints = RixShadingContext::k_AsPoints;
            RtInt const* transformAs;
            sCtx->EvalParam(kTransformAs, -1, &transformAs, &asPoints);
            auto const interpretation = static_cast<RixShadingContext::TransformInterpretation>(*transformAs);
            sCtx->Transform(interpretation, Rix::k_current, *space, Q, Qradius);  // 1: left as is
        } else if (cinfo == k_RixSCNetworkValue) {
            RtPoint3 const* given;
            RtFloat const* givenRadius;
            RtPoint3 const origin(0.0f, 0.0f, 0.0f);
            RtFloat const none = 0.0f;
            sCtx->EvalParam(kManifoldQ, -1, &given, &origin, true);
            sCtx->EvalParam(kManifoldQradius, -1, &givenRadius, &none, true);
            for (int i = 0; i < n; ++i) {
                Q[i] = given[i];
                Qradius[i] = givenRadius[i];
            }
        } else {
            RtFloat2 const* st;
            RtFloat const* radius;
            sCtx->GetPrimVar(Rix::k_st, RtFloat2(0.0f, 0.0f), &st, &radius);
            for (int i = 0; i < n; ++i) {
                Q[i] = RtPoint3(st[i].x, st[i].y, 0.0f);
                Qradius[i] = radius[i];
            }
        }
        for (int i = 0; i < n; ++i) {
            Q[i] = Q[i] * scale[i];
            Qradius[i] *= scale[i];
        }

        OutputSpec* out = pool.AllocForPattern<OutputSpec>(4);
        out[0] = {kResultQ, k_RixSCVarying, Q};
        out[1] = {kResultQradius, k_RixSCVarying, Qradius};
        for (int k = 0; k < 2; ++k) {  // resultS and resultT, only where they are read
            int const id = k == 0 ? kResultS : kResultT;
            sCtx->GetParamInfo(id, &type, &cinfo);
            RtFloat* values = nullptr;
            if (cinfo == k_RixSCNetworkValue) {
                values = pool.AllocForPattern<RtFloat>(n);
                for (int i = 0; i < n; ++i) values[i] = k == 0 ? Q[i].x : Q[i].y;
            }
            out[2 + k] = {id, values ? k_RixSCVarying : k_RixSCInvalidDetail, values};
        }
        *numOutputs = 4;
        *outputs = out;
        return 0;
    }
};

}  // namespace

RIX_PATTERNCREATE {
    PIXAR_ARGUSED(hint);
    return new ManifoldPattern();
}
RIX_PATTERNDESTROY { delete static_cast<ManifoldPattern*>(pattern); }
