// Reading and writing image files, behind an interface: only the programs
// that read or write images (rixrender, the tools, the grader's reports)
// link the OpenImageIO implementation (film/OiioImageFiles) and install it
// at start-up. The others -- the plugin probe that rixmeasure and rixcheck
// are built on -- start without OpenImageIO's hundreds of shared libraries.
#pragma once

#include <string>
#include <vector>

namespace bxdflab {

struct ImagePixels {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;  ///< row-major from the top left, `channels` floats per pixel
};

class ImageFiles {
public:
    virtual ~ImageFiles() = default;
    /// Reads an image as floats. Throws RenderError naming `what` (e.g.
    /// "PxrDomeLight: cannot read lightColorMap") and the reason.
    virtual ImagePixels read(std::string const& path, std::string const& what) const = 0;
    /// Writes floats; the format follows the extension (.exr .tif keep floats,
    /// .png .jpg become 8-bit sRGB without alpha). Throws RenderError.
    virtual void write(std::string const& path, std::vector<float> const& pixels, int width, int height,
                       int channels) const = 0;
};

/// Makes `files` the implementation every image read and write goes through.
void installImageFiles(ImageFiles const* files);
/// The installed implementation; throws RenderError when the program has none.
ImageFiles const& imageFiles();

/// Shorthand for imageFiles().write(...).
void writeImage(std::string const& path, std::vector<float> const& pixels, int width, int height, int channels);

}  // namespace bxdflab
