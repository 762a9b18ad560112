// One exit-status convention for every command-line program of the project:
// 0 success (or --help), 1 a handled error (bad input, failed check),
// 2 a usage error (unknown option, value out of range), with CLI11's message.
#pragma once

#include <CLI/CLI.hpp>

/// Use in main() instead of CLI11_PARSE.
#define BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv)           \
    try {                                                     \
        (app).parse((argc), (argv));                          \
    } catch (CLI::ParseError const& usageError) {             \
        return (app).exit(usageError) == 0 ? 0 : 2;           \
    }
