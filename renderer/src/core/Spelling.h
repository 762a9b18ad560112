// Which known name a mistyped one was meant to be: for "did you mean ...?"
// hints on RIB request and parameter names.
#pragma once

#include <string>
#include <vector>

namespace bxdflab {

/// The candidate closest to `name` when it is at most two letters off, and
/// off by no more than a third of its letters (insertions, deletions or
/// substitutions, ignoring case), else "".
/// Ties go to the earlier candidate.
std::string closestSpelling(std::string const& name, std::vector<std::string> const& candidates);

/// `text` in lower case (ASCII): for names compared without regard to case.
std::string lowered(std::string text);

}  // namespace bxdflab
