// Splits RIB into tokens: request names, numbers, strings and brackets. Both
// of RIB's encodings: ASCII text, and the binary encoding of the RenderMan
// Interface Specification (appendix C.2), which exporters mix freely into the
// same file -- numbers, strings and float arrays as tagged bytes, requests and
// strings defined once and then referred to by a code.
#pragma once

#include <map>
#include <string>
#include <vector>

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
    /// bytes that cannot start a token, unterminated strings and malformed
    /// binary tokens.
    RibToken next();
    RibToken const& peek();

    /// The last string read that ran over a line end: where it opened, and the line it closed on.
    /// Such strings are rare in RIB; one is most often a missing closing quote, which the next
    /// quote, lines later, closes. Every quote after it is then read the wrong way round, so
    /// further such strings that follow within `kReach` lines keep the first one's opening.
    struct MultiLineString {
        static constexpr int kReach = 10;
        SourceLocation opened;
        int closedOnLine = 0;
    };
    MultiLineString const& lastMultiLineString() const { return m_lastMultiLineString; }

private:
    RibToken scan();
    /// A token of the binary encoding, starting with byte `code` (>= 0200).
    /// Returns false for a definition (of a request or string code), which
    /// makes no token of its own.
    bool scanBinary(unsigned char code, RibToken& token);
    void skipSpaceAndComments();
    char current() const { return m_pos < m_text.size() ? m_text[m_pos] : '\0'; }
    bool atLineEnd() const;
    void advance();
    void advanceInPayload();
    void step(bool lineEnd);
    /// The next `count` bytes as an unsigned big-endian number (count <= 4).
    uint32_t takeUnsigned(int count, SourceLocation const& where);
    std::string takeBytes(size_t count, SourceLocation const& where);
    SourceLocation here() const { return {m_file, m_line, m_column}; }

    std::string m_text;
    std::string m_file;
    size_t m_pos = 0;
    int m_line = 1;
    int m_column = 1;
    bool m_hasPeeked = false;
    RibToken m_peeked;
    std::map<int, std::string> m_encodedRequests;  ///< binary request codes defined so far
    std::map<uint32_t, std::string> m_encodedStrings;
    std::vector<float> m_pendingFloats;  ///< the rest of a binary float array
    size_t m_pendingIndex = 0;
    bool m_inBinaryArray = false;
    MultiLineString m_lastMultiLineString;
};

}  // namespace bxdflab
