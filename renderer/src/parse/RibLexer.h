// Splits RIB text into tokens: request names, numbers, strings and brackets.
#pragma once

#include <string>

#include "core/Error.h"

namespace bxdflab {

struct RibToken {
    enum class Kind { Request, Number, String, ArrayBegin, ArrayEnd, End };
    Kind kind = Kind::End;
    std::string text;     ///< request name or string contents (escapes resolved)
    double number = 0.0;  ///< for Kind::Number
    SourceLocation location;

    static const char* kindName(Kind kind);
    /// How the token looks in an error message, e.g. `number 3.5` or `string "P"`.
    std::string describe() const;
};

class RibLexer {
public:
    RibLexer(std::string text, std::string fileName);

    /// The next token (Kind::End at the end of the text). Throws RibError on
    /// characters that cannot start a token and on unterminated strings.
    RibToken next();
    RibToken const& peek();

private:
    RibToken scan();
    void skipSpaceAndComments();
    char current() const { return m_pos < m_text.size() ? m_text[m_pos] : '\0'; }
    void advance();
    SourceLocation here() const { return {m_file, m_line, m_column}; }

    std::string m_text;
    std::string m_file;
    size_t m_pos = 0;
    int m_line = 1;
    int m_column = 1;
    bool m_hasPeeked = false;
    RibToken m_peeked;
};

}  // namespace bxdflab
