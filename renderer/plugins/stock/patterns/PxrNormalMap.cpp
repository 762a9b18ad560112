// PxrNormalMap — bends the shading normal by a tangent-space normal map: a
// colour per point whose red, green and blue encode a unit normal's x, y and
// z as (c + 1) / 2. The colour comes from an image (filename) or from a
// connected pattern (inputRGB); the bent normal goes to a Bxdf's bumpNormal:
//
//   Pattern "PxrNormalMap" "bumps" "string filename" ["oak_normal.tx"]
//   Bxdf "PxrDisney" "desk" "reference normal bumpNormal" ["bumps:resultN"]
//
// Tangent space: z is the surface's normal (its outside, or the normal of a
// connected bumpOverlay, so that maps stack), x runs along dP/ds and y along
// dP/dt, taken here as dPdu and dPdv (s and t are u and v on quadrics and
// patches, and a mesh's st primvar is its uv), each made orthogonal to z.
// y points up the image as the texture shows it, so with invertT off
// (t down the image) it runs along -dP/dt.
//
//   n = normalize(bumpScale (x T + y B) + z N)   (x, y, z) = 2 c - 1
//
// Conventions differ between painting tools; orientation chooses one:
// 0 OpenGL (red along +T, green along +B), 1 DirectX (green along -B), or 2,
// the default, RenderMan's own frame with the flips flipX and flipY: there
// red runs along -T, so that (as RenderMan documents it) an OpenGL map needs
// invertBump and flipY, a DirectX map invertBump. invertBump turns bumps
// into dents (x and y negated).
// surfaceNormalMix blends the result back toward the surface's normal,
// disable returns the surface's normal, reverse negates the result. Where
// the surface faces the viewer and the bent normal would not, it is turned
// toward the viewer just enough to face it (adjustAmount 0 leaves it):
// otherwise a Bxdf would shade that point from behind.
//
// Not done here: UDIM or other atlases (atlasStyle; a warning), and the
// manifold's rotation or scale does not turn the tangent frame.
#include <cmath>

#include "BentNormals.h"
#include "RixShadingUtils.h"

