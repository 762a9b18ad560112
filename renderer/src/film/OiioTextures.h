// The renderer's RixTexture through OpenImageIO's TextureSystem: one tile
// cache shared by every pattern and thread, mip-mapped and filtered lookups.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/Diagnostics.h"
#include "core/ImageFiles.h"

namespace bxdflab {

/// A texture service that finds files as its TextureLocator says and reports
/// unreadable ones to `diagnostics` once each.
std::unique_ptr<TextureService> makeOiioTextures(Diagnostics& diagnostics);

}  // namespace bxdflab
