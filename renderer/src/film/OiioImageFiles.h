// The image files the renderer reads and writes, through OpenImageIO. A
// program that needs them calls useOpenImageIO() once, at the top of main.
#pragma once

#include "core/ImageFiles.h"

namespace bxdflab {

/// Largest image read: 16384 pixels on a side and 2^28 pixels in all. An
/// image declaring more is refused before anything is decoded.
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 1ll << 28;

/// The OpenImageIO implementation of ImageFiles.
ImageFiles const& openImageIOFiles();
/// Installs it (programs linked with OpenImageIO call this at the top of main).
void useOpenImageIO();

}  // namespace bxdflab
