#include "parse/RibParser.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "parse/RibLexer.h"

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

}  // namespace

void parseRib(std::string const& text, std::string const& fileName, RequestHandler const& handler) {
    RibLexer lexer(text, fileName);
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
            if (next.kind == RibToken::Kind::Request || next.kind == RibToken::Kind::End) break;
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

void parseRibFile(std::string const& path, RequestHandler const& handler) {
    // A folder opens like an empty file on Linux; say what it is instead of reading nothing.
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw RenderError("\"" + path + "\" is a folder, not a RIB file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw RenderError("cannot open RIB file \"" + path + "\"");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw RenderError("cannot read RIB file \"" + path + "\"");
    parseRib(text.str(), path, handler);
}

}  // namespace bxdflab
