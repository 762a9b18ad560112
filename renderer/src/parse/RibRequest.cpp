#include "parse/RibRequest.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "parse/RequestNames.h"

namespace bxdflab {

std::string RibValue::describe() const {
    std::ostringstream out;
    switch (kind) {
        case Kind::Number: out << "number " << numbers[0]; break;
        case Kind::String: out << "string \"" << strings[0] << "\""; break;
        case Kind::NumberArray: out << "an array of " << numbers.size() << " numbers"; break;
        case Kind::StringArray: out << "an array of " << strings.size() << " strings"; break;
    }
    return out.str();
}

void RequestReader::fail(SourceLocation const& where, std::string const& message) const {
    throw RibError(where, m_request.name + ": " + message);
}

RibValue const& RequestReader::take(const char* what, const char* expected) {
    if (atEnd()) {
        std::string const missing = std::string("expected ") + what + " (" + expected + ")";
        // A word that is no request where a value belongs ("ShadingRate SR" in a
        // template, an unquoted string): point at it rather than at the request.
        if (!m_request.endedBy.empty() && !isRibRequest(m_request.endedBy))
            fail(m_request.endedAt, missing + ", found the word " + m_request.endedBy +
                                        ", which is not a value (a number, a \"quoted string\" or a [list]) nor a request");
        fail(m_request.where, missing + ", but the request ends here");
    }
    return m_request.args[m_next++];
}

bool RequestReader::nextIsString() const {
    if (atEnd()) return false;
    auto kind = m_request.args[m_next].kind;
    return kind == RibValue::Kind::String || kind == RibValue::Kind::StringArray;
}

float RequestReader::number(const char* what) {
    RibValue const& v = take(what, "a number");
    if ((v.kind == RibValue::Kind::Number || v.kind == RibValue::Kind::NumberArray) && v.numbers.size() == 1) {
        if (!std::isfinite(v.numbers[0])) fail(v.where, std::string(what) + " must be a finite number");
        return static_cast<float>(v.numbers[0]);
    }
    fail(v.where, std::string("expected ") + what + " (a number), found " + v.describe());
}

int RequestReader::integer(const char* what) {
    RibValue const& v = take(what, "a whole number");
    if ((v.kind == RibValue::Kind::Number || v.kind == RibValue::Kind::NumberArray) && v.numbers.size() == 1) {
        if (!isWholeInt(v.numbers[0])) fail(v.where, std::string(what) + " must be a whole number that fits an int");
        return static_cast<int>(v.numbers[0]);
    }
    fail(v.where, std::string("expected ") + what + " (a whole number), found " + v.describe());
}

Vec3 RequestReader::color(const char* what) {
    ColorSamples const& samples = m_declarations.colorSamples();
    // Under ColorSamples a colour is written as its samples, not as red, green and blue.
    std::string const named = samples.toRGB.empty() ? std::string(what)
                                                    : "a colour of " + std::to_string(samples.count) +
                                                          " ColorSamples";
    return samples.rgb(numbers(samples.count, named.c_str()).data());
}

std::vector<float> RequestReader::numbers(size_t count, const char* what) {
    std::vector<float> out;
    if (!atEnd() && m_request.args[m_next].kind == RibValue::Kind::NumberArray) {
        RibValue const& v = take(what, "numbers");
        if (v.numbers.size() != count)
            fail(v.where, std::string("expected ") + std::to_string(count) + (count == 1 ? " number" : " numbers") +
                              " for " + what + ", found " +
                              std::to_string(v.numbers.size()));
        for (double d : v.numbers) out.push_back(static_cast<float>(d));
    } else {
        for (size_t i = 0; i < count; ++i) out.push_back(number(what));
    }
    for (float f : out)
        if (!std::isfinite(f)) fail(m_request.where, std::string(what) + " must be finite numbers");
    return out;
}

std::vector<float> RequestReader::numberArray(const char* what) {
    RibValue const& v = take(what, "an array of numbers");
    if (v.kind != RibValue::Kind::NumberArray && v.kind != RibValue::Kind::Number)
        fail(v.where, std::string("expected ") + what + " (an array of numbers), found " + v.describe());
    std::vector<float> out;
    for (double d : v.numbers) {
        if (!std::isfinite(d)) fail(v.where, std::string(what) + " must be finite numbers");
        out.push_back(static_cast<float>(d));
    }
    return out;
}

std::vector<int> RequestReader::intArray(const char* what) {
    RibValue const& v = take(what, "an array of integers");
    if (v.kind != RibValue::Kind::NumberArray && v.kind != RibValue::Kind::Number)
        fail(v.where, std::string("expected ") + what + " (an array of integers), found " + v.describe());
    std::vector<int> out;
    for (double d : v.numbers) {
        if (!isWholeInt(d)) fail(v.where, std::string(what) + " must be whole numbers that fit an int");
        out.push_back(static_cast<int>(d));
    }
    return out;
}

std::string RequestReader::string(const char* what) {
    RibValue const& v = take(what, "a string");
    if ((v.kind == RibValue::Kind::String || v.kind == RibValue::Kind::StringArray) && v.strings.size() == 1)
        return v.strings[0];
    fail(v.where, std::string("expected ") + what + " (a string), found " + v.describe());
}

bool RequestReader::nextIsArray() const {
    if (atEnd()) return false;
    RibValue::Kind kind = m_request.args[m_next].kind;
    return kind == RibValue::Kind::StringArray || kind == RibValue::Kind::NumberArray;
}

bool RequestReader::nextIsParameter() const {
    if (m_next + 1 >= m_request.args.size() || m_request.args[m_next].kind != RibValue::Kind::String) return false;
    return m_request.args[m_next + 1].kind != RibValue::Kind::String;
}

std::vector<std::string> RequestReader::stringArray(const char* what) {
    RibValue const& v = take(what, "an array of strings");
    if (v.kind == RibValue::Kind::String || v.kind == RibValue::Kind::StringArray) return v.strings;
    if (v.kind == RibValue::Kind::NumberArray && v.numbers.empty()) return {};
    fail(v.where, std::string("expected ") + what + " (an array of strings), found " + v.describe());
}

ParamList RequestReader::params() {
    ParamList list;
    while (!atEnd()) {
        RibValue const& nameValue = m_request.args[m_next++];
        if (nameValue.kind != RibValue::Kind::String)
            fail(nameValue.where, "expected a parameter name such as \"float intensity\", found " + nameValue.describe());
        if (atEnd()) fail(nameValue.where, "parameter \"" + nameValue.strings[0] + "\" has no value");
        RibValue const& value = m_request.args[m_next++];
        Param param;
        param.decl = m_declarations.resolve(nameValue.strings[0], nameValue.where);
        param.location = nameValue.where;
        bool isString = value.kind == RibValue::Kind::String || value.kind == RibValue::Kind::StringArray;
        // Attribute and Option own the standard names; a shader or plugin may mean its own by one.
        bool const ownsStandardNames = m_request.name == "Attribute" || m_request.name == "Option";
        bool const fractionForInt = !ownsStandardNames && param.decl.type == ParamType::Int &&
                                    std::any_of(value.numbers.begin(), value.numbers.end(),
                                                [](double d) { return !isWholeInt(d); });
        if (param.decl.standard && ((param.decl.type == ParamType::String) != isString || fractionForInt)) {
            // A standard name used for something else (an old shader's own "frequency" 3, a light's or
            // PxrDisney's "specular" 0.5 beside the visibility attribute's int): kept as written, for the
            // request to type.
            param.decl.type = ParamType::Unknown;
            param.decl.untyped = true;
        }
        if (param.decl.arraySize == 0) {
            // An empty array ("int[0] utilityPattern" []): a parameter with no values, of any type.
            if (!value.numbers.empty() || !value.strings.empty())
                fail(value.where, "parameter \"" + param.name() + "\" is declared as an array of 0 but has " +
                                      value.describe());
            list.add(std::move(param));
            continue;
        }
        if (param.decl.type == ParamType::Unknown || param.decl.reference) {
            // Kept as written: an untyped name (used only if someone asks), or a connection ("node:output").
            param.strings = value.strings;
            for (double d : value.numbers) param.floats.push_back(static_cast<float>(d));
            if (param.decl.reference && !isString)
                fail(value.where, "parameter \"" + param.name() + "\" is a reference: its value is \"node:output\"");
            list.add(std::move(param));
            continue;
        }
        if ((param.decl.type == ParamType::String) != isString)
            fail(value.where, "parameter \"" + param.name() + "\" is declared " + paramTypeName(param.decl.type) +
                                  " but its value is " + value.describe());
        if (isString) {
            param.strings = value.strings;
        } else {
            ColorSamples const& samples = m_declarations.colorSamples();
            bool const color = param.decl.type == ParamType::Color;
            size_t group = (color ? samples.count : static_cast<size_t>(componentsOf(param.decl.type))) *
                           static_cast<size_t>(param.decl.arraySize);
            std::vector<double> numbers = value.numbers;
            if (color && samples.count == 3 && param.decl.arraySize == 1 && numbers.size() == 1) {
                // Older files write a grey as one number ("color Cs" .5); RenderMan reads it as that grey.
                numbers.assign(3, numbers[0]);
                if (m_diagnostics)
                    m_diagnostics->warn(value.where, "parameter \"" + param.name() + "\" is a color given one number; "
                                                     "taken as the grey [" + std::to_string(value.numbers[0]) + " x3]");
            }
            if (numbers.size() % group != 0)  // [] is allowed: an empty mesh's "P" [] is
                fail(value.where, "parameter \"" + param.name() + "\" (" + paramTypeName(param.decl.type) + ") needs a multiple of " +
                                      std::to_string(group) + " numbers, found " + std::to_string(numbers.size()));
            for (double d : numbers) {
                if (!std::isfinite(d)) fail(value.where, "parameter \"" + param.name() + "\" has a non-finite value");
                if (param.decl.type == ParamType::Int) {
                    if (!isWholeInt(d))
                        fail(value.where, "parameter \"" + param.name() + "\" is an int but has value " + std::to_string(d));
                    param.ints.push_back(static_cast<int>(d));
                }
                param.floats.push_back(static_cast<float>(d));
            }
            if (color && !samples.toRGB.empty()) {  // colours in ColorSamples' numbers become RGB
                std::vector<float> rgb;
                for (size_t at = 0; at < param.floats.size(); at += samples.count) {
                    Vec3 const c = samples.rgb(param.floats.data() + at);
                    rgb.insert(rgb.end(), {c.x, c.y, c.z});
                }
                param.floats = std::move(rgb);
            }
        }
        list.add(std::move(param));
    }
    return list;
}

void RequestReader::finish() {
    if (!atEnd()) fail(m_request.args[m_next].where, "unexpected extra argument " + m_request.args[m_next].describe());
}

}  // namespace bxdflab
