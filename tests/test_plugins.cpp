// Plugins: book-style code works, and every way a plugin can be missing or
// broken gives a clear message instead of a crash.
#include <catch2/catch.hpp>
#include <sstream>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "RixBxdfLobe.h"
#include "shade/PluginLoader.h"
#include "shade/PluginSearchPath.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;
using Catch::Matchers::Contains;

namespace {
const std::string kLitSphere =
    "Format 24 24 1\nProjection \"perspective\" \"fov\" [25]\n"
    "Integrator \"PxrDirectLighting\" \"d\"\n"
    "WorldBegin\n  AttributeBegin\n  Translate 0 2 4\n  Rotate 90 1 0 0\n"
    "  Light \"PxrDiskLight\" \"key\" \"float intensity\" [30]\n  AttributeEnd\n"
    "  Translate 0 0 5\n  BXDF\n  Sphere 1 -1 1 360\nWorldEnd\n";

std::string withBxdf(std::string const& bxdf) {
    std::string rib = kLitSphere;
    return rib.replace(rib.find("BXDF"), 4, bxdf);
}

std::string renderError(std::string const& rib) {
    try {
        test::renderRib(rib);
    } catch (RenderError const& e) {
        return e.what();
    }
    FAIL("expected a RenderError");
    return {};
}
}  // namespace

TEST_CASE("a plugin written in the course text's style compiles, loads and matches the solution", "[plugins]") {
    RenderSettings settings;
    settings.spp = 64;
    auto book = test::renderRib(withBxdf("Bxdf \"bookdiffuse\" \"b\" \"color diffuse_color\" [0.7 0.7 0.7]"), settings);
    auto solution = test::renderRib(withBxdf("Bxdf \"diffuse\" \"s\" \"color diffuseColor\" [0.7 0.7 0.7]"), settings);
    auto all = [](int, int) { return true; };
    double bookMean = test::meanChannel(book, 0, all), solutionMean = test::meanChannel(solution, 0, all);
    CHECK(bookMean > 0.01);
    CHECK(bookMean == Approx(solutionMean).epsilon(0.01));
    CHECK(book.stats.tangentPoints > 0u);  // it asks for Tn, so tangents were computed

    auto glowing = test::renderRib(withBxdf("Bxdf \"bookdiffuse\" \"g\" \"color emissive_color\" [1 0 0] \"color diffuse_color\" [0 0 0]"));
    CHECK(glowing.channel(12, 12, 0) == 1.0f);
    CHECK(glowing.channel(12, 12, 1) == 0.0f);
}

TEST_CASE("a sample tagged by assigning the looked-up lobe is valid as in RenderMan's examples", "[plugins]") {
    // RenderMan's example Bxdfs (and LAIKA's) write lobeSampled[i] = s_lobe and no SetValid(true):
    // the lobe RixBXLookupLobeByName gives is valid, so the path goes on from it.
    RixBXLobeSampled nothing;
    CHECK_FALSE(nothing.GetValid());
    RixBXLobeSampled const diffuse(false, false, true, false, 1, 0);
    CHECK(diffuse.GetValid());
    CHECK((RixBXLobeTraits::All() & RixBXLobeTraits(diffuse)) == RixBXLobeTraits(diffuse));  // a set, not a sample

    std::string rib = withBxdf("Bxdf \"BOOK\" \"b\" \"color diffuse_color\" [0.7 0.7 0.7]");
    rib.replace(rib.find("\"PxrDirectLighting\""), 19, "\"PxrPathTracer\"");
    rib.replace(rib.find("WorldBegin\n"), 11, "WorldBegin\n  Patch \"bilinear\" \"P\" [-9 -1 0 9 -1 0 -9 -1 20 9 -1 20]\n");
    RenderSettings settings;
    settings.spp = 64;
    auto told = test::renderRib(std::string(rib).replace(rib.find("BOOK"), 4, "bookdiffuse"), settings);
    auto assigned = test::renderRib(std::string(rib).replace(rib.find("BOOK"), 4, "bookdiffuse_assigns"), settings);
    CHECK(told.stats.indirectRays > 0u);
    CHECK(assigned.stats.indirectRays == told.stats.indirectRays);
    auto all = [](int, int) { return true; };
    CHECK(test::meanChannel(assigned, 0, all) == Approx(test::meanChannel(told, 0, all)).epsilon(1e-6));
}

