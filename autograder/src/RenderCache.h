// Reference renders kept on disk between grading runs. A reference render is
// deterministic (fixed seed), so a student who grades again, or an
// instructor who grades a second class, need not render the solutions again.
// An entry is found by a key that names everything its pixels depend on --
// the scene, its spp and seed, and the size and modification time of every
// file that could change them (the renderer, the solutions, integrators and
// stock plugins, the scene's folder with its textures) -- and is stored with
// the key inside it, so a stale or foreign file is never taken for a match.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rixgrade {

/// The key of a render: `inputs` are files or folders (folders are read whole, recursively).
std::string renderCacheKey(std::string const& scene, int spp, int seed, std::vector<std::string> const& inputs);

/// The raw image stored in `folder` under `key`, or nothing.
std::optional<std::string> loadCachedRender(std::string const& folder, std::string const& key);

/// Stores a raw image (written to a temporary file and renamed, so a reader
/// never sees half of one) and removes the entries of the same scene, spp and
/// seed made with older inputs. Failing to store is not an error: the cache
/// is only a shortcut.
void storeCachedRender(std::string const& folder, std::string const& key, std::string const& bytes);

}  // namespace rixgrade
