// Reading and writing image files, behind an interface: only the programs
// that read or write images (rixrender, the tools, the grader's reports)
// link the OpenImageIO implementation (film/OiioImageFiles) and install it
// at start-up. The others -- the plugin probe that rixmeasure and rixcheck
// are built on -- start without OpenImageIO's hundreds of shared libraries.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "RixInterfaces.h"
#include "core/TextureLocator.h"

namespace bxdflab {

struct ImagePixels {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;  ///< row-major from the top left, `channels` floats per pixel
};

class Diagnostics;

/// The renderer's RixTexture, with the count of points looked up (for the stats).
class TextureService : public RixTexture {
public:
    /// Where the files that lookups name are found.
    virtual void setLocator(TextureLocator locator) = 0;
    uint64_t lookups() const { return m_lookups.load(std::memory_order_relaxed); }

protected:
    std::atomic<uint64_t> m_lookups{0};
};

class ImageFiles {
public:
    virtual ~ImageFiles() = default;
    /// Reads an image as floats. Throws RenderError naming `what` (e.g.
    /// "PxrDomeLight: cannot read lightColorMap") and the reason.
    virtual ImagePixels read(std::string const& path, std::string const& what) const = 0;
    /// Writes floats; the format follows the extension (.exr .tif keep floats,
    /// .png .jpg become 8-bit sRGB of the first three channels, or of the one).
    /// `names` names the channels (empty: the format's own names, R G B A).
    /// Throws RenderError.
    virtual void write(std::string const& path, std::vector<float> const& pixels, int width, int height,
                       int channels, std::vector<std::string> const& names) const = 0;
    /// Writes the texture file `texture` made from a picture, as RenderMan's
    /// MakeTexture and MakeLatLongEnvironment do. Throws RenderError.
    virtual void makeTexture(std::string const& texture, MadeTexture const& made) const = 0;
    /// A texture service for pattern plugins (warnings about unreadable
    /// files go to `diagnostics`); null when the program reads no images.
    virtual std::unique_ptr<TextureService> openTextures(Diagnostics& diagnostics) const = 0;
};

/// Makes `files` the implementation every image read and write goes through.
void installImageFiles(ImageFiles const* files);
/// The installed implementation; throws RenderError when the program has none.
ImageFiles const& imageFiles();

/// The installed implementation's texture service, or null when the program has none.
std::unique_ptr<TextureService> openTextures(Diagnostics& diagnostics);

/// Whether `path` names an image format writeImage writes, by its extension (any case):
/// .exr, .tif or .tiff (floats), .png, .jpg or .jpeg (8 bits, sRGB).
bool isWritableImageName(std::string const& path);
/// Whether that format stores 8 bits per channel (and is written without alpha, through sRGB).
bool isEightBitImageName(std::string const& path);

/// Shorthand for imageFiles().write(...).
void writeImage(std::string const& path, std::vector<float> const& pixels, int width, int height, int channels,
                std::vector<std::string> const& names = {});

/// Why an image file that cannot be decoded may be no image at all: a
/// repository cloned without Git LFS holds small text pointers in place of
/// its images, and a copy or download that failed leaves an empty file. The
/// explanation to add to the reader's error, or empty.
std::string notAnImageBecause(std::string const& path);

}  // namespace bxdflab