TEST_CASE("a missing plugin names itself and every folder searched", "[plugins][errors]") {
    std::string message = renderError(withBxdf("Bxdf \"nosuchplugin\" \"x\""));
    CHECK_THAT(message, Contains("test.rib:11:3"));
    CHECK_THAT(message,
               Contains("\"nosuchplugin\" not found: no nosuchplugin.so"));  // nothing near enough to suggest
    CHECK_THAT(message, Contains(TEST_PLUGIN_DIR));
    CHECK_THAT(message, Contains("plugins/solutions"));
}

TEST_CASE("a plugin named in another case is found as a file system that ignores case finds it, with a warning",
          "[plugins]") {
    // Scenes written on macOS or Windows say "PXRDisney" for PxrDisney.so.
    auto asSpelled = test::renderRib(withBxdf("Bxdf \"diffuse\" \"s\" \"color diffuseColor\" [0.7 0.7 0.7]"));
    auto otherCase = test::renderRib(withBxdf("Bxdf \"Diffuse\" \"s\" \"color diffuseColor\" [0.7 0.7 0.7]"));
    CHECK_FALSE(asSpelled.anyMessageContains("is spelled"));
    CHECK(otherCase.anyMessageContains("test.rib:11:3: Bxdf plugin \"Diffuse\" is spelled \"diffuse\" on the plugin search path"));
    for (int y = 0; y < 24; y += 3)
        for (int x = 0; x < 24; x += 3) CHECK(otherCase.channel(x, y, 0) == asSpelled.channel(x, y, 0));
    // Only a name that no folder has as spelled: a name that differs in more than case is still not found.
    // It is suggested, as the name of a plugin on the path.
    CHECK_THAT(renderError(withBxdf("Bxdf \"Difuse\" \"x\"")),
               Contains("\"Difuse\" not found (did you mean \"diffuse\"?)"));
}

TEST_CASE("broken plugins are refused with the reason", "[plugins][errors]") {
    struct Case {
        const char* plugin;
        const char* reason;
    };
    auto c = GENERATE(values<Case>({
        {"probe_no_create", "does not export CreateRixBxdfFactory"},
        {"probe_null_table", "GetParamTable returned null"},
        {"probe_unterminated_table", "has no end marker RixSCParamInfo() in its first 1024 entries"},
        {"probe_bad_table_entry", "parameter table entry 1 has an empty name"},
        {"probe_unclosed_struct", "the parameter table's struct \"manifold\" has no k_RixSCStructEnd row"},
        {"probe_instance_table", "a parameter table of its own in CreateInstanceData (InstanceData::paramtable)"},
        {"probe_stale_api", "was built against Rix API version 1, this renderer provides version"},
    }));
    CAPTURE(c.plugin);
    std::string message = renderError(withBxdf(std::string("Bxdf \"") + c.plugin + "\" \"x\""));
    CHECK_THAT(message, Contains(c.plugin));
    CHECK_THAT(message, Contains(c.reason));
}

TEST_CASE("two plugins that share a factory class name and so one parameter table are refused, naming both",
          "[plugins][errors]") {
    // Each alone renders its own parameter.
    auto a = test::renderRib(withBxdf("Bxdf \"sameclass_a\" \"a\" \"color glow_a\" [1 0 0]"));
    CHECK(a.channel(12, 12, 0) == 1.0f);
    // Together, the second hands back the first one's table: refused, at the statement that named it.
    std::string both = withBxdf("Bxdf \"sameclass_a\" \"a\" \"color glow_a\" [1 0 0]\n"
                                "AttributeBegin\nBxdf \"sameclass_b\" \"b\" \"color glow_b\" [0 1 0]\n"
                                "Sphere 0.5 -0.5 0.5 360\nAttributeEnd");
    std::string message = renderError(both);
    CHECK_THAT(message, Contains("plugin \"sameclass_b\""));
    CHECK_THAT(message, Contains("GetParamTable returned the table of another plugin"));
    CHECK_THAT(message, Contains("sameclass_a.so"));
    CHECK_THAT(message, Contains("BxdfFactory::GetParamTable()"));
    CHECK_THAT(message, Contains("test.rib:"));
}

