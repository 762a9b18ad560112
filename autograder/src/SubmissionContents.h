// What a submission's files hold, as far as grading cares: a source submission
// is built from its sources, so compiled code brought along is left out, and
// data that could be compiled code in disguise (a plugin as base64 text or as a
// byte array in a .cpp) is pointed out to the instructor. Both are reasons to
// look, decided by content, never by name. And an exercise that asks for a
// function the API already has must not hand its work to the API's.
#pragma once

#include <string>
#include <vector>

namespace rixgrade {

/// "compiled code (...)" for an ELF file or a static library (by its first bytes), else "".
std::string compiledCode(std::string const& path);

/// For a C/C++ or CMake source: a description of embedded data large enough to be a
/// plugin (a long run of base64 or hex text, or a large table of numbers), else "".
std::string embeddedData(std::string const& path);

/// Whether an exercise's own code calls an API function that does the work the
/// exercise asks for (`names`, from its manifest's writeYourself). Reads the
/// exercise's `sources` in `folder` (relative to the submission's root `root`)
/// and every file of the submission they include with "...", without comments,
/// strings or character literals; token pasting (##) counts too, since it can
/// spell a name the reading cannot see. Returns what it found ("Sampling.cpp
/// calls RixPhongLobePdf"), or "".
std::string callsWhatItShouldWrite(std::string const& root, std::string const& folder,
                                   std::vector<std::string> const& sources, std::vector<std::string> const& names);

}  // namespace rixgrade
