// The names of RIB requests: every request of the RenderMan Interface
// Specification (3.2 to 3.4) and those RenderMan added since (Bxdf, Pattern,
// Light, Integrator, ...), whether this renderer reads them or not. A name
// outside the list is no request at all, most often a typing mistake.
#pragma once

#include <string>

namespace bxdflab {

/// True when `name` is a RIB request (names are case-sensitive, as in RIB).
bool isRibRequest(std::string const& name);

/// True when `name` is a directive of pbrt's scene format that RIB does not
/// have (LookAt, Film, Shape, ...): a sign that the file is no RIB file.
bool isPbrtDirective(std::string const& name);

/// The request `name` was most likely meant to be (one or two letters off,
/// ignoring case), or "" when none is that close.
std::string likelyRibRequest(std::string const& name);

}  // namespace bxdflab
