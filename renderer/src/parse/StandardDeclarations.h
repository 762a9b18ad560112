// The parameter names RIB files use without declaring them: the RenderMan
// Interface Specification's predeclared variables and RenderMan's standard
// options, attributes, display, hider and shader parameters. One table,
// read by Declarations.
#pragma once

#include <utility>
#include <vector>

namespace bxdflab {

/// (name, declaration) pairs, e.g. {"fov", "float"}, {"bucketsize", "int[2]"}.
std::vector<std::pair<char const*, char const*>> const& standardDeclarations();

}  // namespace bxdflab
