// The test runner: Catch2's, with image files through OpenImageIO as in rixrender.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "film/OiioImageFiles.h"

int main(int argc, char* argv[]) {
    bxdflab::useOpenImageIO();
    return Catch::Session().run(argc, argv);
}
