// rixrender's image files: a stand-in that loads the OpenImageIO module
// (film/OiioModule.cpp) on first use and forwards to it.
#pragma once

#include <string>

#include "core/ImageFiles.h"

namespace bxdflab {

/// Installs the stand-in; `modulePath` is the module's shared object
/// (rixrender passes ../lib/rixoiio.so from its own folder).
void useImageModule(std::string const& modulePath);

}  // namespace bxdflab