TEST_CASE("a file that is not a shared object is refused with its path and the reason", "[plugins][errors]") {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(test::outputDir()) / "corrupt-plugin";
    fs::create_directories(dir);
    {
        std::ofstream garbled(dir / "garbled.so");
        for (int line = 0; line < 100; ++line) garbled << "this text is not an ELF shared object\n";
    }
    RenderSettings settings;
    settings.pluginPath = dir.string();
    std::string message;
    try {
        test::renderRib(withBxdf("Bxdf \"garbled\" \"x\""), settings);
    } catch (RenderError const& e) {
        message = e.what();
    }
    CHECK_THAT(message, Contains((dir / "garbled.so").string()));
    CHECK_THAT(message, Contains("invalid ELF header"));
}

TEST_CASE("parameters are checked against the plugin's table", "[plugins][errors]") {
    CHECK_THAT(renderError(withBxdf("Bxdf \"diffuse\" \"x\" \"float diffuseColor\" [1]")),
               Contains("\"diffuseColor\" is a color, but the RIB gives a float"));
    auto r = test::renderRib(withBxdf("Bxdf \"diffuse\" \"x\" \"color difuseColor\" [1 0 0]"));
    CHECK(r.anyMessageContains("has no parameter \"difuseColor\""));
    CHECK(r.anyMessageContains("(did you mean \"diffuseColor\"? its parameters: diffuseColor"));
    // A name nothing like any parameter gets the list alone.
    auto far = test::renderRib(withBxdf("Bxdf \"diffuse\" \"x\" \"color albedo\" [1 0 0]"));
    CHECK(far.anyMessageContains("has no parameter \"albedo\"; ignored (its parameters: diffuseColor"));
    // Written without a type, a parameter takes the plugin's, as RenderMan types a shader's
    // parameters from the shader; values that cannot be that type are a located error.
    auto untyped = test::renderRib(withBxdf("Bxdf \"diffuse\" \"x\" \"diffuseColor\" [0.25 0.5 1]"));
    auto typed = test::renderRib(withBxdf("Bxdf \"diffuse\" \"x\" \"color diffuseColor\" [0.25 0.5 1]"));
    CHECK(untyped.rgba == typed.rgba);
    CHECK_FALSE(untyped.anyMessageContains("diffuseColor"));
    CHECK_THAT(renderError(withBxdf("Bxdf \"diffuse\" \"x\" \"diffuseColor\" [0.25 0.5]")),
               Contains("\"diffuseColor\" is a color, and its value cannot be one (write \"color diffuseColor\" with 3 numbers)"));
    CHECK_THAT(renderError(withBxdf("Bxdf \"diffuse\" \"x\" \"diffuseColor\" \"red\"")),
               Contains("\"diffuseColor\" is a color, and its value cannot be one"));
}

TEST_CASE("plugin search order: command line, environment, RIB option, ini file, built-in", "[plugins]") {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(test::outputDir()) / "searchpath";
    fs::create_directories(dir);
    {
        std::ofstream ini(dir / "rixrender.ini");
        ini << "# plugin folders for scenes in this folder\n/standardrixpluginpath  mine:/abs/theirs\n";
    }
    setenv("RIX_PLUGIN_PATH", "/env/a:/env/b", 1);
    auto path = pluginSearchPath({"/cli/x", {"/rib/y"}, (dir / "scene.rib").string()});
    unsetenv("RIX_PLUGIN_PATH");
    REQUIRE(path.size() >= 7u);
    CHECK(path[0] == "/cli/x");
    CHECK(path[1] == "/env/a");
    CHECK(path[2] == "/env/b");
    CHECK(path[3] == "/rib/y");
    CHECK(path[4] == (dir / "mine").lexically_normal().string());
    CHECK(path[5] == "/abs/theirs");
    CHECK_THAT(path.back(), Contains("plugins/stock"));
}

