// Variables named in RIB text and in RenderMan's ini files: "${NAME}",
// "$NAME" and "$user:NAME", read in search paths and in conditions.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace bxdflab {

/// A variable's value, or nothing when it is not set.
using VariableLookup = std::function<std::optional<std::string>(std::string const& name)>;

/// The environment variable `name`, if it is set.
std::optional<std::string> environmentVariable(std::string const& name);

/// Where the name of a variable written without braces ends, reading from
/// `start` (just after its "$"): letters, digits and "_", and after "user"
/// also ":" and a second name ("$user:pass"). Returns `start` when no name is there.
size_t variableNameEnd(std::string const& text, size_t start);

/// `text` with each "${NAME}" and "$NAME" replaced by `lookup`'s value for NAME;
/// one `lookup` does not know is left as it is written.
std::string expandVariables(std::string const& text, VariableLookup const& lookup);

}  // namespace bxdflab
