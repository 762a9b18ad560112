#include "ToolSupport.h"

#include <iostream>

#include <OpenImageIO/imagebufalgo.h>

#include <stdexcept>

namespace bxdflab::tools {

void writeDisplayImage(OIIO::ImageBuf const& image, std::string const& path) {
    OIIO::ImageBuf out = image;
    out.set_write_format(OIIO::TypeDesc::UINT8);
    if (!out.write(path)) throw std::runtime_error("cannot write \"" + path + "\": " + out.geterror());
}

void label(OIIO::ImageBuf& image, int x, int y, std::string const& text, std::vector<float> const& colour, int size) {
    if (!OIIO::ImageBufAlgo::render_text(image, x, y, text, size, "DejaVuSans", colour)) {
        static bool warned = false;
        if (!warned) std::cerr << "warning: figure labels left out (" << image.geterror() << "; install fonts-dejavu-core)\n";
        warned = true;
    }
}

OIIO::ImageBuf heatmap(std::vector<double> const& values, int width, int height, double maxValue, int cell) {
    OIIO::ImageBuf grey(OIIO::ImageSpec(width * cell, height * cell, 1, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < height * cell; ++y)
        for (int x = 0; x < width * cell; ++x) {
            // Row 0 is drawn at the bottom: cos(theta) grows upward.
            double v = values[static_cast<size_t>((height - 1 - y / cell) * width + x / cell)];
            float value = maxValue > 0 ? static_cast<float>(std::min(1.0, v / maxValue)) : 0.0f;
            grey.setpixel(x, y, &value);
        }
    return OIIO::ImageBufAlgo::color_map(grey, 0, "inferno");
}

}  // namespace bxdflab::tools
