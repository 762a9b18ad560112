// PxrBump — bends the shading normal as if the surface were raised by a
// height map: one channel of an image, read at the surface's s and t. The
// bent normal goes to a Bxdf's bumpNormal:
//
//   Pattern "PxrBump" "scratches" "string filename" ["scratches.tx"] "float scale" [0.02]
//   Bxdf "PxrDisney" "table" "reference normal bumpNormal" ["scratches:resultN"]
//
// Raising P by scale h(s, t) along N tilts the normal against the height's
// slope: with the surface gradient of the height
//
//   grad h = h_s grad s + h_t grad t,
//   grad s = (dPdv x N) / J,  grad t = (N x dPdu) / J,  J = N . (dPdu x dPdv),
//
// the bumped normal is normalize(N - scale grad h). The slopes h_s and h_t
// are central differences of the filtered image over the ray's footprint
// (half a footprint either side), so a distant bump map smooths out instead
// of sparkling. Heights are in the units of the world (RenderMan measures
// them in object space: the same where an object is not scaled). As
// PxrNormalMap does, a bent normal is kept facing a viewer the surface faces.
//
// Not done here: inputBump (RenderMan shades the connected network twice
// more, a little along u and along v, to difference it; a warning says it is
// not used), atlases (atlasStyle).
#include <cmath>

#include "BentNormals.h"
#include "RixShadingUtils.h"

namespace {

class PxrBump : public stockpatterns::BentNormalPattern {
public:
    enum {
        k_scale, k_disable, k_inputBump, k_filename, k_firstChannel, k_atlasStyle, k_invertT, k_blur, k_lerp,
        k_filter, k_resultN
    };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("scale"), k_RixSCFloat),
            RixSCParamInfo(RtUString("disable"), k_RixSCInteger),
            RixSCParamInfo(RtUString("inputBump"), k_RixSCFloat),
            RixSCParamInfo(RtUString("filename"), k_RixSCString),
            STOCK_PATTERN_IMAGE_READING_PARAMS,
            RixSCParamInfo(RtUString("resultN"), k_RixSCNormal, k_RixSCOutput),
            RixSCParamInfo()};
        return table;
    }

    int resultRow() const override { return k_resultN; }

    void bend(RixShadingContext const* sCtx, RtNormal3 const* Nn, RtNormal3* result) override {
        int const n = sCtx->numPts;
        RtInt const zero = 0;
        RtFloat const unit = 1.0f;
        RtUString const noFile;
        RtInt const* disable;
        RtFloat const* scale;
        RtUString const* filename;
        sCtx->EvalParam(k_disable, -1, &disable, &zero);
        sCtx->EvalParam(k_filename, -1, &filename, &noFile);
        sCtx->EvalParam(k_scale, -1, &scale, &unit, true);
        if (*disable) return;
        if (filename->Empty()) {
            RtFloat const* inputBump = nullptr;
            if (sCtx->EvalParam(k_inputBump, -1, &inputBump) == k_RixSCVarying)
                if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
                    messages->Warning("PxrBump: a connected inputBump is not differentiated here (only a filename's "
                                      "heights are); the normal is left as it is");
            return;
        }
        stockpatterns::ImageReading reading = stockpatterns::imageReading(sCtx, k_firstChannel, "PxrBump", *filename);
        reading.lookup.missingColor = RtColorRGB(0.0f);  // a map that cannot be read is flat

        // Four lookups per point, half a footprint either side in s and in t.
        RixShadingContext::Allocator pool(sCtx);
        RtPoint3 const* here = stockpatterns::stManifold(sCtx);
        RtPoint3* around = pool.AllocFor<RtPoint3>(4 * n);
        RtFloat* step = pool.AllocFor<RtFloat>(n);
        for (int i = 0; i < n; ++i) {
            step[i] = 0.5f * RixMax(here[i].z, 1e-4f);
            around[4 * i + 0] = RtPoint3(here[i].x + step[i], here[i].y, here[i].z);
            around[4 * i + 1] = RtPoint3(here[i].x - step[i], here[i].y, here[i].z);
            around[4 * i + 2] = RtPoint3(here[i].x, here[i].y + step[i], here[i].z);
            around[4 * i + 3] = RtPoint3(here[i].x, here[i].y - step[i], here[i].z);
        }
        RtColorRGB* heights = pool.AllocFor<RtColorRGB>(4 * n);
        if (!stockpatterns::readTexture(sCtx, *filename, reading.lookup, around, 4 * n, reading.invertT, reading.blur,
                                        heights))
            return;

        RtVector3 const *dPdu, *dPdv, *Vn;
        sCtx->GetBuiltinVar(RixShadingContext::k_dPdu, &dPdu);
        sCtx->GetBuiltinVar(RixShadingContext::k_dPdv, &dPdv);
        sCtx->GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        for (int i = 0; i < n; ++i) {
            RtNormal3 const& N = Nn[i];
            float const J = N.Dot(dPdu[i].Cross(dPdv[i]));
            if (std::fabs(J) < 1e-12f) continue;  // no tangent plane to differentiate in (a pole)
            float const hs = (heights[4 * i].r - heights[4 * i + 1].r) / (2.0f * step[i]);
            float const ht = (heights[4 * i + 2].r - heights[4 * i + 3].r) / (2.0f * step[i]);
            RtVector3 const gradient = (dPdv[i].Cross(N) * hs + N.Cross(dPdu[i]) * ht) / J;
            RtVector3 const bent = N - gradient * scale[i];
            if (bent.LengthSq() < 1e-12f) continue;
            result[i] = stockpatterns::facingViewer(RtNormal3(Normalize(bent)), N, Vn[i]);
        }
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrBump)
