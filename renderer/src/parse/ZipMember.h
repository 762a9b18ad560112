// RenderMan reads a RIB archive straight out of a zip file when its name is
// written "bundle.zip!path/inside.rib" (RenderMan for Maya stores a scene's
// geometry that way). These helpers split such a name and read the member.
#pragma once

#include <optional>
#include <string>

namespace bxdflab {

/// A name of the form "<file>.zip!<member>", split in two.
struct ZipMemberName {
    std::string zipFile;
    std::string member;
};

/// The two parts of `name` when it names a member of a zip file (the part
/// before the first "!" ends in ".zip", in any case); nullopt otherwise.
std::optional<ZipMemberName> splitZipMemberName(std::string const& name);

/// The bytes of one member of a zip file (at most `maxBytes` once
/// decompressed). Throws RenderError when the file is not a zip file, the
/// member is not in it (the message lists what is), or it cannot be read.
std::string readZipMember(ZipMemberName const& name, size_t maxBytes);

/// Empty when the zip file holds the member; else why it cannot be read
/// (not a zip file, or no such member: then what it does hold).
std::string zipMemberProblem(ZipMemberName const& name);

}  // namespace bxdflab
