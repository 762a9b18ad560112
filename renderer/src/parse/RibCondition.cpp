#include "parse/RibCondition.h"

#include <regex.h>

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace bxdflab {

namespace {

/// A value met while reading: text, which may also read as a number.
struct Value {
    std::string text;

    bool number(double& out) const {
        if (text.empty()) return false;
        char const* begin = text.c_str();
        char* end = nullptr;
        out = std::strtod(begin, &end);
        // Finite only: "nan" and "inf" are words here, and two NaNs would otherwise compare equal to
        // anything.
        return end == begin + text.size() && std::isfinite(out);
    }
    bool holds() const {
        double x = 0.0;
        return number(x) ? x != 0.0 : !text.empty();
    }
    static Value of(bool b) { return {b ? "1" : "0"}; }
};

/// Recursive descent over one expression, lowest precedence first.
class ConditionReader {
public:
    ConditionReader(std::string const& text, VariableLookup const& lookup) : m_text(text), m_lookup(lookup) {}

    bool read() {
        Value const result = anyOf();
        skipSpace();
        if (m_pos < m_text.size()) fail("unexpected '" + m_text.substr(m_pos, 1) + "'");
        return result.holds();
    }

private:
    // a || b
    Value anyOf() {
        Value left = allOf();
        while (accept("||")) {
            Value const right = allOf();  // both sides are read, so an error on either is found
            left = Value::of(left.holds() || right.holds());
        }
        return left;
    }
    // a && b
    Value allOf() {
        Value left = negation();
        while (accept("&&")) {
            Value const right = negation();
            left = Value::of(left.holds() && right.holds());
        }
        return left;
    }
    // !a
    Value negation() {
        skipSpace();
        if (m_pos < m_text.size() && m_text[m_pos] == '!' && !startsWith("!=")) {
            ++m_pos;
            return Value::of(!negation().holds());
        }
        return comparison();
    }
    // a == b, a =~ b, ...
    Value comparison() {
        Value const left = operand();
        // Two-character operators first, so that "<=" is not read as "<".
        static char const* const operators[] = {"==", "!=", "<=", ">=", "=~", "<", ">"};
        for (char const* op : operators) {
            if (!accept(op)) continue;
            skipSpace();
            size_t const rightAt = m_pos;
            Value const right = operand();
            return Value::of(compare(op, left, right, rightAt));
        }
        return left;
    }
    bool compare(std::string const& op, Value const& left, Value const& right, size_t rightAt) const {
        if (op == "=~") return matches(left.text, right.text, rightAt);
        double a = 0.0, b = 0.0;
        int order = 0;
        if (left.number(a) && right.number(b))
            order = a < b ? -1 : (a > b ? 1 : 0);
        else
            order = left.text.compare(right.text) < 0 ? -1 : (left.text == right.text ? 0 : 1);
        if (op == "==") return order == 0;
        if (op == "!=") return order != 0;
        if (op == "<") return order < 0;
        if (op == "<=") return order <= 0;
        if (op == ">") return order > 0;
        return order >= 0;  // ">="
    }
    /// POSIX extended regular expressions: glibc's matcher takes time polynomial in the
    /// text, where std::regex backtracks (and recurses) without bound on patterns such as "(a*)*b".
    bool matches(std::string const& text, std::string const& pattern, size_t patternAt) const {
        regex_t compiled;
        if (regcomp(&compiled, pattern.c_str(), REG_EXTENDED | REG_NOSUB) != 0)
            fail("'" + pattern + "' is not a regular expression", patternAt);
        bool const found = regexec(&compiled, text.c_str(), 0, nullptr, 0) == 0;
        regfree(&compiled);
        return found;
    }
    Value operand() {
        skipSpace();
        if (m_pos >= m_text.size()) fail("a value is missing at the end");
        char const c = m_text[m_pos];
        if (c == '(') {
            ++m_pos;
            Value inner = anyOf();
            if (!accept(")")) fail("')' expected");
            return inner;
        }
        if (c == '\'' || c == '"') return quoted(c);
        if (c == '$') {
            ++m_pos;
            std::optional<std::string> value = m_lookup(variableName());
            return {value.value_or("")};
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') return number();
        if (m_text.compare(m_pos, 7, "defined") == 0) {
            m_pos += 7;
            if (!accept("(")) fail("'(' expected after defined");
            skipSpace();
            if (m_pos < m_text.size() && m_text[m_pos] == '$') ++m_pos;  // defined($NAME) as defined(NAME)
            std::string const name = variableName();
            if (!accept(")")) fail("')' expected after the name in defined(...)");
            return Value::of(m_lookup(name).has_value());
        }
        fail("a value is expected here: a number, a 'quoted string', a $variable or defined(NAME)");
    }
    Value quoted(char quote) {
        size_t const close = m_text.find(quote, m_pos + 1);
        if (close == std::string::npos) fail("this string has no closing quote");
        Value v{m_text.substr(m_pos + 1, close - m_pos - 1)};
        m_pos = close + 1;
        return v;
    }
    Value number() {
        char const* begin = m_text.c_str() + m_pos;
        char* end = nullptr;
        std::strtod(begin, &end);
        if (end == begin) fail("a number is expected here");
        Value v{m_text.substr(m_pos, static_cast<size_t>(end - begin))};
        m_pos += static_cast<size_t>(end - begin);
        return v;
    }
    /// A variable's name: NAME, user:NAME or {NAME}.
    std::string variableName() {
        if (m_pos < m_text.size() && m_text[m_pos] == '{') {
            size_t const close = m_text.find('}', m_pos);
            if (close == std::string::npos) fail("'${' has no closing '}'");
            std::string name = m_text.substr(m_pos + 1, close - m_pos - 1);
            m_pos = close + 1;
            if (name.empty()) fail("a variable's name is missing", close);
            return name;
        }
        size_t const end = variableNameEnd(m_text, m_pos);
        if (end == m_pos) fail("a variable's name is expected here");
        std::string name = m_text.substr(m_pos, end - m_pos);
        m_pos = end;
        return name;
    }
    bool startsWith(char const* word) const {
        return m_text.compare(m_pos, std::char_traits<char>::length(word), word) == 0;
    }
    bool accept(char const* word) {
        skipSpace();
        if (!startsWith(word)) return false;
        m_pos += std::char_traits<char>::length(word);
        return true;
    }
    void skipSpace() {
        while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos]))) ++m_pos;
    }
    [[noreturn]] void fail(std::string const& message) const { fail(message, m_pos); }
    [[noreturn]] void fail(std::string const& message, size_t at) const { throw ConditionError{at, message}; }

    std::string const& m_text;
    VariableLookup const& m_lookup;
    size_t m_pos = 0;
};

}  // namespace

bool evaluateCondition(std::string const& expression, VariableLookup const& lookup) {
    return ConditionReader(expression, lookup).read();
}

}  // namespace bxdflab
