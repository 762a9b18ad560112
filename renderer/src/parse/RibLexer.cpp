#include "parse/RibLexer.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

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
        case Kind::String: {
            // Never raw bytes to a terminal: control and non-ASCII bytes as \xNN, long strings cut.
            std::string shown;
            for (unsigned char c : text.substr(0, 60)) {
                if (c >= 32 && c < 127) {
                    shown += static_cast<char>(c);
                } else {
                    char hex[8];
                    std::snprintf(hex, sizeof hex, "\\x%02x", c);
                    shown += hex;
                }
            }
            return "string \"" + shown + (text.size() > 60 ? "...\"" : "\"");
        }
        default: return kindName(kind);
    }
}

RibLexer::RibLexer(std::string text, std::string fileName) : m_text(std::move(text)), m_file(std::move(fileName)) {
    // A byte-order mark, as some Windows editors save text: not part of the file's content. (Binary
    // RIB reserves 0xef, so no binary file starts with one.)
    if (m_text.compare(0, 3, "\xef\xbb\xbf") == 0) m_pos = 3;
}

bool RibLexer::atLineEnd() const {
    // "\n", and a "\r" not followed by one: files saved on classic Mac OS end their lines in "\r" alone.
    char const c = current();
    return c == '\n' || (c == '\r' && (m_pos + 1 >= m_text.size() || m_text[m_pos + 1] != '\n'));
}

void RibLexer::advance() { step(atLineEnd()); }

void RibLexer::advanceInPayload() {
    // A binary token's bytes are data: a 0x0d among them ends no line (a 0x0a counts, as it always has,
    // so that the locations of binary files stay as they were).
    step(current() == '\n');
}

