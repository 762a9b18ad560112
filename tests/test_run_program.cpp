// Procedural "RunProgram": a helper program, asked once per procedural, writes the RIB of its geometry.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/Error.h"
#include "scene/ProceduralProgram.h"
#include "scene/SceneBuilder.h"
#include "scene/shapes/Quadrics.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;
namespace fs = std::filesystem;

namespace {

/// A folder of its own for each case, with `program` in it as an executable file named `name`.
fs::path folderWithProgram(std::string const& folderName, std::string const& name,
                           std::string const& program) {
    fs::path const folder = fs::path(test::outputDir()) / "run-program" / folderName;
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / name) << program;
    chmod((folder / name).c_str(), 0755);
    return folder;
}

/// Loads a world of `world` from scene.rib in `folder`.
Scene loadWorld(fs::path const& folder, std::string const& world, Diagnostics& diagnostics,
                bool runPrograms = true) {
    std::ofstream(folder / "scene.rib") << "WorldBegin\n" << world << "WorldEnd\n";
    LoadOptions options;
    options.runPrograms = runPrograms;
    return loadScene((folder / "scene.rib").string(), diagnostics, options);
}

// Answers each request with a sphere, in a material of its own, whose radius is the datablock times how
// many requests it has had; then the end mark.
std::string const kCountingProgram =
    "#!/bin/sh\n"
    "n=0\n"
    "while read detail radius; do\n"
    "  n=$((n + 1))\n"
    "  echo \"Bxdf \\\"PxrDiffuse\\\" \\\"inner\\\"\"\n"
    "  echo \"Sphere $((n * radius)) -1 1 360\"\n"
    "  printf '\\377'\n"
    "done\n";

}  // namespace

TEST_CASE("RunProgram runs its program only when asked to, and reads what it writes as RIB in place",
          "[rib]") {
    fs::path const folder = folderWithProgram("counting", "spheres.sh", kCountingProgram);
    std::string const world =
        "Bxdf \"PxrDiffuse\" \"outer\"\nProcedural \"RunProgram\" [\"spheres.sh\" \"1\"] [-1 1 -1 1 -1 1]\n"
        "Procedural \"RunProgram\" [\"spheres.sh\" \"3\"] [-1 1 -1 1 -1 1]\nSphere 1 -1 1 360\n";
    SECTION("not asked: the geometry is skipped, and the warning says how to run it") {
        Diagnostics diagnostics(false);
        Scene scene = loadWorld(folder, world, diagnostics, false);
        CHECK(scene.shapes.size() == 1u);
        CHECK(test::warningsContaining(diagnostics, "run only when asked for (rixrender --run-programs)") ==
              1);
    }
    SECTION("asked: one process answers both procedurals, and what it sets stays inside its geometry") {
        Diagnostics diagnostics(false);
        Scene scene = loadWorld(folder, world, diagnostics);
        REQUIRE(scene.shapes.size() == 3u);
        auto radius = [&](size_t k) {
            Vec3 lower, upper;
            dynamic_cast<Sphere const&>(*scene.shapes[k]).boundsLocal(lower, upper);
            return upper.x;
        };
        CHECK(radius(0) == 1.0f);
        CHECK(radius(1) == 6.0f);  // its second request: 2 x 3
        CHECK(radius(2) == 1.0f);
        // Each procedural's sphere is "inner"; after them the Bxdf is "outer" again.
        CHECK(scene.shapes[0]->material != scene.shapes[2]->material);
        CHECK(scene.shapes[1]->material != scene.shapes[2]->material);
        CHECK(test::warningsContaining(diagnostics, "") == 0);
    }
}

