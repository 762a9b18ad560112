// Where the grader writes reports, results.json, images and the gradebook:
// a folder no sandbox sees. Even so, nothing already there is trusted: every
// file is written to a fresh temporary name (created exclusively, never
// through a symbolic link) and renamed over its final name, which replaces
// whatever entry was there -- a file, or a planted link -- instead of
// following it. Sub-folders are created the same careful way.
#pragma once

#include <string>
#include <vector>

namespace rixgrade {

class OutputFolder {
public:
    /// Creates `path` (and its parents) if needed; refuses a symbolic link.
    explicit OutputFolder(std::string path);
    std::string const& path() const { return m_path; }

    /// Writes `contents` to relative name `name` (sub-folders are created).
    void write(std::string const& name, std::string const& contents) const;
    /// Writes an 8-bit sRGB PNG of linear RGB floats (3 per pixel).
    void writePng(std::string const& name, std::vector<float> const& rgb, int width, int height) const;
    /// A sub-folder (created carefully), as its own OutputFolder.
    OutputFolder sub(std::string const& name) const;

private:
    /// The folder holding `name`'s file (created), and the file's leaf name.
    std::string prepare(std::string const& name, std::string& leaf) const;
    /// A new empty file in `folder` with an unused name; returns its path.
    static std::string temporary(std::string const& folder);

    std::string m_path;
};

/// A name safe as one path component: letters, digits, '.', '_', '-' kept,
/// anything else '_'; never empty, never starting with '.'.
std::string safeName(std::string const& name);

}  // namespace rixgrade
