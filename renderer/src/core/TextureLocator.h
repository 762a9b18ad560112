// Where a texture file a scene names is read from. One rule for every reader
// (pattern plugins through the texture service, the dome light's image):
// a name the scene's MakeTexture made is read from the picture it was made
// from, as RenderMan would have made the texture file from that picture just
// before; any other name as written (absolute, or from the current folder),
// then in each search folder in turn.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/Error.h"

namespace bxdflab {

/// A texture file a scene's MakeTexture or MakeLatLongEnvironment makes (what RenderMan's txmake writes).
struct MadeTexture {
    std::string picture;      ///< the image it is made from, as found from the RIB file's folder when it is there
    bool environment = false; ///< MakeLatLongEnvironment: a latitude-longitude environment map
    std::string wrapS = "periodic", wrapT = "periodic";  ///< MakeTexture's wrap modes: periodic, clamp or black
    SourceLocation where;     ///< the request, for messages
};

struct TextureLocator {
    std::vector<std::string> folders;             ///< searched in order for a relative name
    std::map<std::string, MadeTexture> madeFrom;  ///< MakeTexture: texture name -> what it is made from
    std::set<std::string> reportedMissing;        ///< not found (or no image) when the scene was read, and said so then

    /// The file to read for `name`, or nothing when no place has it.
    std::optional<std::string> find(std::string const& name) const;
    /// The places find() looks, for a message: "the current folder, a, b".
    std::string searchedPlaces() const;
};

}  // namespace bxdflab
