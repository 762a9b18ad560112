// Reads RIB text and hands each request, with its arguments, to a handler.
// Knows nothing about what requests mean (that is the SceneBuilder's job).
#pragma once

#include <functional>
#include <string>

#include "parse/RibRequest.h"

namespace bxdflab {

using RequestHandler = std::function<void(RibRequest const&)>;

/// Parses all requests of `text` (named `fileName` in messages).
void parseRib(std::string const& text, std::string const& fileName, RequestHandler const& handler);

/// The bytes of a RIB file (gzip-compressed files are decompressed; a name
/// "bundle.zip!member.rib" reads a member of a zip file); throws
/// RenderError for what cannot be read, or is not a regular file.
std::string readRibFile(std::string const& path);

/// Reads a file and parses it; throws RenderError if it cannot be read.
void parseRibFile(std::string const& path, RequestHandler const& handler);

}  // namespace bxdflab
