// The expressions of conditional RIB (IfBegin and ElseIf), as RenderMan reads
// them.
#pragma once

#include <cstddef>
#include <string>

#include "core/Variables.h"

namespace bxdflab {

/// A condition that cannot be read: where in its text, and why.
struct ConditionError {
    size_t offset;
    std::string message;
};

/// Whether the condition `expression` holds.
///
/// Values are numbers, quoted strings ('beauty') and variables ($NAME, ${NAME},
/// $user:NAME) looked up through `lookup`; a variable that is not set reads as
/// "". defined(NAME) asks whether one is set. == != < <= > >= compare two
/// numbers as numbers and anything else as text; =~ asks whether the left
/// text contains a match of the (POSIX extended) regular expression on the
/// right. !, && and || combine them, binding in that order after the
/// comparisons; parentheses group.
/// A lone value holds when it is a number other than 0, or non-empty text.
///
/// Throws ConditionError for text that is none of these.
bool evaluateCondition(std::string const& expression, VariableLookup const& lookup);

}  // namespace bxdflab
