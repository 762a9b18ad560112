#include "film/OiioImageFiles.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>

#include "core/Error.h"
#include "film/OiioTextures.h"

namespace bxdflab {
namespace {

/// An image file opened for reading, its declared size checked before any
/// pixel is decoded: a small file can claim an image of many gigabytes.
/// Errors start with `prefix`.
std::unique_ptr<OIIO::ImageInput> openChecked(std::string const& path, std::string const& prefix) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) {
        std::string why = OIIO::geterror(), pointer = notAnImageBecause(path);
        throw RenderError(prefix + (pointer.empty() ? why : pointer));
    }
    OIIO::ImageSpec const& spec = input->spec();
    long long const pixels = static_cast<long long>(spec.width) * spec.height;
    if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxImageSide || spec.height > kMaxImageSide ||
        pixels > kMaxImagePixels || spec.nchannels <= 0 || spec.nchannels > 16 || spec.depth > 1)
        throw RenderError(prefix + "it declares " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                          " pixels of " + std::to_string(spec.nchannels) + " channels; at most " +
                          std::to_string(kMaxImageSide) + " on a side (and 16 channels) are read");
    return input;
}

class OiioImageFiles final : public ImageFiles {
public:
    std::unique_ptr<TextureService> openTextures(Diagnostics& diagnostics) const override {
        return makeOiioTextures(diagnostics);
    }

    ImagePixels read(std::string const& path, std::string const& what) const override {
        std::string const prefix = what + " \"" + path + "\": ";
        auto input = openChecked(path, prefix);
        OIIO::ImageSpec const& spec = input->spec();
        long long const pixels = static_cast<long long>(spec.width) * spec.height;
        ImagePixels image;
        image.width = spec.width;
        image.height = spec.height;
        image.channels = spec.nchannels;
        image.pixels.resize(static_cast<size_t>(pixels) * static_cast<size_t>(spec.nchannels));
        if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
            throw RenderError(prefix + input->geterror());
        return image;
    }

    void makeTexture(std::string const& texture, MadeTexture const& made) const override {
        std::string const prefix = made.where.str() + ": picture \"" + made.picture + "\": ";
        openChecked(made.picture, prefix);
        OIIO::ImageSpec config;
        config.attribute("wrapmodes", made.environment ? "periodic,clamp" : made.wrapS + "," + made.wrapT);
        // RenderMan's own .tex format is not written: a tiled, mip-mapped TIFF
        // (OpenEXR for a .exr name), which OpenImageIO reads under any name.
        std::string const extension = std::filesystem::path(texture).extension().string();
        config.attribute("maketx:fileformatname", extension == ".exr" ? "openexr" : "tiff");
        auto const mode = made.environment ? OIIO::ImageBufAlgo::MakeTxEnvLatl : OIIO::ImageBufAlgo::MakeTxTexture;
        if (!OIIO::ImageBufAlgo::make_texture(mode, made.picture, texture, config))
            throw RenderError(made.where.str() + ": cannot make texture \"" + texture + "\": " + OIIO::geterror());
    }

    void write(std::string const& path, std::vector<float> const& pixels, int width, int height, int channels,
               std::vector<std::string> const& names) const override {
        if (!isWritableImageName(path))
            throw RenderError("cannot write \"" + path + "\": unknown image format \"" +
                              std::filesystem::path(path).extension().string() + "\" (use .exr, .tif, .png or .jpg)");
        bool const eightBit = isEightBitImageName(path);
        OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
        if (static_cast<int>(names.size()) == channels) {
            spec.channelnames = names;
            // Which channels hold alpha and depth, for readers that look for them by role.
            auto role = [&names](char const* name) {
                return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
            };
            spec.alpha_channel = role("A") < channels ? role("A") : -1;
            spec.z_channel = role("Z") < channels ? role("Z") : -1;
        }
        OIIO::ImageBuf image(spec);
        image.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
        OIIO::TypeDesc storage = OIIO::TypeDesc::FLOAT;
        if (eightBit) {
            // 8-bit images are for looking at: no alpha (viewers would show the
            // empty background as white), colour through the sRGB transfer curve.
            if (channels > 3) image = OIIO::ImageBufAlgo::channels(image, 3, {0, 1, 2});
            else if (channels == 2) image = OIIO::ImageBufAlgo::channels(image, 1, {0});
            OIIO::ImageBuf encoded;
            if (!OIIO::ImageBufAlgo::colorconvert(encoded, image, "linear", "sRGB", false))
                throw RenderError("cannot convert \"" + path + "\" to sRGB: " + encoded.geterror());
            image = std::move(encoded);
            storage = OIIO::TypeDesc::UINT8;
        }
        image.set_write_format(storage);
        if (!image.write(path)) throw RenderError("cannot write image \"" + path + "\": " + image.geterror());
    }
};

}  // namespace

ImageFiles const& openImageIOFiles() {
    static OiioImageFiles const files;
    return files;
}

void useOpenImageIO() { installImageFiles(&openImageIOFiles()); }

}  // namespace bxdflab
