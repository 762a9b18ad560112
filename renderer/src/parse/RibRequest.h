// One RIB request with its arguments, and a reader that checks them.
//
// RIB is loosely typed: `Sphere 1 -1 1 360` and `Sphere [1 -1 1 360]` mean
// the same. The reader accepts both and reports mismatches as
// "file:line:col: Sphere: expected zmax (a number), found string \"x\"".
#pragma once

#include <string>
#include <vector>

#include "core/Error.h"
#include "parse/ParamList.h"

namespace bxdflab {

struct RibValue {
    enum class Kind { Number, String, NumberArray, StringArray };
    Kind kind = Kind::Number;
    std::vector<double> numbers;
    std::vector<std::string> strings;
    SourceLocation where;
    std::string describe() const;
};

struct RibRequest {
    std::string name;
    SourceLocation where;
    std::vector<RibValue> args;
    /// The word that ended the request (the next request's name), "" at the
    /// end of the file: when a value is missing it is often that word, a value
    /// written without quotes or a name left in a template.
    std::string endedBy;
    SourceLocation endedAt;
};

class RequestReader {
public:
    /// `diagnostics`, when given, hears about values read leniently (a colour given one number).
    RequestReader(RibRequest const& request, Declarations const& declarations, Diagnostics* diagnostics = nullptr)
        : m_request(request), m_declarations(declarations), m_diagnostics(diagnostics) {}

    float number(const char* what);
    /// A whole number that fits an int (a count, a step).
    int integer(const char* what);
    /// `count` numbers, given one by one or as one array.
    std::vector<float> numbers(size_t count, const char* what);
    /// One colour (Color, Opacity): as many numbers as ColorSamples says, given as RGB.
    Vec3 color(const char* what);
    /// One array of numbers of any length (a lone number counts as an array of one).
    std::vector<float> numberArray(const char* what);
    std::vector<int> intArray(const char* what);
    std::string string(const char* what);
    /// One array of strings (a lone string, or [] for none).
    std::vector<std::string> stringArray(const char* what);
    bool atEnd() const { return m_next >= m_request.args.size(); }
    bool nextIsString() const;
    /// Whether the next argument is written as an array ([...]), not a lone value.
    bool nextIsArray() const;
    /// Whether the next arguments are a parameter's name and its value: a lone
    /// string followed by a number or an array (not by another string, as a
    /// handle is followed by a name).
    bool nextIsParameter() const;
    /// The remaining arguments as "type name" value pairs.
    ParamList params();
    /// Throws if arguments are left over.
    void finish();
    /// Leaves the remaining arguments unread (a request whose content is not used).
    void skipRemaining() { m_next = m_request.args.size(); }
    [[noreturn]] void fail(SourceLocation const& where, std::string const& message) const;
    SourceLocation const& where() const { return m_request.where; }

private:
    RibValue const& take(const char* what, const char* expected);
    RibRequest const& m_request;
    Declarations const& m_declarations;
    Diagnostics* m_diagnostics;
    size_t m_next = 0;
};

}  // namespace bxdflab
