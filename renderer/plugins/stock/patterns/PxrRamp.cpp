// PxrRamp — a colour gradient across a surface. A position x along the ramp
// comes from the texture coordinates (s, t), or from a connected manifold, by
// the ramp's shape (rampType):
//   0  S ramp         x = s
//   1  T ramp         x = t
//   2  diagonal       x = (s + t) / 2
//   3  radial         x = the angle of (s, t) around (0.5, 0.5), a full turn per ramp
//   4  circular       x = twice the distance of (s, t) from (0.5, 0.5)
//   5  box            x = twice the larger of |s - 0.5| and |t - 0.5|
// A connected splineMap (a noise, say) gives x instead. tile repeats the ramp
// outside [0, 1] (it is clamped otherwise) and reverse runs it from 1 to 0.
//
// The colour at x is interpolated between the knots, as RenderMan 22 and later
// write them:
//   Pattern "PxrRamp" "band" "int rampType" [1] "int colorRamp" [3]
//       "float[3] colorRamp_Knots" [0 0.5 1] "color[3] colorRamp_Colors" [1 0 0  0 1 0  0 0 1]
//       "string colorRamp_Interpolation" ["linear"]
// Interpolations: "linear", "catmull-rom" (the default: a smooth curve through
// every knot), "bspline" (smoother, near the knots rather than through them)
// and "constant" ("none" in RenderMan 21: each knot's colour up to the next).
// Before the first knot the ramp has the first colour, after the last the last.
// RenderMan 20 and 21's form, "float positions" and "color colors" with an
// "int basis" (3 linear, 4 Catmull-Rom, 1 B-spline) and an unused first and
// last point, is read where useNewRamp is 0 or only it is written.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "PatternHelpers.h"

namespace {

enum class Interpolation { Constant, Linear, CatmullRom, BSpline };

/// The knots of a ramp, sorted by position.
struct Ramp {
    std::vector<float> knots;
    std::vector<RtColorRGB> colors;
    Interpolation interpolation = Interpolation::CatmullRom;

    /// The colour at x.
    RtColorRGB at(float x) const {
        size_t const n = knots.size();
        if (n == 0) return RtColorRGB(0.0f);
        if (x <= knots.front() || n == 1) return colors.front();
        if (x >= knots.back()) return colors.back();
        // The segment [knots[i], knots[i + 1]) holding x; knots at one position make no segment.
        size_t i = static_cast<size_t>(std::upper_bound(knots.begin(), knots.end(), x) - knots.begin()) - 1;
        float const u = (x - knots[i]) / (knots[i + 1] - knots[i]);
        RtColorRGB const& p1 = colors[i];
        RtColorRGB const& p2 = colors[i + 1];
        RtColorRGB const& p0 = i > 0 ? colors[i - 1] : p1;          // the ends repeat their colour
        RtColorRGB const& p3 = i + 2 < n ? colors[i + 2] : p2;
        RtColorRGB c;
        switch (interpolation) {
            case Interpolation::Constant: return p1;
            case Interpolation::Linear: return p1 * (1.0f - u) + p2 * u;
            case Interpolation::CatmullRom: {
                float const u2 = u * u, u3 = u2 * u;
                c = (p1 * 2.0f + (p2 - p0) * u + (p0 * 2.0f - p1 * 5.0f + p2 * 4.0f - p3) * u2 +
                     (p1 * 3.0f - p0 - p2 * 3.0f + p3) * u3) *
                    0.5f;
                break;
            }
            case Interpolation::BSpline: {
                float const v = 1.0f - u, u2 = u * u, u3 = u2 * u;
                c = (p0 * (v * v * v) + p1 * (3.0f * u3 - 6.0f * u2 + 4.0f) +
                     p2 * (-3.0f * u3 + 3.0f * u2 + 3.0f * u + 1.0f) + p3 * u3) *
                    (1.0f / 6.0f);
                break;
            }
        }
        // A curve may overshoot its knots; a colour below black is no colour.
        return RtColorRGB(std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f));
    }
};

class PxrRamp : public stockpatterns::StockPattern {
public:
    enum {
        k_rampType, k_tile, k_useNewRamp, k_reverse, k_splineMap, k_manifold,
        k_colorRamp, k_colorRamp_Knots, k_colorRamp_Colors, k_colorRamp_Interpolation,
        k_positions, k_colors, k_basis,
        k_resultRGB, k_resultR, k_resultG, k_resultB
    };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("rampType"), k_RixSCInteger),
            RixSCParamInfo(RtUString("tile"), k_RixSCInteger),
            RixSCParamInfo(RtUString("useNewRamp"), k_RixSCInteger),
            RixSCParamInfo(RtUString("reverse"), k_RixSCInteger),
            RixSCParamInfo(RtUString("splineMap"), k_RixSCFloat),
            RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),  // (s, t, filter width): see PxrManifold2D
            RixSCParamInfo(RtUString("colorRamp"), k_RixSCInteger),  // how many knots
            RixSCParamInfo(RtUString("colorRamp_Knots"), k_RixSCFloat, k_RixSCInput, 0),
            RixSCParamInfo(RtUString("colorRamp_Colors"), k_RixSCColor, k_RixSCInput, 0),
            RixSCParamInfo(RtUString("colorRamp_Interpolation"), k_RixSCString),
            RixSCParamInfo(RtUString("positions"), k_RixSCFloat, k_RixSCInput, 0),
            RixSCParamInfo(RtUString("colors"), k_RixSCColor, k_RixSCInput, 0),
            RixSCParamInfo(RtUString("basis"), k_RixSCInteger),
            STOCK_PATTERN_COLOR_OUTPUTS,
            RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtInt const zero = 0;
        RtInt const *rampType, *tile, *reverse;
        sCtx->EvalParam(k_rampType, -1, &rampType, &zero);
        sCtx->EvalParam(k_tile, -1, &tile, &zero);
        sCtx->EvalParam(k_reverse, -1, &reverse, &zero);
        RtFloat const* splineMap = nullptr;
        bool const mapped = sCtx->EvalParam(k_splineMap, -1, &splineMap) == k_RixSCVarying;
        if (*rampType < 0 || *rampType > 5)
            warn(sCtx, "rampType " + std::to_string(*rampType) +
                           " is not one of the shapes this renderer has (0-5); an S ramp is used");
        Ramp const ramp = readRamp(sCtx);
        RtPoint3 const* manifold = stockpatterns::manifoldOf(sCtx, k_manifold);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            float x = mapped ? splineMap[i] : position(*rampType, manifold[i].x, manifold[i].y);
            x = *tile ? x - std::floor(x) : std::clamp(x, 0.0f, 1.0f);
            if (*reverse) x = 1.0f - x;
            result.set(i, ramp.at(x));
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }

