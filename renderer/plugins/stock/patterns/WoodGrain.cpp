// WoodGrain — a procedural pattern for the finished-wood Bxdf: growth rings,
// curly figure and fiber direction (the model is in WoodGrainModel.h).
//
//   Pattern "WoodGrain" "maple" "float ringsPerUnit" [14]
//   Bxdf "finishedwood" "board"
//       "reference color diffuseColor" ["maple:resultRGB"]
//       "reference color fiberColor" ["maple:resultFiberColor"]
//       "reference vector fiberAxis" ["maple:resultFiberAxis"]
//       "reference float beta" ["maple:resultBeta"]
//
// Its coordinates are the surface's s and t, or a connected manifold
// (PxrManifold2D) to scale or turn the board.
#include "PatternHelpers.h"
#include "WoodGrainModel.h"

namespace {

class WoodGrain : public stockpatterns::StockPattern {
public:
    enum {
        k_ringsPerUnit, k_figureStrength, k_figureFrequency, k_grainAngle, k_earlyColor, k_lateColor, k_manifold,
        k_resultRGB, k_resultFiberColor, k_resultFiberAxis, k_resultBeta
    };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("ringsPerUnit"), k_RixSCFloat),
            RixSCParamInfo(RtUString("figureStrength"), k_RixSCFloat),
            RixSCParamInfo(RtUString("figureFrequency"), k_RixSCFloat),
            RixSCParamInfo(RtUString("grainAngle"), k_RixSCFloat),  // degrees
            RixSCParamInfo(RtUString("earlyColor"), k_RixSCColor),
            RixSCParamInfo(RtUString("lateColor"), k_RixSCColor),
            RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),
            RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput),
            RixSCParamInfo(RtUString("resultFiberColor"), k_RixSCColor, k_RixSCOutput),
            RixSCParamInfo(RtUString("resultFiberAxis"), k_RixSCVector, k_RixSCOutput),
            RixSCParamInfo(RtUString("resultBeta"), k_RixSCFloat, k_RixSCOutput),
            RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        // The model's parameters are uniform: one value each for the batch,
        // the model's own defaults where the RIB gives none.
        woodgrain::Params model;
        RtFloat const* value;
        sCtx->EvalParam(k_ringsPerUnit, -1, &value, &model.ringsPerUnit);
        model.ringsPerUnit = *value;
        sCtx->EvalParam(k_figureStrength, -1, &value, &model.figureStrength);
        model.figureStrength = *value;
        sCtx->EvalParam(k_figureFrequency, -1, &value, &model.figureFrequency);
        model.figureFrequency = *value;
        RtFloat const straight = 0.0f;
        sCtx->EvalParam(k_grainAngle, -1, &value, &straight);
        model.grainAngle = *value * 3.14159265f / 180.0f;
        RtColorRGB const early(model.earlyColor[0], model.earlyColor[1], model.earlyColor[2]);
        RtColorRGB const late(model.lateColor[0], model.lateColor[1], model.lateColor[2]);
        RtColorRGB const* color;
        sCtx->EvalParam(k_earlyColor, -1, &color, &early);
        for (int c = 0; c < 3; ++c) model.earlyColor[c] = (*color)[c];
        sCtx->EvalParam(k_lateColor, -1, &color, &late);
        for (int c = 0; c < 3; ++c) model.lateColor[c] = (*color)[c];

        RtPoint3 const* manifold = nullptr;
        if (sCtx->EvalParam(k_manifold, -1, &manifold) != k_RixSCVarying) manifold = stockpatterns::stManifold(sCtx);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        RtColorRGB* diffuse = stockpatterns::addVaryingOutput<RtColorRGB>(sCtx, out, count, k_resultRGB);
        RtColorRGB* fiberColor = stockpatterns::addVaryingOutput<RtColorRGB>(sCtx, out, count, k_resultFiberColor);
        RtVector3* fiberAxis = stockpatterns::addVaryingOutput<RtVector3>(sCtx, out, count, k_resultFiberAxis);
        RtFloat* beta = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultBeta);
        for (int i = 0; i < sCtx->numPts; ++i) {
            woodgrain::Sample w = woodgrain::evaluate(model, manifold[i].x, manifold[i].y);
            diffuse[i] = RtColorRGB(w.diffuse[0], w.diffuse[1], w.diffuse[2]);
            fiberColor[i] = RtColorRGB(w.fiberColor[0], w.fiberColor[1], w.fiberColor[2]);
            fiberAxis[i] = RtVector3(w.fiberAxis[0], w.fiberAxis[1], w.fiberAxis[2]);
            beta[i] = w.beta;
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

RIX_PATTERNCREATE {
    PIXAR_ARGUSED(hint);
    return new WoodGrain();
}
RIX_PATTERNDESTROY { delete static_cast<WoodGrain*>(pattern); }