TEST_CASE(
    "RunProgram: a python 2 script for a python that is not here runs with python3 and ends its answers",
    "[rib]") {
    // Written for RenderMan's python 2: "\377" through a text stream is the end mark only as Latin-1.
    fs::path const folder = folderWithProgram("python2", "sphere.py",
                                              "#!/no/such/folder/python\n"
                                              "import sys\n"
                                              "line = sys.stdin.readline()\n"
                                              "while line:\n"
                                              "    sys.stdout.write('Sphere 2 -1 1 360\\n')\n"
                                              "    sys.stdout.write('\\377')\n"
                                              "    sys.stdout.flush()\n"
                                              "    line = sys.stdin.readline()\n");
    // Even where the user's own PYTHONIOENCODING asks for UTF-8.
    struct UserEncoding {
        UserEncoding() { setenv("PYTHONIOENCODING", "utf-8", 1); }
        ~UserEncoding() { unsetenv("PYTHONIOENCODING"); }
    } const userEncoding;
    auto radiusOfTheOneSphere = [](Scene const& scene) {
        REQUIRE(scene.shapes.size() == 1u);
        Vec3 lower, upper;
        dynamic_cast<Sphere const&>(*scene.shapes[0]).boundsLocal(lower, upper);
        return upper.x;
    };
    SECTION("named by its file: python3 stands in for the python its first line names, and a note says so") {
        Diagnostics diagnostics(false);
        Scene scene = loadWorld(folder, "Procedural \"RunProgram\" [\"sphere.py\" \"\"] [-2 2 -2 2 -2 2]\n",
                                diagnostics);
        CHECK(radiusOfTheOneSphere(scene) == 2.0f);
        bool noted = false;
        for (auto const& entry : diagnostics.entries())
            noted = noted ||
                    entry.text.find("asks for /no/such/folder/python, which is not here: it is run with") !=
                        std::string::npos;
        CHECK(noted);
    }
    SECTION("named as a command on PATH with the script as its argument") {
        Diagnostics diagnostics(false);
        Scene scene = loadWorld(
            folder, "Procedural \"RunProgram\" [\"python3 sphere.py\" \"\"] [-2 2 -2 2 -2 2]\n", diagnostics);
        CHECK(radiusOfTheOneSphere(scene) == 2.0f);
        CHECK(test::warningsContaining(diagnostics, "") == 0);
    }
}

TEST_CASE(
    "RunProgram: a program that is missing, ends early, hangs or writes bad RIB is reported, never waited on",
    "[rib]") {
    SECTION("missing: every place searched is named, and the rest renders") {
        fs::path const folder = folderWithProgram("missing", "other.sh", "#!/bin/sh\n");
        Diagnostics diagnostics(false);
        Scene scene = loadWorld(folder,
                                "Procedural \"RunProgram\" [\"absent.sh\" \"\"] [-1 1 -1 1 -1 1]\n"
                                "Sphere 1 -1 1 360\n",
                                diagnostics);
        CHECK(scene.shapes.size() == 1u);
        CHECK(test::warningsContaining(diagnostics, "the program is not in any place searched:\n    " +
                                                        (folder / "absent.sh").string()) == 1);
    }
    SECTION("ends without its end mark: said once, and its later procedurals are skipped") {
        fs::path const folder =
            folderWithProgram("early", "early.sh", "#!/bin/sh\nread line\necho 'Sphere 1 -1 1 360'\n");
        Diagnostics diagnostics(false);
        Scene scene = loadWorld(folder,
                                "Procedural \"RunProgram\" [\"early.sh\" \"\"] [-1 1 -1 1 -1 1]\n"
                                "Procedural \"RunProgram\" [\"early.sh\" \"\"] [-1 1 -1 1 -1 1]\n",
                                diagnostics);
        CHECK(scene.shapes.empty());
        CHECK(test::warningsContaining(diagnostics,
                                       "the program ended after 18 bytes, without the byte 0xFF") == 1);
    }
    SECTION("silent too long: stopped") {
        fs::path const folder = folderWithProgram("silent", "silent.sh", "#!/bin/sh\nsleep 30\n");
        ProgramLaunch const launch = programLaunch((folder / "silent.sh").string(), {});
        ProceduralProgram program(launch, folder.string(), 200);
        CHECK_THROWS_WITH(program.generate(1.0f, ""), Catch::Matchers::Contains("wrote nothing for 0.2 s"));
    }
    SECTION(
        "bad RIB in its output is located in the output; a block left open is an error at the procedural") {
        fs::path const folder =
            folderWithProgram("bad", "bad.sh",
                              "#!/bin/sh\nwhile read line; do\n"
                              "  case \"$line\" in *typo) echo 'Sphere 1 -1 1 360 Sphere';; "
                              "*) echo 'AttributeBegin';; esac\n"
                              "  printf '\\377'\ndone\n");
        Diagnostics diagnostics(false);
        CHECK_THROWS_WITH(
            loadWorld(folder, "Procedural \"RunProgram\" [\"bad.sh\" \"typo\"] [0 0 0 0 0 0]\n", diagnostics),
            Catch::Matchers::StartsWith((folder / "bad.sh").string() + " (output):"));
        CHECK_THROWS_WITH(
            loadWorld(folder, "Procedural \"RunProgram\" [\"bad.sh\" \"open\"] [-1 1 -1 1 -1 1]\n",
                      diagnostics),
            Catch::Matchers::Contains("scene.rib:2:1: Procedural \"RunProgram\" (\"bad.sh\"): its output "
                                      "does not close every AttributeBegin"));
    }
}