private:
    /// Where (s, t) lies along a ramp of the given shape.
    static float position(int rampType, float s, float t) {
        float const ds = s - 0.5f, dt = t - 0.5f;
        switch (rampType) {
            case 1: return t;
            case 2: return 0.5f * (s + t);
            case 3: {
                float const turn = std::atan2(dt, ds) / (2.0f * 3.14159265f);
                return turn < 0.0f ? turn + 1.0f : turn;
            }
            case 4: return 2.0f * std::sqrt(ds * ds + dt * dt);
            case 5: return 2.0f * std::max(std::fabs(ds), std::fabs(dt));
            default: return s;
        }
    }

    /// One warning per distinct message (the renderer counts repeats).
    static void warn(RixShadingContext const* sCtx, std::string const& message) {
        if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
            messages->Warning("PxrRamp: %s", message.c_str());
    }

    static int lengthOf(RixShadingContext const* sCtx, int id) {
        RixSCConnectionInfo given = k_RixSCDefaultValue;
        int length = -1;
        sCtx->GetParamInfo(id, nullptr, &given, &length);
        return given == k_RixSCDefaultValue ? 0 : std::max(length, 0);
    }

    /// The ramp's knots as written, in the form the RIB uses.
    static Ramp readRamp(RixShadingContext const* sCtx) {
        RtInt const newRampByDefault = 1;
        RtInt const* useNewRamp;
        sCtx->EvalParam(k_useNewRamp, -1, &useNewRamp, &newRampByDefault);
        bool const oldForm = *useNewRamp == 0 ||
                             (lengthOf(sCtx, k_colorRamp_Knots) == 0 && lengthOf(sCtx, k_positions) > 0);
        Ramp ramp;
        int const knotsId = oldForm ? k_positions : k_colorRamp_Knots;
        int const colorsId = oldForm ? k_colors : k_colorRamp_Colors;
        int n = std::min(lengthOf(sCtx, knotsId), lengthOf(sCtx, colorsId));
        if (!oldForm) {
            RtInt const* count = nullptr;
            if (sCtx->EvalParam(k_colorRamp, -1, &count) != k_RixSCInvalidDetail && count && *count >= 0)
                n = std::min(n, *count);
        }
        std::vector<std::pair<float, RtColorRGB>> points;
        for (int k = 0; k < n; ++k) {
            RtFloat const* knot;
            RtColorRGB const* color;
            sCtx->EvalParam(knotsId, k, &knot);
            sCtx->EvalParam(colorsId, k, &color);
            if (knot && color) points.emplace_back(*knot, *color);
        }
        if (oldForm) {
            RtInt const catmullRom = 4;
            RtInt const* basis;
            sCtx->EvalParam(k_basis, -1, &basis, &catmullRom);
            ramp.interpolation = *basis == 3 ? Interpolation::Linear
                                 : *basis == 1 ? Interpolation::BSpline
                                               : Interpolation::CatmullRom;
            if (*basis == 0 || *basis == 2)
                warn(sCtx, "basis " + std::to_string(*basis) + " (Bezier or Hermite) is read as Catmull-Rom");
            // The first and last points only shape the curve's ends: the ramp runs between the others.
            if (points.size() >= 4) {
                points.pop_back();
                points.erase(points.begin());
            }
        } else {
            RtUString const catmullRom("catmull-rom");
            RtUString const* name;
            sCtx->EvalParam(k_colorRamp_Interpolation, -1, &name, &catmullRom);
            std::string const interpolation = name->CStr();
            ramp.interpolation = interpolation == "linear"                              ? Interpolation::Linear
                                 : interpolation == "constant" || interpolation == "none" ? Interpolation::Constant
                                 : interpolation == "bspline"                             ? Interpolation::BSpline
                                                                                          : Interpolation::CatmullRom;
            if (ramp.interpolation == Interpolation::CatmullRom && interpolation != "catmull-rom")
                warn(sCtx, "colorRamp_Interpolation \"" + interpolation + "\" is read as \"catmull-rom\"");
        }
        std::stable_sort(points.begin(), points.end(),
                         [](auto const& a, auto const& b) { return a.first < b.first; });
        for (auto const& [knot, color] : points) {
            ramp.knots.push_back(knot);
            ramp.colors.push_back(color);
        }
        return ramp;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrRamp)
