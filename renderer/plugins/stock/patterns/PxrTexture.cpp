// PxrTexture — reads a colour from an image at each shade point's texture
// coordinates, through the renderer's texture service (RixTexture): mip-mapped
// and filtered over the ray's footprint, so a distant board does not shimmer.
//
//   Pattern "PxrTexture" "grain" "string filename" ["maple_color.tx"] "int linearize" [1]
//   Bxdf "PxrDiffuse" "board" "reference color diffuseColor" ["grain:resultRGB"]
//
// Coordinates come from a connected manifold (PxrManifold2D) or else from the
// surface's s and t. With invertT (on by default, as in RenderMan) t runs up
// the image: t = 0 is its bottom row; blur widens the filter (in texture
// units). "linearize" undoes the sRGB encoding of 8-bit images made for
// display, so the colours are the reflectances meant. A file that cannot be
// read gives missingColor (magenta) and one warning.
#include <cmath>

#include "PatternHelpers.h"

namespace {

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

class PxrTexture : public stockpatterns::StockPattern {
public:
    enum {
        k_filename, k_firstChannel, k_atlasStyle, k_invertT, k_blur, k_lerp, k_filter, k_linearize, k_missingColor,
        k_missingAlpha, k_manifold, k_resultRGB, k_resultR, k_resultG, k_resultB, k_resultA
    };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("filename"), k_RixSCString),
            STOCK_PATTERN_IMAGE_READING_PARAMS,
            RixSCParamInfo(RtUString("linearize"), k_RixSCInteger),
            RixSCParamInfo(RtUString("missingColor"), k_RixSCColor),
            RixSCParamInfo(RtUString("missingAlpha"), k_RixSCFloat),
            RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),  // (s, t, filter width): see PxrManifold2D
            STOCK_PATTERN_COLOR_OUTPUTS,
            RixSCParamInfo(RtUString("resultA"), k_RixSCFloat, k_RixSCOutput),
            RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        int const n = sCtx->numPts;
        RtUString const noFile;
        RtInt const zero = 0;
        RtColorRGB const magenta(1.0f, 0.0f, 1.0f);
        RtFloat const opaque = 1.0f;
        RtUString const* filename;
        RtInt const* linearize;
        RtColorRGB const* missingColor;
        RtFloat const* missingAlpha;
        // Uniform parameters: one value for the whole batch.
        sCtx->EvalParam(k_filename, -1, &filename, &noFile);
        stockpatterns::ImageReading reading =
            stockpatterns::imageReading(sCtx, k_firstChannel, "PxrTexture", *filename);
        sCtx->EvalParam(k_linearize, -1, &linearize, &zero);
        sCtx->EvalParam(k_missingColor, -1, &missingColor, &magenta);
        sCtx->EvalParam(k_missingAlpha, -1, &missingAlpha, &opaque);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(5);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        RtColorRGB* rgb = result.rgb();
        RtFloat* a = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultA);

        reading.lookup.missingColor = *missingColor;
        // The image's alpha (its fourth channel; 1 where it has none), read only when asked for.
        bool const alphaRead = stockpatterns::isOutputRead(sCtx, k_resultA);
        bool const found = stockpatterns::readTexture(sCtx, *filename, reading.lookup,
                                                      stockpatterns::manifoldOf(sCtx, k_manifold), n,
                                                      reading.invertT, reading.blur, rgb, alphaRead ? a : nullptr);
        for (int i = 0; i < n; ++i) {
            if (found && *linearize)
                rgb[i] = RtColorRGB(srgbToLinear(rgb[i].r), srgbToLinear(rgb[i].g), srgbToLinear(rgb[i].b));
            result.set(i, rgb[i]);
            if (!found)
                a[i] = *missingAlpha;
            else if (!alphaRead)
                a[i] = 1.0f;
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrTexture)