void RibLexer::step(bool lineEnd) {
    if (m_pos >= m_text.size()) return;
    if (lineEnd) {
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
            while (!atLineEnd() && current() != '\0') advance();
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

uint32_t RibLexer::takeUnsigned(int count, SourceLocation const& where) {
    if (m_pos + static_cast<size_t>(count) > m_text.size()) throw RibError(where, "binary RIB token cut short by the end of the file");
    uint32_t value = 0;
    for (int i = 0; i < count; ++i) {
        value = (value << 8) | static_cast<unsigned char>(current());
        advanceInPayload();
    }
    return value;
}

std::string RibLexer::takeBytes(size_t count, SourceLocation const& where) {
    if (count > m_text.size() - m_pos) throw RibError(where, "binary RIB string cut short by the end of the file");
    std::string out = m_text.substr(m_pos, count);
    for (size_t i = 0; i < count; ++i) advanceInPayload();
    return out;
}

bool RibLexer::scanBinary(unsigned char code, RibToken& token) {
    SourceLocation where = token.location;
    auto number = [&](double value) {
        token.kind = RibToken::Kind::Number;
        token.number = value;
        token.text = std::to_string(value);
        return true;
    };
    auto string = [&](std::string value) {
        token.kind = RibToken::Kind::String;
        token.text = std::move(value);
        return true;
    };
    auto float32 = [&] {
        uint32_t bits = takeUnsigned(4, where);
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    };
    if (code <= 0203) {  // integer of 1-4 bytes, most significant first
        int bytes = code - 0200 + 1;
        uint32_t raw = takeUnsigned(bytes, where);
        return number(bytes == 4 ? static_cast<double>(static_cast<int32_t>(raw)) : static_cast<double>(raw));
    }
    if (code <= 0217) {  // fixed point: w+1 bytes, the radix point d bytes from the right
        int bytes = ((code - 0200) & 3) + 1, radix = ((code - 0200) >> 2) & 3;
        uint32_t whole = takeUnsigned(std::max(0, bytes - radix), where);
        uint32_t fraction = takeUnsigned(std::min(radix, bytes), where);
        return number(whole + static_cast<double>(fraction) / static_cast<double>(1u << (8 * radix)));
    }
    if (code <= 0237) return string(takeBytes(code - 0220u, where));  // a string shorter than 16 bytes
    if (code <= 0243) return string(takeBytes(takeUnsigned(code - 0240 + 1, where), where));
    if (code == 0244) return number(float32());
    if (code == 0245) {
        uint64_t bits = (static_cast<uint64_t>(takeUnsigned(4, where)) << 32) | takeUnsigned(4, where);
        double d;
        std::memcpy(&d, &bits, sizeof d);
        if (!(std::fabs(d) <= FLT_MAX)) throw RibError(where, "binary number too large for a 32-bit float");
        return number(d);
    }
    if (code == 0246) {  // an encoded request, defined before
        int id = static_cast<int>(takeUnsigned(1, where));
        auto found = m_encodedRequests.find(id);
        if (found == m_encodedRequests.end())
            throw RibError(where, "binary RIB uses request code " + std::to_string(id) + " before defining it");
        token.kind = RibToken::Kind::Request;
        token.text = found->second;
        return true;
    }
    if (code >= 0310 && code <= 0313) {  // an array of 32-bit floats
        uint32_t count = takeUnsigned(code - 0310 + 1, where);
        if (count > (m_text.size() - m_pos) / 4) throw RibError(where, "binary float array longer than the file");
        m_pendingFloats.clear();
        for (uint32_t i = 0; i < count; ++i) m_pendingFloats.push_back(float32());
        m_pendingIndex = 0;
        m_inBinaryArray = true;
        token.kind = RibToken::Kind::ArrayBegin;
        token.text = "[";
        return true;
    }
    if (code == 0314) {  // define a request code: the code, then the request's name as a string
        int id = static_cast<int>(takeUnsigned(1, where));
        RibToken name = scan();
        if (name.kind != RibToken::Kind::String || name.text.empty())
            throw RibError(where, "binary RIB request definition without a name");
        m_encodedRequests[id] = name.text;
        return false;
    }
    if (code == 0315 || code == 0316) {  // define a string code
        uint32_t id = takeUnsigned(code - 0315 + 1, where);
        RibToken text = scan();
        if (text.kind != RibToken::Kind::String) throw RibError(where, "binary RIB string definition without a string");
        m_encodedStrings[id] = text.text;
        return false;
    }
    if (code == 0317 || code == 0320) {
        uint32_t id = takeUnsigned(code - 0317 + 1, where);
        auto found = m_encodedStrings.find(id);
        if (found == m_encodedStrings.end())
            throw RibError(where, "binary RIB uses string code " + std::to_string(id) + " before defining it");
        return string(found->second);
    }
    // What Windows PowerShell's > and some editors save: text of two bytes a character, which starts
    // with the byte-order mark 0xff 0xfe (or 0xfe 0xff).
    bool const utf16 = m_pos == 1 && m_text.size() >= 2 &&
                       ((code == 0xff && m_text[1] == '\xfe') || (code == 0xfe && m_text[1] == '\xff'));
    if (utf16)
        throw RibError(where, "the file is UTF-16 text (two bytes a character, as Windows PowerShell's > writes); "
                              "RIB is ASCII, UTF-8 or RenderMan's binary encoding: save it as one of those");
    char shown[16];
    std::snprintf(shown, sizeof shown, "0x%02x", code);
    throw RibError(where, std::string("unexpected byte ") + shown + " (a code the binary RIB encoding reserves)");
}

RibToken RibLexer::scan() {
    RibToken token;
    if (m_inBinaryArray) {
        token.location = here();
        if (m_pendingIndex < m_pendingFloats.size()) {
            token.kind = RibToken::Kind::Number;
            token.number = m_pendingFloats[m_pendingIndex++];
            token.text = std::to_string(token.number);
            if (!std::isfinite(token.number)) throw RibError(token.location, "binary float array holds a non-finite value");
        } else {
            m_inBinaryArray = false;
            token.kind = RibToken::Kind::ArrayEnd;
            token.text = "]";
        }
        return token;
    }
    for (;;) {
        skipSpaceAndComments();
        token.location = here();
        unsigned char byte = static_cast<unsigned char>(current());
        if (byte < 0200 || m_pos >= m_text.size()) break;
        advance();
        if (scanBinary(byte, token)) return token;
    }
    char c = current();
    if (c == '\0') {
        if (m_pos < m_text.size()) throw RibError(token.location, "unexpected NUL byte (this is not a RIB file)");
        token.kind = RibToken::Kind::End;
        return token;
    }
    if (c == '[' || c == ']') {
        token.kind = c == '[' ? RibToken::Kind::ArrayBegin : RibToken::Kind::ArrayEnd;
        token.text = std::string(1, c);
        advance();
        return token;
    }
    if (c == '"' || c == '\'') {
        // Double quotes are RIB's; some hand-written files use single quotes.
        char quote = c;
        token.kind = RibToken::Kind::String;
        advance();
        for (;;) {
            char s = current();
            if (s == '\0' && m_pos >= m_text.size())
                throw RibError(token.location, std::string("unterminated string (missing closing ") + quote + ")");
            advance();
            if (s == quote) break;
            if (s == '\\') {
                char e = current();
                advance();
                switch (e) {
                    case 'n': token.text += '\n'; break;
                    case 't': token.text += '\t'; break;
                    case 'r': token.text += '\r'; break;
                    case '\n': break;  // an escaped line break continues the string
                    default: token.text += e; break;
                }
                continue;
            }
            token.text += s;  // a string may span lines
        }
        if (m_line != token.location.line) {
            MultiLineString& last = m_lastMultiLineString;
            bool const sameSlip = last.closedOnLine > 0 && token.location.line - last.closedOnLine <= last.kReach;
            last = {sameSlip ? last.opened : token.location, m_line};
        }
        return token;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
        size_t start = m_pos;
        // sign? digits [. digits] [(e|E) sign? digits]. A sign after that starts the next number,
        // as in RenderMan's reading of "Scale 1 1-1"; a digit, point or letter run on ("1.5.2", "1e5e3",
        // "360A") is an error below, as no number or request starts there.
        auto digits = [this] {
            while (std::isdigit(static_cast<unsigned char>(current()))) advance();
        };
        if (current() == '-' || current() == '+') advance();
        digits();
        if (current() == '.') {
            advance();
            digits();
        }
        if (current() == 'e' || current() == 'E') {
            advance();
            if (current() == '-' || current() == '+') advance();
            digits();
        }
        token.text = m_text.substr(start, m_pos - start);
        bool const runsOn = std::isalnum(static_cast<unsigned char>(current())) || current() == '.' || current() == '_';
        char* end = nullptr;
        token.number = std::strtod(token.text.c_str(), &end);
        if (runsOn || end != token.text.c_str() + token.text.size()) {
            // Show the whole word ("-x" of a shell line, "1.2.3a"), not only the part read as a number.
            while (std::isalnum(static_cast<unsigned char>(current())) || current() == '_' || current() == '.' ||
                   current() == '-' || current() == '+')
                advance();
            throw RibError(token.location, "malformed number '" + m_text.substr(start, m_pos - start) + "'");
        }
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
    throw RibError(token.location, std::string("unexpected ") + shown);
}

}  // namespace bxdflab
