// Errors the renderer reports to its user. Library code throws; only the
// command-line front ends catch and turn them into an exit status, so a host
// program (the autograder, the tests) survives any bad input.
#pragma once

#include <stdexcept>
#include <string>

namespace bxdflab {

/// A place in an input file, printed as file:line:col.
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;

    bool known() const { return !file.empty(); }
    std::string str() const {
        if (!known()) return "<unknown>";
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    }
};

/// Anything that stops a render: bad input, a missing plugin, an unwritable file.
class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    /// What went wrong without where: for a message that is quoted inside another one at the same place.
    virtual std::string message() const { return what(); }
};

/// An error located in a RIB file: "file:line:col: message".
class RibError : public RenderError {
public:
    RibError(SourceLocation where, std::string const& message)
        : RenderError(where.str() + ": " + message), location(std::move(where)), m_message(message) {}
    std::string message() const override { return m_message; }
    SourceLocation location;

private:
    std::string m_message;
};

/// An exception a plugin threw while shading, with the plugin and the RIB
/// statement that uses it: "plugin \"x\" (Bxdf \"h\", scene.rib:12:3) threw: ...".
class PluginFault : public RenderError {
public:
    using RenderError::RenderError;
};

}  // namespace bxdflab
