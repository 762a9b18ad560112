#include "film/Film.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/Error.h"

namespace bxdflab {

Film::Film(int width, int height)
    : m_width(width), m_height(height), m_pixels(static_cast<size_t>(width) * static_cast<size_t>(height)) {}

void Film::addSample(int x, int y, RtColorRGB const& radiance, float alpha) {
    Pixel& p = m_pixels[static_cast<size_t>(y) * static_cast<size_t>(m_width) + static_cast<size_t>(x)];
    for (int c = 0; c < 3; ++c) {
        double v = radiance[c];
        p.sum[c] += v;
        p.sumSq[c] += v * v;
    }
    p.alpha += alpha;
    ++p.count;
}

std::vector<float> Film::rgba() const {
    std::vector<float> out(m_pixels.size() * 4, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count == 0) continue;
        for (int c = 0; c < 3; ++c) out[4 * i + static_cast<size_t>(c)] = static_cast<float>(p.sum[c] / p.count);
        out[4 * i + 3] = static_cast<float>(p.alpha / p.count);
    }
    return out;
}

std::vector<float> Film::varianceOfMean() const {
    std::vector<float> out(m_pixels.size() * 3, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count < 2) continue;
        for (int c = 0; c < 3; ++c) {
            double mean = p.sum[c] / p.count;
            double variance = std::max(0.0, (p.sumSq[c] - p.count * mean * mean) / (p.count - 1));
            out[3 * i + static_cast<size_t>(c)] = static_cast<float>(variance / p.count);
        }
    }
    return out;
}

void writeImage(std::string const& path, std::vector<float> const& pixels, int width, int height, int channels) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    bool eightBit = extension == ".png" || extension == ".jpg" || extension == ".jpeg";
    if (!eightBit && extension != ".exr" && extension != ".tif" && extension != ".tiff")
        throw RenderError("cannot write \"" + path + "\": unknown image format \"" + extension +
                          "\" (use .exr, .tif, .png or .jpg)");

    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf image(spec);
    image.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
    OIIO::TypeDesc storage = OIIO::TypeDesc::FLOAT;
    if (eightBit) {
        // 8-bit images are for looking at: no alpha (viewers would show the
        // empty background as white), colour through the sRGB transfer curve.
        if (channels == 4) image = OIIO::ImageBufAlgo::channels(image, 3, {0, 1, 2});
        OIIO::ImageBuf encoded;
        if (!OIIO::ImageBufAlgo::colorconvert(encoded, image, "linear", "sRGB", false))
            throw RenderError("cannot convert \"" + path + "\" to sRGB: " + encoded.geterror());
        image = std::move(encoded);
        storage = OIIO::TypeDesc::UINT8;
    }
    image.set_write_format(storage);
    if (!image.write(path)) throw RenderError("cannot write image \"" + path + "\": " + image.geterror());
}

}  // namespace bxdflab
