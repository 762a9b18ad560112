#include "parse/RibLexer.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace bxdflab {

const char* RibToken::kindName(Kind kind) {
    switch (kind) {
        case Kind::Request: return "request name";
        case Kind::Number: return "number";
        case Kind::String: return "string";
        case Kind::ArrayBegin: return "'['";
        case Kind::ArrayEnd: return "']'";
        case Kind::End: return "end of file";
    }
    return "token";
}

std::string RibToken::describe() const {
    switch (kind) {
        case Kind::Request: return "request " + text;
        case Kind::Number: return "number " + text;
        case Kind::String: return "string \"" + text + "\"";
        default: return kindName(kind);
    }
}

RibLexer::RibLexer(std::string text, std::string fileName) : m_text(std::move(text)), m_file(std::move(fileName)) {}

void RibLexer::advance() {
    if (m_pos >= m_text.size()) return;
    if (m_text[m_pos] == '\n') {
        ++m_line;
        m_column = 1;
    } else {
        ++m_column;
    }
    ++m_pos;
}

void RibLexer::skipSpaceAndComments() {
    for (;;) {
        char c = current();
        if (c == '#') {
            while (current() != '\n' && current() != '\0') advance();
        } else if (c != '\0' && std::isspace(static_cast<unsigned char>(c))) {
            advance();
        } else {
            return;
        }
    }
}

RibToken const& RibLexer::peek() {
    if (!m_hasPeeked) {
        m_peeked = scan();
        m_hasPeeked = true;
    }
    return m_peeked;
}

RibToken RibLexer::next() {
    if (m_hasPeeked) {
        m_hasPeeked = false;
        return std::move(m_peeked);
    }
    return scan();
}

RibToken RibLexer::scan() {
    skipSpaceAndComments();
    RibToken token;
    token.location = here();
    char c = current();
    if (c == '\0') {
        if (m_pos < m_text.size()) throw RibError(token.location, "unexpected NUL byte (binary RIB is not supported)");
        token.kind = RibToken::Kind::End;
        return token;
    }
    if (c == '[' || c == ']') {
        token.kind = c == '[' ? RibToken::Kind::ArrayBegin : RibToken::Kind::ArrayEnd;
        token.text = std::string(1, c);
        advance();
        return token;
    }
    if (c == '"') {
        token.kind = RibToken::Kind::String;
        advance();
        for (;;) {
            char s = current();
            if (s == '\0' && m_pos >= m_text.size())
                throw RibError(token.location, "unterminated string (missing closing \")");
            if (s == '\n') throw RibError(token.location, "unterminated string (a string may not span lines)");
            advance();
            if (s == '"') break;
            if (s == '\\') {
                char e = current();
                advance();
                switch (e) {
                    case 'n': token.text += '\n'; break;
                    case 't': token.text += '\t'; break;
                    case '\\': token.text += '\\'; break;
                    case '"': token.text += '"'; break;
                    default: token.text += e; break;
                }
                continue;
            }
            token.text += s;
        }
        return token;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
        size_t start = m_pos;
        while (std::isdigit(static_cast<unsigned char>(current())) || current() == '-' || current() == '+' ||
               current() == '.' || current() == 'e' || current() == 'E')
            advance();
        token.text = m_text.substr(start, m_pos - start);
        char* end = nullptr;
        token.number = std::strtod(token.text.c_str(), &end);
        if (end != token.text.c_str() + token.text.size())
            throw RibError(token.location, "malformed number '" + token.text + "'");
        // RIB numbers are 32-bit floats: a larger one would silently become infinite.
        if (!(std::fabs(token.number) <= FLT_MAX))
            throw RibError(token.location, "number " + token.text + " is too large for a 32-bit float (at most about 3.4e38)");
        token.kind = RibToken::Kind::Number;
        return token;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        size_t start = m_pos;
        while (std::isalnum(static_cast<unsigned char>(current())) || current() == '_') advance();
        token.kind = RibToken::Kind::Request;
        token.text = m_text.substr(start, m_pos - start);
        return token;
    }
    // Anything else: shown as text when printable, else as a byte value (never raw to the terminal).
    unsigned char const byte = static_cast<unsigned char>(c);
    char shown[32];
    if (std::isprint(byte))
        std::snprintf(shown, sizeof shown, "character '%c'", c);
    else
        std::snprintf(shown, sizeof shown, "byte 0x%02x", byte);
    throw RibError(token.location, std::string("unexpected ") + shown +
                                       (std::isprint(byte) ? "" : " (binary RIB is not supported)"));
}

}  // namespace bxdflab
