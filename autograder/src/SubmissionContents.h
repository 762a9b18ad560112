// What a submission's files hold, as far as grading cares: a source submission
// is built from its sources, so compiled code brought along is left out, and
// data that could be compiled code in disguise (a plugin as base64 text or as a
// byte array in a .cpp) is pointed out to the instructor. Both are reasons to
// look, decided by content, never by name.
#pragma once

#include <string>

namespace rixgrade {

/// "compiled code (...)" for an ELF file or a static library (by its first bytes), else "".
std::string compiledCode(std::string const& path);

/// For a C/C++ or CMake source: a description of embedded data large enough to be a
/// plugin (a long run of base64 or hex text, or a large table of numbers), else "".
std::string embeddedData(std::string const& path);

}  // namespace rixgrade