namespace {

enum Orientation { k_openGL = 0, k_directX = 1, k_manual = 2 };

/// T and B made orthonormal to N, T along dPdu and B on dPdv's side (any
/// frame around N where the surface has no usable tangents).
void tangentFrame(RtNormal3 const& N, RtVector3 const& dPdu, RtVector3 const& dPdv, RtVector3& T, RtVector3& B) {
    RixComputeShadingBasis(N, dPdu, T, B);
    RtVector3 along = dPdv - N * N.Dot(dPdv) - T * T.Dot(dPdv);
    float const lenSq = along.LengthSq();
    if (lenSq > 1e-12f && lenSq > 1e-8f * dPdv.LengthSq()) B = along / std::sqrt(lenSq);
}

class PxrNormalMap : public stockpatterns::BentNormalPattern {
public:
    enum {
        k_bumpScale, k_inputRGB, k_filename, k_bumpOverlay, k_invertBump, k_orientation, k_flipX, k_flipY,
        k_firstChannel, k_atlasStyle, k_invertT, k_blur, k_lerp, k_filter, k_manifold, k_reverse, k_adjustAmount,
        k_surfaceNormalMix, k_disable, k_resultN
    };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("bumpScale"), k_RixSCFloat),
            RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),  // used when there is no filename
            RixSCParamInfo(RtUString("filename"), k_RixSCString),
            RixSCParamInfo(RtUString("bumpOverlay"), k_RixSCNormal),  // another bump pattern's resultN
            RixSCParamInfo(RtUString("invertBump"), k_RixSCInteger),
            RixSCParamInfo(RtUString("orientation"), k_RixSCInteger),
            RixSCParamInfo(RtUString("flipX"), k_RixSCInteger),
            RixSCParamInfo(RtUString("flipY"), k_RixSCInteger),
            STOCK_PATTERN_IMAGE_READING_PARAMS,
            RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),
            RixSCParamInfo(RtUString("reverse"), k_RixSCInteger),
            RixSCParamInfo(RtUString("adjustAmount"), k_RixSCFloat),
            RixSCParamInfo(RtUString("surfaceNormalMix"), k_RixSCFloat),
            RixSCParamInfo(RtUString("disable"), k_RixSCInteger),
            RixSCParamInfo(RtUString("resultN"), k_RixSCNormal, k_RixSCOutput),
            RixSCParamInfo()};
        return table;
    }

    int resultRow() const override { return k_resultN; }

    void bend(RixShadingContext const* sCtx, RtNormal3 const* Nn, RtNormal3* result) override {
        int const n = sCtx->numPts;
        RtNormal3 const* base = Nn;
        RtNormal3 const* overlay = nullptr;
        if (sCtx->EvalParam(k_bumpOverlay, -1, &overlay) == k_RixSCVarying) base = overlay;
        RtInt const zero = 0, one = 1, custom = k_manual;
        RtInt const* disable;
        sCtx->EvalParam(k_disable, -1, &disable, &zero);
        if (*disable) {
            for (int i = 0; i < n; ++i) result[i] = base[i];
            return;
        }

        RtColorRGB const* colors = encodedNormals(sCtx);
        RtFloat const fullScale = 1.0f, none = 0.0f, adjust = 1.0f;
        RtFloat const *bumpScale, *adjustAmount, *surfaceNormalMix;
        RtInt const *invertBump, *orientation, *flipX, *flipY, *invertT, *reverse;
        sCtx->EvalParam(k_bumpScale, -1, &bumpScale, &fullScale, true);
        sCtx->EvalParam(k_surfaceNormalMix, -1, &surfaceNormalMix, &none, true);
        sCtx->EvalParam(k_adjustAmount, -1, &adjustAmount, &adjust);
        sCtx->EvalParam(k_invertBump, -1, &invertBump, &zero);
        sCtx->EvalParam(k_orientation, -1, &orientation, &custom);
        sCtx->EvalParam(k_flipX, -1, &flipX, &zero);
        sCtx->EvalParam(k_flipY, -1, &flipY, &zero);
        sCtx->EvalParam(k_invertT, -1, &invertT, &one);
        sCtx->EvalParam(k_reverse, -1, &reverse, &zero);

        // The signs of the map's x and y, from the convention and the flips (which only the manual
        // orientation reads).
        bool const manual = *orientation != k_openGL && *orientation != k_directX;
        float signX = manual ? (*flipX ? 1.0f : -1.0f) : 1.0f;
        float signY = (manual && *flipY) || *orientation == k_directX ? -1.0f : 1.0f;
        if (*invertBump) signX = -signX, signY = -signY;
        if (!*invertT) signY = -signY;  // the image's up is then -t

        RtVector3 const *dPdu, *dPdv, *Vn;
        sCtx->GetBuiltinVar(RixShadingContext::k_dPdu, &dPdu);
        sCtx->GetBuiltinVar(RixShadingContext::k_dPdv, &dPdv);
        sCtx->GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        for (int i = 0; i < n; ++i) {
            RtNormal3 const N = base[i].LengthSq() > 0.0f ? RtNormal3(Normalize(base[i])) : Nn[i];
            RtVector3 T, B;
            tangentFrame(N, dPdu[i], dPdv[i], T, B);
            float const x = signX * (2.0f * colors[i].r - 1.0f), y = signY * (2.0f * colors[i].g - 1.0f);
            float const z = 2.0f * colors[i].b - 1.0f;
            RtVector3 bent = (T * x + B * y) * bumpScale[i] + N * z;
            RtNormal3 normal = bent.LengthSq() > 1e-12f ? RtNormal3(Normalize(bent)) : N;
            float const mix = RixClamp(surfaceNormalMix[i], 0.0f, 1.0f);
            if (mix > 0.0f) {
                RtVector3 blended = normal * (1.0f - mix) + N * mix;
                normal = blended.LengthSq() > 1e-12f ? RtNormal3(Normalize(blended)) : N;
            }
            if (*adjustAmount > 0.0f) normal = stockpatterns::facingViewer(normal, N, Vn[i]);
            result[i] = *reverse ? RtNormal3(-normal) : normal;
        }
    }

private:
    /// Each point's encoded normal: the image's colour at its texture
    /// coordinates, or inputRGB when there is no image.
    RtColorRGB const* encodedNormals(RixShadingContext const* sCtx) {
        RtUString const noFile;
        RtColorRGB const flat(0.5f, 0.5f, 1.0f);  // (0, 0, 1): the surface's own normal
        RtUString const* filename;
        RtColorRGB const* inputRGB;
        sCtx->EvalParam(k_filename, -1, &filename, &noFile);
        sCtx->EvalParam(k_inputRGB, -1, &inputRGB, &flat, true);
        if (filename->Empty()) return inputRGB;

        stockpatterns::ImageReading reading =
            stockpatterns::imageReading(sCtx, k_firstChannel, "PxrNormalMap", *filename);
        reading.lookup.missingColor = flat;  // a map that cannot be read leaves the normal as it is
        RtColorRGB* colors = RixShadingContext::Allocator(sCtx).AllocFor<RtColorRGB>(sCtx->numPts);
        stockpatterns::readTexture(sCtx, *filename, reading.lookup, stockpatterns::manifoldOf(sCtx, k_manifold),
                                   sCtx->numPts, reading.invertT, reading.blur, colors);
        return colors;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrNormalMap)
