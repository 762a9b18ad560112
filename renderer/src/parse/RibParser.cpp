#include "parse/RibParser.h"

#include <sys/stat.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/GitLfs.h"
#include "parse/RibLexer.h"
#include "parse/ZipMember.h"

namespace bxdflab {
namespace {

RibValue readArray(RibLexer& lexer, RibToken const& open) {
    RibValue value;
    value.where = open.location;
    bool sawNumber = false, sawString = false;
    for (;;) {
        RibToken token = lexer.next();
        switch (token.kind) {
            case RibToken::Kind::ArrayEnd:
                value.kind = sawString ? RibValue::Kind::StringArray : RibValue::Kind::NumberArray;
                return value;
            case RibToken::Kind::Number:
                sawNumber = true;
                value.numbers.push_back(token.number);
                break;
            case RibToken::Kind::String:
                sawString = true;
                value.strings.push_back(token.text);
                break;
            case RibToken::Kind::End:
                throw RibError(open.location, "unterminated array: '[' has no matching ']'");
            default:
                throw RibError(token.location, "expected a number, a string or ']' inside the array, found " + token.describe());
        }
        if (sawNumber && sawString)
            throw RibError(token.location, "an array may hold numbers or strings, not both");
    }
}

/// Reads requests to the end of the text, handing each to `handler`.
void readRequests(RibLexer& lexer, RequestHandler const& handler) {
    for (;;) {
        RibToken token = lexer.next();
        if (token.kind == RibToken::Kind::End) return;
        if (token.kind != RibToken::Kind::Request)
            throw RibError(token.location, "expected a request name (such as WorldBegin or Sphere), found " + token.describe());
        RibRequest request;
        request.name = token.text;
        request.where = token.location;
        for (;;) {
            RibToken const& next = lexer.peek();
            if (next.kind == RibToken::Kind::End) break;
            if (next.kind == RibToken::Kind::Request) {
                request.endedBy = next.text;
                request.endedAt = next.location;
                break;
            }
            RibToken arg = lexer.next();
            RibValue value;
            value.where = arg.location;
            if (arg.kind == RibToken::Kind::Number) {
                value.kind = RibValue::Kind::Number;
                value.numbers.push_back(arg.number);
            } else if (arg.kind == RibToken::Kind::String) {
                value.kind = RibValue::Kind::String;
                value.strings.push_back(arg.text);
            } else if (arg.kind == RibToken::Kind::ArrayBegin) {
                value = readArray(lexer, arg);
            } else {
                throw RibError(arg.location, "unexpected " + arg.describe() + " (no matching '[')");
            }
            request.args.push_back(std::move(value));
        }
        handler(request);
    }
}

/// `error` with a pointer back to a string that ran over lines just before it: a missing closing
/// quote is closed by the next quote, and the text after it then fails lines away from the mistake.
RibError pointingAtOpenQuote(RibError const& error, RibLexer::MultiLineString const& string) {
    return RibError(error.location, error.message() + " (the string opened at " + string.opened.str() +
                                        " runs on past its line: is its closing quote missing?)");
}
}  // namespace

void parseRib(std::string const& text, std::string const& fileName, RequestHandler const& handler) {
    RibLexer lexer(text, fileName);
    try {
        readRequests(lexer, handler);
    } catch (RibError const& error) {
        RibLexer::MultiLineString const& string = lexer.lastMultiLineString();
        bool const justAfter = string.closedOnLine > 0 && error.location.file == fileName &&
                               error.location.line >= string.closedOnLine &&
                               error.location.line - string.closedOnLine <= string.kReach;
        if (justAfter) throw pointingAtOpenQuote(error, string);
        throw;
    }
}

namespace {

constexpr size_t kMaxRibBytes = size_t(1) << 31;  // 2 GiB, compressed or not

/// The text of a gzip-compressed RIB file (RenderMan reads .rib.gz directly).
std::string gunzip(std::string const& compressed, std::string const& path) {
    z_stream stream{};
    if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) throw RenderError("cannot start decompressing \"" + path + "\"");
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
    stream.avail_in = static_cast<uInt>(compressed.size());
    std::string out;
    char buffer[1 << 16];
    int status = Z_OK;
    while (status != Z_STREAM_END) {
        stream.next_out = reinterpret_cast<Bytef*>(buffer);
        stream.avail_out = sizeof buffer;
        status = inflate(&stream, Z_NO_FLUSH);
        if (status != Z_OK && status != Z_STREAM_END) {
            inflateEnd(&stream);
            throw RenderError("\"" + path + "\" is not valid gzip data (" + (stream.msg ? stream.msg : "corrupt") + ")");
        }
        out.append(buffer, sizeof buffer - stream.avail_out);
        if (out.size() > kMaxRibBytes) {
            inflateEnd(&stream);
            throw RenderError("\"" + path + "\" decompresses to more than 2 GiB");
        }
        if (status == Z_OK && stream.avail_in == 0 && stream.avail_out != 0) {
            inflateEnd(&stream);
            throw RenderError("\"" + path + "\" ends in the middle of its gzip data");
        }
    }
    inflateEnd(&stream);
    return out;
}


/// The text of a RIB file's bytes: inflated when they are gzip data.
std::string ribText(std::string const& bytes, std::string const& path) {
    if (bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f && static_cast<unsigned char>(bytes[1]) == 0x8b)
        return gunzip(bytes, path);
    if (isGitLfsPointer(bytes)) throw RenderError("\"" + path + "\" is " + gitLfsPointerNote("RIB file"));
    return bytes;
}

}  // namespace

std::string readRibFile(std::string const& path) {
    if (std::optional<ZipMemberName> zipped = splitZipMemberName(path)) return ribText(readZipMember(*zipped, kMaxRibBytes), path);
    // A folder, a FIFO or a device would make the read misbehave (empty, block
    // forever, never end): only regular files are RIB files.
    struct stat st;
    if (stat(path.c_str(), &st) != 0) throw RenderError("cannot open RIB file \"" + path + "\"");
    if (S_ISDIR(st.st_mode)) throw RenderError("\"" + path + "\" is a folder, not a RIB file");
    if (!S_ISREG(st.st_mode)) throw RenderError("\"" + path + "\" is not a regular file (a pipe or a device?)");
    if (static_cast<unsigned long long>(st.st_size) > kMaxRibBytes) throw RenderError("\"" + path + "\" is larger than 2 GiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw RenderError("cannot open RIB file \"" + path + "\"");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw RenderError("cannot read RIB file \"" + path + "\"");
    return ribText(text.str(), path);
}

void parseRibFile(std::string const& path, RequestHandler const& handler) { parseRib(readRibFile(path), path, handler); }

}  // namespace bxdflab
