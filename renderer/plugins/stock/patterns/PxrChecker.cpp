// PxrChecker — a checkerboard of two colours. In two dimensions (the default)
// the squares are half a unit of the texture coordinates (s, t) wide, or of a
// connected manifold's, so that s and t from 0 to 1 hold a board of 2 x 2 with
// colorA in the square at (0, 0); a PxrManifold2D's scaleS and scaleT make it
// finer:
//   Pattern "PxrManifold2D" "eight" "float scaleS" [4] "float scaleT" [4]
//   Pattern "PxrChecker" "board" "reference struct manifold" ["eight:result"]
//       "color colorA" [0.9 0.9 0.9] "color colorB" [0.1 0.1 0.1]
// With "int dimensions" [3] the board is a block of cubes half a unit wide in
// the object's own space (its coordinates before any transformation), so a
// cut through the object shows them too.
#include <cmath>

#include "PatternHelpers.h"

namespace {

class PxrChecker : public stockpatterns::StockPattern {
public:
    enum { k_colorA, k_colorB, k_dimensions, k_manifold, k_resultRGB, k_resultR, k_resultG, k_resultB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("colorA"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("colorB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("dimensions"), k_RixSCInteger),  // 2 or 3
                                         RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const white(1.0f), black(0.0f);
        RtInt const two = 2;
        RtColorRGB const *colorA, *colorB;
        RtInt const* dimensions;
        sCtx->EvalParam(k_colorA, -1, &colorA, &white, true);
        sCtx->EvalParam(k_colorB, -1, &colorB, &black, true);
        sCtx->EvalParam(k_dimensions, -1, &dimensions, &two);
        bool const solid = *dimensions == 3;
        RtPoint3 const* where =
            solid ? stockpatterns::objectPositions(sCtx) : stockpatterns::manifoldOf(sCtx, k_manifold);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            // Which half-unit cell the point is in, along each axis; the parity of their sum picks the colour.
            long long cells = static_cast<long long>(std::floor(2.0f * where[i].x)) +
                              static_cast<long long>(std::floor(2.0f * where[i].y));
            if (solid) cells += static_cast<long long>(std::floor(2.0f * where[i].z));
            result.set(i, (cells & 1) == 0 ? colorA[i] : colorB[i]);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrChecker)