TEST_CASE("integrators are plugins: a missing one names the folders searched, a bad parameter is located",
          "[plugins][errors]") {
    std::string rib = kLitSphere;
    rib.replace(rib.find("BXDF"), 4, "Bxdf \"diffuse\" \"d\"");
    std::string missing = rib;
    missing.replace(missing.find("Integrator \"PxrDirectLighting\" \"d\""), 34, "Integrator \"PxrNoSuchThing\" \"x\"");
    std::string message = renderError(missing);
    CHECK_THAT(message, Contains("test.rib:3:1"));
    CHECK_THAT(message, Contains("Integrator plugin \"PxrNoSuchThing\" not found"));
    CHECK_THAT(message, Contains("plugins/integrators"));
    // A name one letter off a plugin on the path: the hint finds it.
    std::string misspelt = rib;
    misspelt.replace(misspelt.find("Integrator \"PxrDirectLighting\" \"d\""), 34,
                     "Integrator \"PxrPathTracr\" \"x\"");
    CHECK_THAT(renderError(misspelt),
               Contains("\"PxrPathTracr\" not found (did you mean \"PxrPathTracer\"?)"));
    // RenderMan's debugging view without its last letter is rendered by it, with a warning.
    std::string visualize = rib;
    visualize.replace(visualize.find("Integrator \"PxrDirectLighting\" \"d\""), 34,
                      "Integrator \"PxrVisualize\" \"x\" \"int wireframe\" [0]");
    auto shortName = test::renderRib(visualize);
    CHECK(shortName.anyMessageContains(
        "test.rib:3:1: Integrator \"PxrVisualize\": RenderMan's integrator is spelled"));
    CHECK_FALSE(shortName.anyMessageContains("tessellation"));  // PxrVisualizer read its parameters
    // What an integrator says as it reads its parameters is placed at its statement.
    visualize.replace(visualize.find("\"int wireframe\" [0]"), 19, "\"string style\" [\"matcap\"]");
    CHECK(test::renderRib(visualize).anyMessageContains("test.rib:3:1: plugin PxrVisualizer: style matcap"));
    std::string bad = rib;
    bad.replace(bad.find("Integrator \"PxrDirectLighting\" \"d\""), 34,
                "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [-2]");
    message = renderError(bad);
    CHECK_THAT(message, Contains("test.rib:3:1"));
    CHECK_THAT(message, Contains("numLightSamples must be between 0 and 4096"));
}

TEST_CASE("a plugin in the course text's style (SetValid only, pdfs left unwritten) renders like the solution",
          "[plugins][api][heavy]") {
    // The chapter 6 scene, with the text-style Bxdf in place of the solution.
    std::string solution = test::readScene("ch06/diffuse.rib"), textStyle = solution;
    textStyle.replace(textStyle.find("Bxdf \"diffuse\""), 14, "Bxdf \"textdiffuse\"");
    RenderSettings settings;
    settings.spp = 16;
    auto mine = test::renderRib(textStyle, settings, "text.rib");
    settings.pluginPath = SOLUTION_PLUGIN_DIR;
    auto reference = test::renderRib(solution, settings, "solution.rib");
    CHECK(mine.stats.invalidPdfSamples == 0);
    CHECK(mine.stats.nonFiniteSamples == 0);
    int warnings = 0;
    for (auto const& m : mine.messages) warnings += m.severity == Diagnostics::Severity::Warning;
    CHECK(warnings == 0);
    auto all = [](int, int) { return true; };
    double a = test::meanChannel(mine, 0, all), b = test::meanChannel(reference, 0, all);
    CHECK(a == Approx(b).epsilon(0.02));
    // No fireflies: no pixel far brighter than the brightest of the solution's render.
    float brightest = 0.0f, brightestMine = 0.0f;
    for (int y = 0; y < mine.height; ++y)
        for (int x = 0; x < mine.width; ++x) {
            brightest = std::max(brightest, reference.channel(x, y, 0));
            brightestMine = std::max(brightestMine, mine.channel(x, y, 0));
        }
    CHECK(brightestMine < 1.5f * brightest);
}
