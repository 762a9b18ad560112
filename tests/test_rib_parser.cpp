// The RIB front end: tokens, requests, the graphics state, and located errors.
#include <zip.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "core/Spelling.h"
#include "parse/RibCondition.h"
#include "parse/RibLexer.h"
#include "parse/RibParser.h"
#include "scene/SceneBuilder.h"
#include "scene/shapes/Quadrics.h"
#include "scene/shapes/TriangleMesh.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;
using bxdflab::test::parseRib;

namespace {
/// The message of the RibError the text raises (fails the test if none).
std::string ribErrorOf(std::string const& rib, LoadOptions options = {}) {
    Diagnostics diagnostics(false);
    try {
        parseRib(rib, diagnostics, "bad.rib", options);
    } catch (RibError const& e) {
        return e.what();
    }
    FAIL("expected a RibError for:\n" << rib);
    return {};
}
}  // namespace

TEST_CASE("lexer: the binary encoding -- numbers, strings, float arrays, defined requests and strings", "[rib]") {
    // version 3.05 (float32), request 5 defined as "Sphere", a 1-byte integer,
    // a 2-byte fixed point with one fraction byte (1.5), a float array of two,
    // a string defined as code 1 and then used, and request 5 used.
    std::string bytes = std::string("version") + '\xa4' + std::string("\x40\x43\x33\x33", 4) +
                        std::string("\xcc\x05\x96", 3) + "Sphere" + std::string("\xa6\x05", 2) + '\x80' + '\x02' +
                        std::string("\x85\x01\x80", 3) + std::string("\xc8\x02", 2) +
                        std::string("\x3f\x80\x00\x00\x40\x00\x00\x00", 8) + std::string("\xcd\x01\x91", 3) + "P" +
                        std::string("\xcf\x01", 2);
    RibLexer lexer(bytes, "b.rib");
    CHECK(lexer.next().text == "version");
    CHECK(lexer.next().number == Approx(3.05f));
    RibToken request = lexer.next();
    CHECK(request.kind == RibToken::Kind::Request);
    CHECK(request.text == "Sphere");
    CHECK(lexer.next().number == 2.0);
    CHECK(lexer.next().number == 1.5);
    CHECK(lexer.next().kind == RibToken::Kind::ArrayBegin);
    CHECK(lexer.next().number == 1.0);
    CHECK(lexer.next().number == 2.0);
    CHECK(lexer.next().kind == RibToken::Kind::ArrayEnd);
    RibToken defined = lexer.next();
    CHECK(defined.kind == RibToken::Kind::String);
    CHECK(defined.text == "P");
    CHECK(lexer.next().kind == RibToken::Kind::End);
    CHECK_THROWS_WITH(RibLexer(std::string("\xa6\x09", 2), "c.rib").next(), Catch::Matchers::Contains("before defining it"));
    CHECK_THROWS_WITH(RibLexer(std::string("\xa4\x40", 2), "c.rib").next(), Catch::Matchers::Contains("cut short"));
}

TEST_CASE("lexer: single-quoted strings and strings that span lines", "[rib]") {
    RibLexer lexer("Display 'out.tif' \"a\nb\"", "t.rib");
    lexer.next();
    CHECK(lexer.next().text == "out.tif");
    CHECK(lexer.next().text == "a\nb");
}

TEST_CASE("lexer: a sign after a whole number starts the next one, as in \"Scale 1 1-1\"", "[rib]") {
    RibLexer lexer("Scale 1 1-1 [0.5-.25 2e-3+4 -1.5E+2-7]", "t.rib");
    CHECK(lexer.next().text == "Scale");
    std::vector<double> numbers;
    for (RibToken token = lexer.next(); token.kind != RibToken::Kind::End; token = lexer.next())
        if (token.kind == RibToken::Kind::Number) numbers.push_back(token.number);
    CHECK(numbers == std::vector<double>{1, 1, -1, 0.5, -0.25, 2e-3, 4, -150, -7});
    // The third number begins at its sign: errors and warnings point there.
    RibLexer located("Scale 1 1-1", "t.rib");
    for (int k = 0; k < 3; ++k) located.next();
    CHECK(located.next().location.column == 10);
}

TEST_CASE("lexer: requests, numbers, strings, arrays and comments with positions", "[rib]") {
    RibLexer lexer("Sphere 1 -2.5e1 \"a \\\"q\\\"\" # comment\n[ 3 ]", "t.rib");
    RibToken t = lexer.next();
    CHECK(t.kind == RibToken::Kind::Request);
    CHECK(t.text == "Sphere");
    CHECK(lexer.next().number == 1.0);
    CHECK(lexer.next().number == -25.0);
    RibToken s = lexer.next();
    CHECK(s.kind == RibToken::Kind::String);
    CHECK(s.text == "a \"q\"");
    RibToken open = lexer.next();
    CHECK(open.kind == RibToken::Kind::ArrayBegin);
    CHECK(open.location.line == 2);
    CHECK(open.location.column == 1);
    CHECK(lexer.next().number == 3.0);
    CHECK(lexer.next().kind == RibToken::Kind::ArrayEnd);
    CHECK(lexer.next().kind == RibToken::Kind::End);
}

TEST_CASE("lexer: a file saved with a byte-order mark, Windows or classic Mac OS line ends reads as any other, and "
          "UTF-16 text is named as such", "[rib]") {
    // Each line holds a comment, which ends where the line does.
    for (std::string const end : {"\n", "\r\n", "\r"}) {
        for (std::string const mark : {"", "\xef\xbb\xbf"}) {
            CAPTURE(end.size(), mark.size());
            RibLexer lexer(mark + "Sphere 1 # one" + end + "# two" + end + "  Disk # three" + end + "[ 3 ]", "t.rib");
            RibToken const sphere = lexer.next();
            CHECK(sphere.text == "Sphere");
            CHECK(sphere.location.column == 1);
            CHECK(lexer.next().number == 1.0);
            RibToken const disk = lexer.next();
            CHECK(disk.text == "Disk");
            CHECK(disk.location.line == 3);
            CHECK(disk.location.column == 3);
            RibToken const open = lexer.next();
            CHECK(open.kind == RibToken::Kind::ArrayBegin);
            CHECK(open.location.line == 4);
            CHECK(lexer.next().number == 3.0);
        }
    }
    // A classic Mac OS file renders its sphere and locates its errors by line.
    Diagnostics diagnostics(false);
    Scene scene = parseRib("WorldBegin # the world\rSurface \"matte\"\rSphere 1 -1 1 360\rWorldEnd\r", diagnostics);
    CHECK(scene.shapes.size() == 1u);
    CHECK_THAT(ribErrorOf("WorldBegin # the world\rSphere 1 -1 1\r"), Catch::Matchers::StartsWith("bad.rib:2:1"));
    // UTF-16 text is named as such, little- or big-endian, rather than as a stray binary code.
    for (std::string const mark : {"\xff\xfe", "\xfe\xff"}) {
        std::string const message = ribErrorOf(mark + std::string("W\0o\0r\0l\0d\0", 10));
        CHECK_THAT(message, Catch::Matchers::StartsWith("bad.rib:1:1"));
        CHECK_THAT(message, Catch::Matchers::Contains("UTF-16"));
    }
}

TEST_CASE("malformed RIB gives file:line:col and what was expected", "[rib][errors]") {
    struct Case {
        const char* rib;
        const char* location;
        const char* mentions;
    };
    auto c = GENERATE(values<Case>({
        {"WorldBegin\nSphere 1 -1 1\nWorldEnd", "bad.rib:2:1", "thetamax"},
        {"WorldBegin\n  Sphere 1 -1 \"x\" 360", "bad.rib:2:15", "zmax"},
        // A template's placeholder where a value belongs: the word is named, where it stands.
        {"Format 256 192 1\nShadingRate SR\nWorldBegin", "bad.rib:2:13", "found the word SR, which is not a value"},
        {"PixelSamples SX SY", "bad.rib:1:14", "found the word SX"},
        {"Display \"a.exr\" \"file\" \"rgba\n", "bad.rib:1:24", "unterminated string"},
        {"Format 10 10 1 [1 2", "bad.rib:1:16", "unterminated array"},
        {"AttributeEnd", "bad.rib:1:1", "without a matching AttributeBegin"},
        {"Projection \"perspective\" \"fov\" [200]", "bad.rib:1:26", "between 0 and 180"},
        {"Projection \"perspective\" \"fov\" [0]", "bad.rib:1:26", "between 0 and 180"},
        {"Format 0 10 1", "bad.rib:1:1", "at least 1 pixel"},
        {"Format 100000 100 1", "bad.rib:1:1", "exceeds the limit"},
        {"Format 3e32 100 1", "bad.rib:1:1", "resolution 3e+32 x 100 exceeds the limit"},
        {"WorldBegin\nObjectBegin \"a\"\nObjectInstance \"a\"\nObjectEnd\nObjectInstance \"a\"", "bad.rib:3:1",
         "object \"a\" is used inside its own definition"},
        {"WorldBegin\nArchiveBegin \"x\"\nReadArchive \"y\"\nArchiveEnd\nArchiveBegin \"y\"\nReadArchive \"x\"\n"
         "ArchiveEnd\nReadArchive \"x\"", "bad.rib:6:1", "archive \"x\" is used inside its own definition"},
        {"PixelSamples 0 0", "bad.rib:1:1", "at least 1"},
        {"PixelSamples 1e20 1e20", "bad.rib:1:1", "more than the limit"},
        {"Hider \"raytrace\" \"int maxsamples\" [2000000000]", "bad.rib:1:18", "between 1 and 1048576"},
        {"WorldBegin\nPatchMesh \"bicubic\" 4294967295 \"nonperiodic\" 4 \"nonperiodic\" \"P\" [0 0 0]", "bad.rib:2:21", "fits an int"},
        {"Basis \"bezier\" 3e9 \"bezier\" 3", "bad.rib:1:16", "fits an int"},
        {"Hider \"raytrace\" \"int maxsamples\" [0]", "bad.rib:1:18", "between 1 and"},
        {"Light \"PxrDiskLight\" \"l\" \"blah intensity\" [1]", "bad.rib:1:26", "unknown parameter type"},
        {"WorldBegin\nAreaLightSource \"PxrStdAreaLight\" \"a\"\nGeometry \"spherelight\" \"radius\" [1]", "bad.rib:3:24",
         "\"radius\" has no type"},
        {"WorldBegin\nLight \"PxrDiskLight\" \"l\" \"exposure\" [\"bright\"]", "bad.rib:2:26",
         "\"exposure\" is a float, and its value cannot be one"},
        {"Light \"PxrDiskLight\" \"l\" \"float intensity\" \"x\"", "bad.rib:1:44", "declared float"},
        {"Translate 1e999 0 0", "bad.rib:1:11", "too large for a 32-bit float"},
        // A shell line left at the top of a RIB file (a real one has "set -x"): the whole word is shown.
        {"set -x\nFormat 10 10 1", "bad.rib:1:5", "malformed number '-x'"},
        {"Translate 1.5.2x 0 0", "bad.rib:1:11", "malformed number '1.5.2x'"},
        {"Translate 1--2 0 0", "bad.rib:1:12", "malformed number '--2'"},
        // A letter run on is not a request that follows: no request starts in the middle of a word.
        {"Translate 1e5e3 0 0", "bad.rib:1:11", "malformed number '1e5e3'"},
        {"Sphere 1 -1 1 360A", "bad.rib:1:15", "malformed number '360A'"},
        // A missing closing quote: the next quote closes the string lines later, and the error met
        // after it points back at where the string opened, also across the quotes read the wrong way round.
        {"ReadArchive \"a.rib\nAttributeBegin\nAttribute \"identifier\" \"string name\" [\"x\"]\nReadArchive "
         "\"geo/b.rib\"\nAttributeEnd",
         "bad.rib:4:17", "(the string opened at bad.rib:1:13 runs on past its line: is its closing quote missing?)"},
        {"Translate 1 2e 0", "bad.rib:1:13", "malformed number '2e'"},
        {"WorldBegin\nTranslate 3e38 0 0\nPolygon \"P\" [0 0 0 3e38 0 0 0 1 0]", "bad.rib:3:1", "not finite once transformed"},
        {"WorldBegin\nScale 1e30 1 1\nScale 1e30 1 1", "bad.rib:3:1", "finite"},
        {"WorldBegin\nPointsPolygons [3] [0 1 7] \"P\" [0 0 0 1 0 0 0 1 0]", "bad.rib:2:1", "out of range"},
        {"] Sphere", "bad.rib:1:1", "expected a request name"},
        {"Rotate 30 0 0 0", "bad.rib:1:1", "zero vector"},
        {"Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [3e10]", "bad.rib:1:52", "is an int but has value"},
        {"Attribute \"visibility\" \"float camera\" [3e9]", "bad.rib:1:24", "fits an int"},
        {"WorldBegin\nPointsPolygons [3e9] [0 1 2] \"P\" [0 0 0 1 0 0 0 1 0]", "bad.rib:2:16", "fit an int"},
        {"Scale 1 1 1 \"extra\"", "bad.rib:1:13", "unexpected extra argument"},
    }));
    CAPTURE(c.rib);
    std::string message = ribErrorOf(c.rib);
    CHECK_THAT(message, Catch::Matchers::StartsWith(c.location));
    CHECK_THAT(message, Catch::Matchers::Contains(c.mentions));
}

TEST_CASE("standard names need no type, an unknown untyped name in a skipped request is only a warning", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib("Option \"limits\" \"bucketsize\" [16 16] \"gridsize\" 256\n"
                           "Option \"statistics\" \"endofframe\" 1\nHider \"hidden\" \"jitter\" 1\n"
                           "Option \"mystery\" \"whatever\" [3]\n"
                           "WorldBegin\nAttribute \"bound\" \"displacement\" [0.1]\nAttribute \"trace\" \"bias\" 0.01\n"
                           "Light \"PxrDiskLight\" \"l\" \"strength\" [1]\nSphere 1 -1 1 360\nWorldEnd\n",
                           diagnostics);
    CHECK(scene.shapes.size() == 1);
    bool warnedStrength = false;
    for (auto const& e : diagnostics.entries())
        warnedStrength = warnedStrength || (e.text.find("\"strength\" has no type") != std::string::npos &&
                                            e.text.find("test.rib:8:") == 0);
    CHECK(warnedStrength);
}

TEST_CASE("unknown requests are warned about once with their location, then skipped", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene =
        parseRib("Atmosphere \"fog\"\nAtmosphere \"depthcue\"\nWorldBegin\nSphere 1 -1 1 360\nWorldEnd\n",
                 diagnostics);
    CHECK(scene.shapes.size() == 1);
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 1u);
    CHECK_THAT(warnings[0], Catch::Matchers::StartsWith("test.rib:1:1"));
    CHECK_THAT(warnings[0], Catch::Matchers::Contains("Atmosphere"));
}

TEST_CASE(
    "Matte, GeometricRepresentation and solids: the usual values are read quietly, the others drawn as "
    "surfaces",
    "[rib]") {
    Diagnostics quiet(false);
    CHECK(
        parseRib("WorldBegin\nMatte 0\nGeometricRepresentation \"primitive\"\nSphere 1 -1 1 360\nWorldEnd\n",
                 quiet)
            .shapes.size() == 1);
    CHECK(test::warningsContaining(quiet, "") == 0);
    Diagnostics holdout(false);
    CHECK(parseRib("WorldBegin\nMatte 1\nSphere 1 -1 1 360\nMatte 1\nWorldEnd\n", holdout).shapes.size() ==
          1);
    CHECK(test::warningsContaining(holdout, "Matte 1 (a holdout") == 1);
    Diagnostics wireframe(false);
    CHECK(parseRib("WorldBegin\nGeometricRepresentation \"lines\"\nSphere 1 -1 1 360\nWorldEnd\n", wireframe)
              .shapes.size() == 1);
    CHECK(test::warningsContaining(wireframe, "GeometricRepresentation \"lines\" is not supported") == 1);
    // Solid modelling: a union of primitives is every surface; an intersection is drawn as a union.
    Diagnostics solids(false);
    std::string const unionOf =
        "SolidBegin \"union\"\nSolidBegin \"primitive\"\nSphere 1 -1 1 360\nSolidEnd\n"
        "SolidBegin \"primitive\"\nSphere 2 -2 2 360\nSolidEnd\nSolidEnd\n";
    CHECK(parseRib("WorldBegin\n" + unionOf + "WorldEnd\n", solids).shapes.size() == 2);
    CHECK(test::warningsContaining(solids, "") == 0);
    CHECK(parseRib("WorldBegin\nSolidBegin \"intersection\"\n" + unionOf + "SolidEnd\nWorldEnd\n", solids)
              .shapes.size() == 2);
    CHECK(test::warningsContaining(solids, "SolidBegin \"intersection\" is not supported") == 1);
    CHECK_THROWS_WITH(parseRib("WorldBegin\nSolidEnd\n", solids),
                      Catch::Matchers::StartsWith("test.rib:2:1: SolidEnd: no SolidBegin to match"));
    Diagnostics bad(false);
    CHECK_THROWS_WITH(parseRib("WorldBegin\nMatte 2\n", bad),
                      Catch::Matchers::StartsWith("test.rib:2:1: Matte: onoff must be 0 or 1"));
}

TEST_CASE("Resource saves attributes under a name and restores all of them, the shading or the transform", "[rib]") {
    // Two spheres: one where and as the attributes were saved, one after the restore.
    std::string const saved =
        "WorldBegin\nTranslate 1 0 0\nBxdf \"PxrDiffuse\" \"red\" \"color diffuseColor\" [1 0 0]\n"
        "Resource \"kept\" \"attributes\" \"string operation\" \"save\"\nSphere 1 -1 1 360\n"
        "Translate 0 5 0\nBxdf \"PxrDiffuse\" \"blue\" \"color diffuseColor\" [0 0 1]\n";
    auto restoredIs = [&](std::string const& subset, bool sameMaterial, bool samePlace) {
        Diagnostics quiet(false);
        Scene scene = parseRib(saved + "Resource \"kept\" \"attributes\" \"string operation\" \"restore\"" + subset +
                                   "\nSphere 1 -1 1 360\nWorldEnd\n",
                               quiet);
        REQUIRE(scene.shapes.size() == 2u);
        auto const& first = dynamic_cast<Quadric const&>(*scene.shapes[0]);
        auto const& second = dynamic_cast<Quadric const&>(*scene.shapes[1]);
        CHECK((first.material == second.material) == sameMaterial);
        CHECK((first.objectToWorld() == second.objectToWorld()) == samePlace);
        CHECK(test::warningsContaining(quiet, "") == 0);
    };
    SECTION("all") { restoredIs("", true, true); }
    SECTION("shading") { restoredIs(" \"string subset\" \"shading\"", true, false); }
    SECTION("transform") { restoredIs(" \"string subset\" \"transform\"", false, true); }
    SECTION("ResourceEnd forgets what was saved inside it, and a restore of no saved name is warned about") {
        Diagnostics diagnostics(false);
        Scene scene = parseRib(
            "ResourceBegin\nWorldBegin\nResourceBegin\nResource \"inner\" \"attributes\" \"string operation\" "
            "\"save\"\nResourceEnd\nResource \"inner\" \"attributes\" \"string operation\" \"restore\"\n"
            "Sphere 1 -1 1 360\nWorldEnd\nResourceEnd\n",
            diagnostics);
        CHECK(scene.shapes.size() == 1u);
        CHECK(test::warningTexts(diagnostics) ==
              std::vector<std::string>{"test.rib:6:1: Resource \"inner\": no attributes were saved under this name "
                                       "here; nothing restored"});
    }
    SECTION("other kinds of resource are skipped with a warning; bad operations and unmatched ends are errors") {
        Diagnostics diagnostics(false);
        parseRib("WorldBegin\nResource \"map.tex\" \"texture\" \"string filename\" \"map.tex\"\nWorldEnd\n",
                 diagnostics);
        CHECK(test::warningsContaining(diagnostics, "Resource of type \"texture\" is not a resource") == 1);
        CHECK_THROWS_WITH(parseRib("WorldBegin\nResource \"a\" \"attributes\" \"string operation\" \"keep\"\n",
                                   diagnostics),
                          Catch::Matchers::StartsWith("test.rib:2:1: Resource: \"string operation\" must be"));
        CHECK_THROWS_WITH(
            parseRib("ResourceEnd\n", diagnostics),
            Catch::Matchers::StartsWith("test.rib:1:1: ResourceEnd: no ResourceBegin to match"));
    }
}

TEST_CASE("a name that is no RIB request is told apart from an unsupported one, with the request it was likely meant to be",
          "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib(
        "Atmosphere \"fog\"\nWorldBegin\nTransforBegin\nsphere 1 -1 1 360\nFrobnicate 3\nSphere 1 -1 1 360\n"
        "WorldEnd\n",
        diagnostics);
    CHECK(scene.shapes.size() == 1);
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 4u);
    // A skipped shading request says what it takes out of the image.
    CHECK_THAT(warnings[0], Catch::Matchers::Contains("unsupported request Atmosphere skipped: volumes are not rendered"));
    CHECK_THAT(warnings[1], Catch::Matchers::StartsWith("test.rib:3:1"));
    CHECK_THAT(warnings[1], Catch::Matchers::Contains("TransforBegin is not a RIB request; skipped (did you mean TransformBegin?)"));
    CHECK_THAT(warnings[2], Catch::Matchers::Contains("sphere is not a RIB request; skipped (did you mean Sphere?)"));
    CHECK_THAT(warnings[3], Catch::Matchers::Contains("Frobnicate is not a RIB request; skipped"));
    CHECK_THAT(warnings[3], !Catch::Matchers::Contains("did you mean"));
    Diagnostics displaced(false);
    parseRib("WorldBegin\nDisplace \"PxrDisplace\" \"d\" \"float dispAmount\" [0.1]\nSphere 1 -1 1 360\n", displaced);
    CHECK(test::warningsContaining(displaced, "test.rib:2:1: unsupported request Displace skipped: displacement is "
                                              "not rendered, so surfaces keep their own shape") == 1);
    // RenderMan's request for volume samples (exporters write it in every frame) is a request, not a typo.
    Diagnostics volumeSamples(false);
    parseRib("VolumePixelSamples 1 1\nWorldBegin\nSphere 1 -1 1 360\n", volumeSamples);
    CHECK(test::warningsContaining(volumeSamples, "test.rib:1:1: unsupported request VolumePixelSamples skipped: it "
                                                  "sets how finely volumes are sampled") == 1);
    CHECK(test::warningsContaining(volumeSamples, "not a RIB request") == 0);
    Diagnostics coshader(false);
    parseRib("WorldBegin\nShader \"texturePj\" \"wood\" \"float tiling\" [1]\nSphere 1 -1 1 360\n", coshader);
    CHECK(test::warningsContaining(coshader, "unsupported request Shader skipped: co-shaders are not run") == 1);
}

TEST_CASE("a pbrt scene is named as one at its second pbrt directive, and one stray pbrt word is only a warning", "[rib]") {
    // pbrt's format looks like RIB: without this it stopped at "Integrator: expected integrator handle".
    Diagnostics diagnostics(false);
    CHECK_THROWS_WITH(parseRib("LookAt 1 1 -1  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [50]\n"
                               "Film \"image\" \"integer xresolution\" [450]\nIntegrator \"directlighting\"\n"
                               "WorldBegin\nShape \"sphere\" \"float radius\" [1]\nWorldEnd\n",
                               diagnostics),
                      Catch::Matchers::StartsWith("test.rib:3:1: this looks like a pbrt scene file, not a RIB file: "
                                                  "LookAt (at test.rib:1:1) and Film are pbrt directives"));
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE_FALSE(warnings.empty());
    CHECK_THAT(warnings[0], Catch::Matchers::StartsWith("test.rib:1:1: LookAt is not a RIB request but a directive of "
                                                        "pbrt's scene format"));

    // The same pbrt word twice, in a RIB file, is a warning and the file is read.
    Diagnostics ribDiagnostics(false);
    Scene scene = parseRib("WorldBegin\nMaterial \"matte\"\nSphere 1 -1 1 360\nMaterial \"plastic\"\n"
                           "Sphere 1 -1 1 360\nWorldEnd\n",
                           ribDiagnostics);
    CHECK(scene.shapes.size() == 2u);
    CHECK(test::warningTexts(ribDiagnostics).size() == 1u);
}

TEST_CASE("a misspelt AttributeBegin or TransformBegin is closed by its End as the block it meant, and only then",
          "[rib]") {
    // "TransforBegin" stands in a real Houdini export; RenderMan reads on past it.
    Diagnostics diagnostics(false);
    Scene scene = parseRib("WorldBegin\nAttributeBegin\n  TransforBegin\n    Translate 5 0 0\n  TransformEnd\n"
                           "  Polygon \"P\" [0 0 0 1 0 0 0 1 0]\n"        // after the block: not moved
                           "  AtributeBegin\n    Translate 0 7 0\n    Color [1 0 0]\n  AttributeEnd\n"
                           "  Polygon \"P\" [0 0 0 1 0 0 0 1 0]\n"        // not moved, not red
                           "  Color [1 0 0]\n  Polygon \"P\" [0 0 0 1 0 0 0 1 0]\n"
                           "AttributeEnd\nWorldEnd\n",
                           diagnostics);
    REQUIRE(scene.shapes.size() == 3u);
    for (size_t i = 0; i < 2; ++i) {
        auto const& mesh = dynamic_cast<TriangleMesh const&>(*scene.shapes[i]);
        INFO("polygon " << i);
        for (Vec3 const& p : mesh.data().P) {
            CHECK(p.x >= 0.0f);
            CHECK(p.x <= 1.0f);
            CHECK(p.y >= 0.0f);
            CHECK(p.y <= 1.0f);
        }
    }
    // The colour set inside the attribute block stayed there (the third polygon, red, shows it would tell).
    CHECK(scene.shapes[1]->material == scene.shapes[0]->material);
    CHECK(scene.shapes[2]->material != scene.shapes[0]->material);
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 4u);
    CHECK_THAT(warnings[1], Catch::Matchers::StartsWith("test.rib:5:3: TransformEnd closes the TransforBegin at test.rib:3:3"));
    CHECK_THAT(warnings[3], Catch::Matchers::StartsWith("test.rib:10:3: AttributeEnd closes the AtributeBegin at test.rib:7:3"));

    // Without a misspelt Begin at its depth an unmatched End is still an error.
    Diagnostics strictDiagnostics(false);
    CHECK_THROWS_WITH(parseRib("WorldBegin\nTransforBegin\nTransformBegin\nTransformEnd\nTransformEnd\nTransformEnd\n",
                               strictDiagnostics),
                      Catch::Matchers::StartsWith("test.rib:6:1: TransformEnd: TransformEnd without a matching"));
    CHECK_THROWS_WITH(parseRib("WorldBegin\nAttributeBegin\nTransforBegin\nAttributeEnd\nTransformEnd\n", strictDiagnostics),
                      Catch::Matchers::StartsWith("test.rib:5:1: TransformEnd: TransformEnd without a matching"));
}

TEST_CASE("the spelling hint: at most two letters off, and at most a third of the name", "[rib]") {
    CHECK(closestSpelling("intensty", {"exposure", "intensity"}) == "intensity");
    CHECK(closestSpelling("sphere", {"Sphere", "Cone"}) == "Sphere");  // case is ignored
    CHECK(closestSpelling("AttributeBegn", {"AttributeEnd", "AttributeBegin"}) == "AttributeBegin");
    CHECK(closestSpelling("resultRBG", {"resultRGB", "resultR"}) == "resultRGB");  // a swap is two letters
    CHECK(closestSpelling("Kr", {"Ka", "Kd", "Ks"}).empty());  // one letter of two is another name, not a slip
    CHECK(closestSpelling("Sphre", {"Sphere"}) == "Sphere");
    CHECK(closestSpelling("glow", {"intensity", "exposure"}).empty());
    CHECK(closestSpelling("anything", {}).empty());
}

TEST_CASE("a parameter nobody reads names the one its reader asked for when it is spelled nearly so", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib("WorldBegin\nLight \"PxrDiskLight\" \"l\" \"float intensty\" [10] \"float glow\" [1]\n"
                           "Sphere 1 -1 1 360\nWorldEnd\n",
                           diagnostics);
    CHECK(scene.lights.size() == 1u);
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 2u);
    CHECK_THAT(warnings[0], Catch::Matchers::StartsWith("test.rib:2:"));
    CHECK_THAT(warnings[0], Catch::Matchers::EndsWith("parameter \"intensty\" is not used; ignored (did you mean \"intensity\"?)"));
    CHECK_THAT(warnings[1], Catch::Matchers::EndsWith("parameter \"glow\" is not used; ignored"));  // nothing near it

    // Exporters write every parameter of every light: a name no light reads is said once, for the first.
    Diagnostics many(false);
    std::string lights;
    for (char const* handle : {"key", "fill", "rim"})
        lights += std::string("Light \"PxrRectLight\" \"") + handle +
                  "\" \"color shadowColor\" [0.3 0.3 0.3] \"float shadowFalloff\" [2]\n";
    parseRib("WorldBegin\n" + lights + "Light \"PxrDiskLight\" \"d\" \"color shadowColor\" [0.5 0.5 0.5]\nWorldEnd\n", many);
    std::vector<std::string> const once = test::warningTexts(many);
    REQUIRE(once.size() == 3u);  // the rect lights' two names, and the disk light's own
    CHECK(once[0] == "test.rib:2:28: PxrRectLight \"key\": parameter \"shadowColor\" is not used; ignored");
    CHECK_THAT(once[1], Catch::Matchers::Contains("PxrRectLight \"key\": parameter \"shadowFalloff\""));
    CHECK_THAT(once[2], Catch::Matchers::Contains("PxrDiskLight \"d\": parameter \"shadowColor\""));
}

TEST_CASE("RenderMan's older visibility attributes: transmission as a string, typed or not, and trace", "[rib]") {
    for (std::string const form : {"\"string transmission\" [\"transparent\"]", "\"transmission\" [\"transparent\"]",
                                   "\"transmission\" [\"opaque\"]", "\"int transmission\" [0]"}) {
        CAPTURE(form);
        Diagnostics diagnostics(false);
        Scene scene = parseRib("WorldBegin\nAttribute \"visibility\" " + form + "\nSphere 1 -1 1 360\nWorldEnd\n", diagnostics);
        REQUIRE(scene.shapes.size() == 1u);
        CHECK(scene.shapes[0]->visibility.transmission == (form.find("opaque") != std::string::npos));
        for (auto const& e : diagnostics.entries()) CHECK(e.severity != Diagnostics::Severity::Warning);
    }
    // The same era's "trace" is visibility to reflected and refracted rays.
    Diagnostics diagnostics(false);
    Scene scene = parseRib("WorldBegin\nAttribute \"visibility\" \"trace\" [0]\nSphere 1 -1 1 360\nWorldEnd\n", diagnostics);
    REQUIRE(scene.shapes.size() == 1u);
    CHECK_FALSE(scene.shapes[0]->visibility.indirect);
    CHECK(scene.shapes[0]->visibility.camera);
    CHECK(diagnostics.entries().empty());
}

TEST_CASE("Attribute trace sets a shape's bounce limits: RenderMan's 1 and 2 by default, scoped by blocks", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib("Attribute \"trace\" \"int maxspeculardepth\" [6]\nWorldBegin\nSphere 1 -1 1 360\n"
                           "AttributeBegin\n  Attribute \"trace\" \"maxdiffusedepth\" 3 \"int maxspeculardepth\" [0]\n"
                           "  Sphere 1 -1 1 360\n  Attribute \"trace\" \"int maxdiffusedepth\" [-1]\n"
                           "  Attribute \"trace\" \"float bias\" [0.01]\n  Sphere 1 -1 1 360\nAttributeEnd\n"
                           "Sphere 1 -1 1 360\nWorldEnd\n",
                           diagnostics);
    REQUIRE(scene.shapes.size() == 4u);
    auto limits = [&](size_t k) {
        return std::make_pair(scene.shapes[k]->traceDepth.maxDiffuse, scene.shapes[k]->traceDepth.maxSpecular);
    };
    CHECK(limits(0) == std::make_pair(1, 6));  // set before WorldBegin: holds in the world
    CHECK(limits(1) == std::make_pair(3, 0));
    CHECK(limits(2) == std::make_pair(3, 0));  // a negative depth changes nothing...
    CHECK(limits(3) == std::make_pair(1, 6));  // and the block's end restores what was in effect
    std::vector<std::string> const warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 2u);
    CAPTURE(warnings[0]);
    CHECK(warnings[0].find("test.rib:7:21:") == 0);  // ...with a warning at the parameter
    CHECK(warnings[0].find("is below 0") != std::string::npos);
    CHECK(warnings[1].find("Attribute \"trace\" \"bias\" is not used by this renderer") != std::string::npos);
    Diagnostics defaults(false);
    Scene plain = parseRib("WorldBegin\nSphere 1 -1 1 360\nWorldEnd\n", defaults);
    REQUIRE(plain.shapes.size() == 1u);
    CHECK(plain.shapes[0]->traceDepth.maxDiffuse == 1);
    CHECK(plain.shapes[0]->traceDepth.maxSpecular == 2);
}

TEST_CASE("a whole scene read inside a world: its WorldBegin/WorldEnd and camera requests are warned about and ignored",
          "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib("Display \"mine.exr\" \"file\" \"rgba\"\nProjection \"perspective\" \"fov\" [30]\nWorldBegin\n"
                           "Sphere 1 -1 1 360\n"
                           "ArchiveBegin \"scene\"\n  Display \"other.tif\" \"file\" \"rgba\"\n"
                           "  Projection \"perspective\" \"fov\" [90]\n  WorldBegin\n  Disk 0 1 360\n  WorldEnd\nArchiveEnd\n"
                           "ReadArchive \"scene\"\nCone 1 1 360\nWorldEnd\n",
                           diagnostics);
    REQUIRE(scene.shapes.size() == 3u);  // the sphere, the archive's disk, and the cone after it
    CHECK(scene.camera.fov == Approx(30.0f));
    CHECK(scene.display.name == "mine.exr");
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 3u);
    CHECK_THAT(warnings[0], Catch::Matchers::Contains("Display inside a world block is ignored"));
    CHECK_THAT(warnings[1], Catch::Matchers::Contains("Projection inside a world block is ignored"));
    CHECK_THAT(warnings[2], Catch::Matchers::Contains("WorldBegin inside a world block"));
    // Older test files name their image just after WorldBegin: a first Display is kept.
    Diagnostics quiet(false);
    CHECK(parseRib("WorldBegin\nDisplay \"late.tif\" \"file\" \"rgb\"\nSphere 1 -1 1 360\nWorldEnd\n", quiet).display.name ==
          "late.tif");
    CHECK(quiet.entries().empty());
    // A WorldEnd with no world still stops the file.
    CHECK_THROWS_WITH(parseRib("WorldBegin\nWorldEnd\nWorldEnd\n", diagnostics),
                      Catch::Matchers::Contains("WorldEnd without WorldBegin"));
}

TEST_CASE("Display \"+name\" adds an output to the image in effect, and with none is the image", "[rib]") {
    Diagnostics diagnostics(false);
    // Blender's RIBMosaic writes every frame's only Display with a "+".
    CHECK(parseRib("Display \"+out/frame.exr\" \"openexr\" \"rgba\"\nWorldBegin\nWorldEnd\n", diagnostics).display.name ==
          "out/frame.exr");
    CHECK(diagnostics.entries().empty());
    Scene withAov =
        parseRib("Display \"beauty.exr\" \"file\" \"rgba\"\nDisplay \"+z.exr\" \"file\" \"z\"\nWorldBegin\nWorldEnd\n", diagnostics);
    CHECK(withAov.display.name == "beauty.exr");
    REQUIRE(withAov.moreDisplays.size() == 1);
    CHECK(withAov.moreDisplays[0].name == "z.exr");
    CHECK(withAov.moreDisplays[0].mode == "z");
    CHECK(diagnostics.entries().empty());
    // A shader's output variable is not made here: a further display of one is skipped, and the image's own
    // display of one writes the shaded image; a further framebuffer has no window to show in; a display
    // without "+" replaces all of them.
    Scene skipped = parseRib("Display \"a.exr\" \"file\" \"rgba\"\nDisplay \"+b.exr\" \"file\" \"color myval\"\n"
                             "Display \"+c.exr\" \"framebuffer\" \"N\"\nDisplay \"+d.exr\" \"file\" \"Ci,a,z\"\n"
                             "WorldBegin\nWorldEnd\n",
                             diagnostics);
    REQUIRE(skipped.moreDisplays.size() == 1);
    CHECK(skipped.moreDisplays[0].name == "d.exr");
    CHECK(test::warningsContaining(diagnostics, "Display \"+b.exr\" mode \"color myval\": \"myval\" is not an output "
                                                "this renderer makes") == 1);
    CHECK(test::warningsContaining(diagnostics, "Display \"+c.exr\" \"framebuffer\" would show a further image") == 1);
    Scene replaced = parseRib("Display \"a.exr\" \"file\" \"rgba\"\nDisplay \"+b.exr\" \"file\" \"N\"\n"
                              "Display \"c.exr\" \"file\" \"myval\"\nWorldBegin\nWorldEnd\n",
                              diagnostics);
    CHECK(replaced.display.name == "c.exr");
    CHECK(replaced.display.mode == "rgba");
    CHECK(replaced.moreDisplays.empty());
    CHECK(test::warningsContaining(diagnostics, "the shaded image is written instead") == 1);
}

TEST_CASE("transforms compose the RenderMan way: the last one applies first", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib(
        "Translate 0 0 5\n"  // camera transform: world -> camera
        "WorldBegin\n"
        "  TransformBegin\n"
        "    Translate 1 0 0\n"
        "    Scale 2 2 2\n"
        "    Sphere 1 -1 1 360\n"
        "  TransformEnd\n"
        "  Sphere 1 -1 1 360\n"
        "WorldEnd\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 2);
    CHECK(transformPoint(scene.camera.worldToCamera, Vec3(0)) == Vec3(0, 0, 5));
    auto const& scaled = dynamic_cast<Quadric const&>(*scene.shapes[0]);
    // Scale first, then translate: the point (1,0,0) lands at (3,0,0).
    CHECK(transformPoint(scaled.objectToWorld(), Vec3(1, 0, 0)) == Vec3(3, 0, 0));
    auto const& plain = dynamic_cast<Quadric const&>(*scene.shapes[1]);
    CHECK(transformPoint(plain.objectToWorld(), Vec3(1, 0, 0)) == Vec3(1, 0, 0));
}

TEST_CASE("ConcatTransform reads RIB's row-vector matrices", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib("WorldBegin\nConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1]\nSphere 1 -1 1 360\n",
                           diagnostics);
    auto const& sphere = dynamic_cast<Quadric const&>(*scene.shapes[0]);
    CHECK(transformPoint(sphere.objectToWorld(), Vec3(0)) == Vec3(4, 5, 6));
}

TEST_CASE("typed inline declarations, Declare and option values", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib(
        "Declare \"myfov\" \"float\"\n"
        "Projection \"perspective\" \"uniform float fov\" [33]\n"
        "Format 64 32 1\nPixelSamples 2 3\n"
        "Display \"x.tif\" \"tiff\" \"rgba\"\n"
        "Integrator \"PxrDirectLighting\" \"i\" \"int numLightSamples\" [4]\n",
        diagnostics);
    CHECK(scene.camera.fov == 33.0f);
    CHECK(scene.xres == 64);
    CHECK(scene.yres == 32);
    CHECK(scene.spp == 6);
    CHECK(scene.display.name == "x.tif");
    CHECK(scene.integrator.name == "PxrDirectLighting");
    CHECK(scene.integrator.params.getInt("numLightSamples", 0) == 4);
}

TEST_CASE("instancing: a redefinition inside a replay is safe, and exponential expansion is refused", "[rib][heavy]") {
    Diagnostics diagnostics(false);
    // "a" holds [Sphere, ObjectBegin "a", Disk]: replaying it makes a sphere, then starts a new "a"
    // (recording the Disk, ended by the ObjectEnd after the instance) while the old "a" is still
    // being replayed. The replay must go on with the old list, not a cleared one.
    Scene scene = parseRib("WorldBegin\nObjectBegin \"a\"\nSphere 1 -1 1 360\nObjectBegin \"a\"\nDisk 0 1 360\n"
                           "ObjectEnd\nObjectInstance \"a\"\nObjectEnd\nObjectInstance \"a\"\nWorldEnd\n",
                           diagnostics);
    CHECK(scene.shapes.size() == 2);  // the sphere of the first "a", then the disk of the new one
    // Each object instances the previous one twice: 2^30 spheres if nothing stopped it.
    std::string rib = "WorldBegin\nObjectBegin \"o0\"\nSphere 1 -1 1 360\nObjectEnd\n";
    for (int k = 1; k <= 30; ++k)
        rib += "ObjectBegin \"o" + std::to_string(k) + "\"\nObjectInstance \"o" + std::to_string(k - 1) +
               "\"\nObjectInstance \"o" + std::to_string(k - 1) + "\"\nObjectEnd\n";
    rib += "ObjectInstance \"o30\"\n";
    CHECK_THAT(ribErrorOf(rib), Catch::Matchers::Contains("instancing expands to more than"));
}

TEST_CASE("search paths: & is the path so far, and each folder appears once however often it is repeated", "[rib]") {
    Diagnostics diagnostics(false);
    std::string rib = "Option \"searchpath\" \"string rixplugin\" [\"/a:/b\"]\n";
    for (int k = 0; k < 40; ++k)  // each line would double the path if & were copied blindly
        rib += "Option \"searchpath\" \"string rixplugin\" [\"&:/c:&:@\"]\n";
    Scene scene = parseRib(rib, diagnostics);
    CHECK(scene.pluginSearchPath == std::vector<std::string>{"/a", "/b", "/c"});
}

TEST_CASE("attributes scope visibility, names and materials", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib(
        "WorldBegin\n"
        "AttributeBegin\n"
        "  Attribute \"visibility\" \"int camera\" [0]\n"
        "  Attribute \"identifier\" \"name\" [\"hidden\"]\n"
        "  Bxdf \"diffuse\" \"red\" \"color diffuseColor\" [1 0 0]\n"
        "  Sphere 1 -1 1 360\n"
        "AttributeEnd\n"
        "Sphere 1 -1 1 360\n"
        "AttributeBegin\n"
        "  Attribute \"visibility\" \"int camera\" [0] \"int indirect\" [0] \"int transmission\" [0]\n"
        "  Sphere 1 -1 1 360\n"
        "AttributeEnd\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 2);  // the third is invisible to every ray: dropped
    CHECK_FALSE(scene.shapes[0]->visibility.camera);
    CHECK(scene.shapes[0]->visibility.indirect);
    CHECK(scene.shapes[0]->name == "hidden");
    CHECK(scene.materials[static_cast<size_t>(scene.shapes[0]->material)].handle == "red");
    CHECK(scene.shapes[1]->visibility.camera);
    CHECK(scene.materials[static_cast<size_t>(scene.shapes[1]->material)].plugin == "PxrDiffuse");  // default material
    REQUIRE(scene.dropped.size() == 1);
}

TEST_CASE("an archive named relative to an absolute search-path folder of another machine is found beside the scene",
          "[rib]") {
    // The exporter ran in /exporter-machine/project; the files now sit in <out>/project. The scene,
    // project/shot/scene.rib, reads "shot/geometry/geo.rib" through that search path.
    namespace fs = std::filesystem;
    fs::path const project = fs::path(test::outputDir()) / "archive-search-tail" / "project";
    fs::create_directories(project / "shot" / "geometry");
    std::ofstream(project / "shot" / "geometry" / "geo.rib") << "Sphere 1 -1 1 360\n";
    std::ofstream(project / "shot" / "scene.rib")
        << "Option \"searchpath\" \"archive\" [\"/exporter-machine/project\"]\nWorldBegin\n"
           "ReadArchive \"shot/geometry/geo.rib\"\nWorldEnd\n";
    Diagnostics diagnostics(false);
    Scene scene = loadScene((project / "shot" / "scene.rib").string(), diagnostics);
    CHECK(scene.shapes.size() == 1u);
    CHECK(test::warningsContaining(diagnostics, "the end of its path on the search path "
                                                "(/exporter-machine/project/shot/geometry/geo.rib) found beside the scene") == 1);
}

TEST_CASE("an archive named from the project folder is found from the scene's ancestors when rendering elsewhere",
          "[rib]") {
    // A student project: project/renderRib/scene.rib reads "rib/lights.rib", a path from the
    // project folder it was rendered in. Rendered from anywhere else it still finds it, and says where.
    namespace fs = std::filesystem;
    fs::path const project = fs::path(test::outputDir()) / "archive-from-project" / "project";
    fs::create_directories(project / "rib");
    fs::create_directories(project / "renderRib");
    std::ofstream(project / "rib" / "lights.rib") << "Sphere 1 -1 1 360\n";
    std::ofstream(project / "renderRib" / "scene.rib") << "WorldBegin\nReadArchive \"rib/lights.rib\"\nWorldEnd\n";
    Diagnostics diagnostics(false);
    Scene scene = loadScene((project / "renderRib" / "scene.rib").string(), diagnostics);
    CHECK(scene.shapes.size() == 1u);
    CHECK(test::warningsContaining(diagnostics, "read from the scene's ancestor folder \"" +
                                                    fs::absolute(project).lexically_normal().string() + "\"") == 1);
    // A name found nowhere lists the ancestors it was looked for in.
    std::ofstream(project / "renderRib" / "missing.rib") << "WorldBegin\nReadArchive \"rib/absent.rib\"\nWorldEnd\n";
    Diagnostics missing(false);
    loadScene((project / "renderRib" / "missing.rib").string(), missing);
    CHECK(test::warningsContaining(missing, (fs::absolute(project).lexically_normal() / "rib" / "absent.rib").string()) == 1);
}

TEST_CASE("an archive's name may name variables, as RenderMan for Maya's material presets write",
          "[rib][condition]") {
    // materialSample.rib reads "${MATDIR}/m_shading.rib", MATDIR set by the preset browser.
    namespace fs = std::filesystem;
    fs::path const folder = fs::path(test::outputDir()) / "archive-variables";
    fs::create_directories(folder / "material");
    std::ofstream(folder / "material" / "m_shading.rib") << "Sphere 1 -1 1 360\n";
    Diagnostics diagnostics(false);
    Scene scene = parseRib("Option \"ribparse\" \"string varsubst\" [\"\"]\nOption \"ribparse\" \"string varsubst\" "
                           "[\"$\"]\nOption \"user\" \"string MATDIR\" [\"" + (folder / "material").string() +
                               "\"]\nWorldBegin\nReadArchive \"${MATDIR}/m_shading.rib\"\n"
                               "ReadArchive \"$user:MATDIR/m_shading.rib\"\nWorldEnd\n",
                           diagnostics, "preset.rib");
    CHECK(scene.shapes.size() == 2u);
    CHECK(test::warningsContaining(diagnostics, "") == 0);  // the ribparse options that turn "$" on are read quietly
    Diagnostics other(false);
    parseRib("Option \"ribparse\" \"varsubst\" [\"%\"]\nWorldBegin\nWorldEnd\n", other, "percent.rib");
    CHECK(test::warningsContaining(other, "percent.rib:1:1: Option \"ribparse\" \"varsubst\" [\"%\"]: variables are always "
                                          "written $NAME or ${NAME} here") == 1);
}

TEST_CASE(
    "an empty array (\"int[0] utilityPattern\" [], as RenderMan for Maya writes) is a parameter without "
    "values",
    "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib(
        "WorldBegin\nBxdf \"PxrDiffuse\" \"d\" \"color diffuseColor\" [0.5 0.5 0.5] "
        "\"int[0] utilityPattern\" [] \"string[0] names\" []\nSphere 1 -1 1 360\nWorldEnd\n",
        diagnostics);
    CHECK(scene.shapes.size() == 1u);
    CHECK_THAT(ribErrorOf("WorldBegin\nBxdf \"PxrDiffuse\" \"d\" \"int[0] utilityPattern\" [1 2]\n"),
               Catch::Matchers::StartsWith(
                   "bad.rib:2:47: Bxdf: parameter \"utilityPattern\" is declared as an array of 0 "
                   "but has an array of 2 numbers"));
    CHECK_THAT(ribErrorOf("WorldBegin\nBxdf \"PxrDiffuse\" \"d\" \"int[-1] x\" []\n"),
               Catch::Matchers::Contains("array length must not be negative in 'int[-1]'"));
}

TEST_CASE("an archive rendered as a scene is named as the archive, also when its shapes come from an archive it reads",
          "[rib]") {
    // A student project's bottle.rib reads bottle_geometry.rib outside any world: bottle.rib is the
    // archive the user gave the renderer, and the error names it, at the shape that gave it away.
    namespace fs = std::filesystem;
    fs::path const folder = fs::path(test::outputDir()) / "archive-as-scene";
    fs::create_directories(folder);
    std::ofstream(folder / "bottle_geometry.rib") << "AttributeBegin\n  Sphere 1 -1 1 360\nAttributeEnd\n";
    std::ofstream(folder / "bottle.rib") << "Attribute \"identifier\" \"name\" [\"bottle\"]\nReadArchive \"bottle_geometry.rib\"\n";
    Diagnostics diagnostics(false);
    std::string const outer = (folder / "bottle.rib").string();
    CHECK_THROWS_WITH(loadScene(outer, diagnostics),
                      Catch::Matchers::StartsWith((folder / "bottle_geometry.rib").string() + ":2:3: geometry before any "
                                                  "WorldBegin: \"" + outer + "\", which reads this file outside any world, "
                                                  "is itself an archive"));
    // The archive alone is named as one in so many words.
    Diagnostics alone(false);
    CHECK_THROWS_WITH(loadScene((folder / "bottle_geometry.rib").string(), alone),
                      Catch::Matchers::Contains(":2:3: geometry before any WorldBegin: a file of shapes without a world "
                                                "is an archive"));
}

TEST_CASE("a file that is a Git LFS pointer is named as one: an archive is missing, a scene cannot be read", "[rib]") {
    // A repository cloned without Git LFS holds pointers like this one in place of its large files.
    namespace fs = std::filesystem;
    fs::path const folder = fs::path(test::outputDir()) / "lfs-pointers";
    fs::create_directories(folder);
    std::string const pointer = "version https://git-lfs.github.com/spec/v1\n"
                                "oid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\nsize 104857\n";
    std::ofstream(folder / "geometry.rib") << pointer;
    std::ofstream(folder / "scene.rib") << "WorldBegin\nReadArchive \"geometry.rib\"\nSphere 1 -1 1 360\nWorldEnd\n";
    Diagnostics diagnostics(false);
    Scene scene = loadScene((folder / "scene.rib").string(), diagnostics);
    CHECK(scene.shapes.size() == 1u);  // rendered without the archive, as without a missing one
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 1u);
    CHECK_THAT(warnings[0], Catch::Matchers::Contains("scene.rib:2:1: archive"));
    CHECK_THAT(warnings[0], Catch::Matchers::Contains("geometry.rib\" is a Git LFS pointer, not the RIB file: fetch it"));
    LoadOptions strict;
    strict.strict = true;
    Diagnostics strictDiagnostics(false);
    CHECK_THROWS_WITH(loadScene((folder / "scene.rib").string(), strictDiagnostics, strict),
                      Catch::Matchers::Contains("is a Git LFS pointer"));
    // The scene itself: nothing to render, and a message that says why.
    Diagnostics top(false);
    CHECK_THROWS_WITH(loadScene((folder / "geometry.rib").string(), top),
                      Catch::Matchers::Contains("geometry.rib\" is a Git LFS pointer, not the RIB file"));
    // A RIB file that merely starts with "version" is not one.
    std::ofstream(folder / "versioned.rib") << "version 3.04\nWorldBegin\nSphere 1 -1 1 360\nWorldEnd\n";
    Diagnostics versioned(false);
    CHECK(loadScene((folder / "versioned.rib").string(), versioned).shapes.size() == 1u);
}

namespace {

/// Writes a zip file holding `members` (name, text), as RenderMan for Maya bundles a scene's geometry.
void writeZip(std::filesystem::path const& path, std::vector<std::pair<std::string, std::string>> const& members) {
    std::filesystem::remove(path);
    int error = 0;
    zip_t* archive = zip_open(path.string().c_str(), ZIP_CREATE | ZIP_EXCL, &error);
    REQUIRE(archive != nullptr);
    for (auto const& [name, text] : members) {
        zip_source_t* source = zip_source_buffer(archive, text.data(), text.size(), 0);
        REQUIRE(source != nullptr);
        REQUIRE(zip_file_add(archive, name.c_str(), source, ZIP_FL_ENC_UTF_8) >= 0);
    }
    REQUIRE(zip_close(archive) == 0);  // the buffers are read here, while `members` still holds them
}

}  // namespace

TEST_CASE("archives are read out of zip files (\"bundle.zip!member.rib\"), also through delayed-read procedurals",
          "[rib]") {
    namespace fs = std::filesystem;
    fs::path const folder = fs::path(test::outputDir()) / "zip-archives";
    fs::create_directories(folder / "geo");
    writeZip(folder / "geo" / "cache.zip",
             {{"shapes/sphere.rib", "Sphere 1 -1 1 360\n"}, {"shapes/disk.rib", "Disk 0 2 360\n"},
              {"shapes/broken.rib", "Sphere 1 -1 1 360\nPolygon \"P\" [0 0 0 1 0\n"}});
    auto load = [&](std::string const& world, Diagnostics& diagnostics, LoadOptions options = {}) {
        std::ofstream(folder / "scene.rib") << "WorldBegin\n" << world << "WorldEnd\n";
        return loadScene((folder / "scene.rib").string(), diagnostics, options);
    };
    SECTION("ReadArchive, Procedural \"DelayedReadArchive\" and Procedural2 \"DelayedReadArchive2\" read a member") {
        Diagnostics diagnostics(false);
        Scene scene = load("ReadArchive \"geo/cache.zip!shapes/sphere.rib\"\n"
                           "Procedural \"DelayedReadArchive\" [\"geo/cache.zip!shapes/disk.rib\"] [-2 2 -2 2 0 0]\n"
                           "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" "
                           "[\"geo/cache.zip!shapes/sphere.rib\"] \"float[6] bound\" [-1 1 -1 1 -1 1]\n"
                           // as Python scripts and exporters write it: RenderMan's "__" names are its own
                           "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" "
                           "[\"geo/cache.zip!shapes/sphere.rib\"] \"float[6] __bound\" [-1 1 -1 1 -1 1] "
                           "\"int __immediatesubdivide\" [0]\n",
                           diagnostics);
        REQUIRE(scene.shapes.size() == 4u);
        CHECK(dynamic_cast<Sphere const*>(scene.shapes[0].get()) != nullptr);
        CHECK(dynamic_cast<Sphere const*>(scene.shapes[1].get()) == nullptr);  // the disk
        CHECK(dynamic_cast<Sphere const*>(scene.shapes[2].get()) != nullptr);
        CHECK(test::warningsContaining(diagnostics, "") == 0);
    }
    SECTION("an error inside a member is located in it") {
        Diagnostics diagnostics(false);
        std::string message;
        try {
            load("ReadArchive \"geo/cache.zip!shapes/broken.rib\"\n", diagnostics);
        } catch (RenderError const& e) {
            message = e.what();
        }
        CHECK_THAT(message, Catch::Matchers::Contains("cache.zip!shapes/broken.rib:2:"));
    }
    SECTION("a member that is not there is a warning that says what the zip file holds; --strict makes it an error") {
        Diagnostics diagnostics(false);
        Scene scene = load("ReadArchive \"geo/cache.zip!shapes/cube.rib\"\nSphere 1 -1 1 360\n", diagnostics);
        CHECK(scene.shapes.size() == 1u);
        CHECK(test::warningsContaining(diagnostics, "scene.rib:2:1: archive \"geo/cache.zip!shapes/cube.rib\" not read") == 1);
        CHECK(test::warningsContaining(diagnostics, "has no member \"shapes/cube.rib\"; it holds \"shapes/sphere.rib\"") == 1);
        LoadOptions strict;
        strict.strict = true;
        Diagnostics strictDiagnostics(false);
        CHECK_THROWS_WITH(load("ReadArchive \"geo/cache.zip!shapes/cube.rib\"\n", strictDiagnostics, strict),
                          Catch::Matchers::Contains("has no member"));
    }
    SECTION("a file that is not a zip file says so") {
        std::ofstream(folder / "geo" / "fake.zip") << "Sphere 1 -1 1 360\n";
        Diagnostics diagnostics(false);
        load("ReadArchive \"geo/fake.zip!sphere.rib\"\n", diagnostics);
        CHECK(test::warningsContaining(diagnostics, "as a zip file") == 1);
    }
    SECTION("programs (unless asked for) and plugins a procedural names are not run: one warning, the rest renders") {
        Diagnostics diagnostics(false);
        Scene scene = load("Procedural \"RunProgram\" [\"spiral.py\" \"1 0.2\"] [-5 5 -5 5 -5 5]\n"
                           "Procedural \"RunProgram\" [\"spiral.py\" \"2 0.4\"] [-5 5 -5 5 -5 5]\n"
                           "Procedural \"DynamicLoad\" [\"sphere.so\" \"\"] [-1 1 -1 1 -1 1]\nSphere 1 -1 1 360\n",
                           diagnostics);
        CHECK(scene.shapes.size() == 1u);
        CHECK(test::warningsContaining(diagnostics, "Procedural \"RunProgram\" (\"spiral.py\"): a scene's programs run "
                                                    "only when asked for") == 1);
        CHECK(test::warningsContaining(diagnostics, "Procedural \"DynamicLoad\" (\"sphere.so\"): the plugin is not in any folder "
                                        "searched:\n    " + folder.string()) == 1);
    }
}

TEST_CASE("a RenderMan for Maya export finds its geometry: ${NAME} from Option \"user\", the project a few folders up",
          "[rib]") {
    // <project>/renderman/shot/rib/0001/shot.rib reads renderman/shot/rib/job/cache.zip!... through the
    // search path "${RMSPROJ}:.", where RMSPROJ is the project folder on the exporter's machine.
    namespace fs = std::filesystem;
    fs::path const project = fs::path(test::outputDir()) / "rfm-project";
    fs::path const frame = project / "renderman" / "shot" / "rib" / "0001";
    fs::create_directories(frame);
    fs::create_directories(project / "renderman" / "shot" / "rib" / "job");
    writeZip(project / "renderman" / "shot" / "rib" / "job" / "cache.zip",
             {{"renderman/shot/rib/job/ball.rib", "Sphere 1 -1 1 360\n"}});
    std::ofstream(frame / "shot.rib")
        << "Option \"user\" \"string RMSPROJ\" [\"/Users/someone/project/\"]\n"
           "Option \"searchpath\" \"string archive\" [\"${RMSPROJ}:.\"]\nWorldBegin\n"
           "Procedural2 \"DelayedReadArchive2\" \"SimpleBound\" \"string filename\" "
           "[\"renderman/shot/rib/job/cache.zip!renderman/shot/rib/job/ball.rib\"] \"float[6] bound\" [-1 1 -1 1 -1 1]\n"
           "WorldEnd\n";
    Diagnostics diagnostics(false);
    Scene scene = loadScene((frame / "shot.rib").string(), diagnostics);
    CHECK(scene.shapes.size() == 1u);
    CHECK(test::warningsContaining(diagnostics, "the end of its path on the search path "
                                    "(/Users/someone/project/renderman/shot/rib/job/cache.zip)") == 1);
    CHECK(test::warningsContaining(diagnostics, "Option \"user\"") == 0);  // used, not skipped
}

TEST_CASE("conditional RIB: the first branch whose condition holds is read", "[rib][condition]") {
    // RenderMan for Maya binds materials through such blocks ("shader_bindingstrength"), and
    // picks light rigs and passes by user options.
    Diagnostics diagnostics(false);
    Scene scene = parseRib(
        "Option \"user\" \"string pass\" [\"shadow\"]\nWorldBegin\n"
        "IfBegin \"$user:pass == 'beauty'\"\n  Sphere 1 -1 1 360\n"
        "ElseIf \"$user:pass == 'shadow'\"\n  Disk 0 1 360\n"
        "  IfBegin \"defined(user:nothing)\"\n    Disk 0 2 360\n  IfEnd\n"
        "Else\n  Cone 1 1 360\nIfEnd\n"
        "AttributeBegin\n  Attribute \"user\" \"int shader_bindingstrength\" [1]\n"
        "  IfBegin \"!defined(user:shader_bindingstrength) || $user:shader_bindingstrength <= 0\"\n"
        "    Sphere 2 -2 2 360\n  Else\n    Cylinder 1 -1 1 360\n  IfEnd\nAttributeEnd\n"
        // The attribute ended with its block.
        "IfBegin \"!defined(user:shader_bindingstrength)\"\n  Paraboloid 1 0 1 360\nIfEnd\n"
        // A skipped block's conditions are not read, so this one is not warned about.
        "IfBegin \"0\"\n  IfBegin \"$$$\"\n  IfEnd\nIfEnd\n"
        // One that cannot be read is taken to hold, as files were read before conditions were.
        "IfBegin \"$user:pass ==\"\n  Hyperboloid 1 0 0 1 1 1 360\nElseIf \"1\"\n  Sphere 1 -1 1 "
        "360\nIfEnd\n",
        diagnostics, "cond.rib");
    REQUIRE(scene.shapes.size() == 4u);
    CHECK(dynamic_cast<Disk const*>(scene.shapes[0].get()) != nullptr);
    CHECK(dynamic_cast<Cylinder const*>(scene.shapes[1].get()) != nullptr);
    CHECK(dynamic_cast<Paraboloid const*>(scene.shapes[2].get()) != nullptr);
    CHECK(dynamic_cast<Hyperboloid const*>(scene.shapes[3].get()) != nullptr);
    CHECK(test::warningsContaining(diagnostics,
                                   "cond.rib:28:1: IfBegin/ElseIf \"$user:pass ==\": a value is missing "
                                   "at the end (at character 14); the condition is taken to hold") == 1);
    CHECK(test::warningsContaining(diagnostics, "") == 1);
    CHECK_THAT(ribErrorOf("WorldBegin\nSphere 1 -1 1 360\nIfEnd\n"), Catch::Matchers::StartsWith("bad.rib:3:1: IfEnd without"));
    CHECK_THAT(ribErrorOf("WorldBegin\nElse\n"), Catch::Matchers::StartsWith("bad.rib:2:1: Else without"));
    CHECK_THAT(ribErrorOf("WorldBegin\nElseIf \"1\"\n"),
               Catch::Matchers::StartsWith("bad.rib:2:1: ElseIf without"));

    SECTION("the frame number, and a branch after Else") {
        Diagnostics frames(false);
        Scene framed = parseRib(
            "FrameBegin 3\nWorldBegin\nIfBegin \"$Frame == 3\"\n  Sphere 1 -1 1 360\n"
            "Else\n  Disk 0 1 360\nElseIf \"1\"\n  Cone 1 1 360\nIfEnd\nWorldEnd\nFrameEnd\n",
            frames, "frames.rib");
        REQUIRE(framed.shapes.size() == 1u);
        CHECK(dynamic_cast<Sphere const*>(framed.shapes[0].get()) != nullptr);
        CHECK(test::warningsContaining(frames,
                                       "frames.rib:7:1: ElseIf after Else: its branch is never read") == 1);
    }
}

TEST_CASE("conditions: values, comparisons, defined() and regular expressions", "[rib][condition]") {
    std::map<std::string, std::string> const variables = {
        {"user:pass", "beauty"}, {"user:strength", "0"}, {"user:count", "9"}, {"RMSTREE", "/opt/rfm"}};
    VariableLookup const lookup = [&](std::string const& name) -> std::optional<std::string> {
        auto found = variables.find(name);
        if (found == variables.end()) return std::nullopt;
        return found->second;
    };
    auto holds = [&](std::string const& condition) { return evaluateCondition(condition, lookup); };
    CHECK(holds("1"));
    CHECK_FALSE(holds("0"));
    CHECK_FALSE(holds("''"));
    CHECK(holds("'beauty' == 'beauty'"));
    CHECK(holds("$user:pass == 'beauty'"));
    CHECK(holds("${user:pass} == \"beauty\""));
    CHECK_FALSE(holds("$user:pass != 'beauty'"));
    CHECK(holds("$user:nothing == ''"));  // not set: empty
    CHECK_FALSE(holds("defined(user:nothing)"));
    CHECK(holds("defined(RMSTREE) && !defined(RMSPROJ_FROM_ENV)"));
    CHECK(holds("defined($RMSTREE)"));
    // Numbers compare as numbers (as text "9" would come after "10"), other values as text.
    CHECK(holds("$user:count < 10"));
    CHECK(holds("$user:count >= 9.0"));
    CHECK(holds("'abc' < 'abd'"));
    CHECK_FALSE(holds("'nan' == 'inf'"));  // words, not numbers
    CHECK(holds("'inf' == 'inf'"));
    CHECK(holds("!defined(user:strength) || $user:strength <= 0"));
    CHECK_FALSE(holds("!defined(user:strength) || $user:strength > 0"));
    // ! binds after the comparison it stands before, && before ||.
    CHECK(holds("!$user:pass == 'shadow'"));
    CHECK(holds("1 || 0 && 0"));
    CHECK_FALSE(holds("(1 || 0) && 0"));
    CHECK(holds("!(1 && 0)"));
    CHECK(holds("$user:pass =~ '^bea'"));
    CHECK_FALSE(holds("$user:pass =~ 'x$'"));
    CHECK(holds("$RMSTREE =~ '/(opt|usr)/'"));
    // A pattern that backtracking matchers take exponential time over.
    CHECK_FALSE(holds("'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa' =~ '(a*)*b'"));

    auto errorOf = [&](std::string const& condition) -> ConditionError {
        try {
            evaluateCondition(condition, lookup);
        } catch (ConditionError const& e) {
            return e;
        }
        return {std::string::npos, "no error"};
    };
    CHECK(errorOf("$user:pass ==").offset == 13);
    CHECK(errorOf("'beauty").message == "this string has no closing quote");
    CHECK(errorOf("1 1").message == "unexpected '1'");
    CHECK(errorOf("(1").message == "')' expected");
    CHECK(errorOf("beauty").offset == 0);
    CHECK(errorOf("$user:pass =~ '('").message == "'(' is not a regular expression");
    CHECK(errorOf("$user:pass =~ '('").offset == 14);
    CHECK(errorOf("${user:pass").message == "'${' has no closing '}'");
    CHECK(errorOf("defined()").message == "a variable's name is expected here");
}

TEST_CASE("what 1990s RIB files write: mpoint, a standard name as a shader's own, blobby leaves, numbered objects",
          "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = parseRib(
        "WorldBegin\n"
        // PRMan's "mpoint" (a matrix per blobby primitive) and a plugin field left out of nleaf.
        "Blobby 1 [1001 0  1004 0 0 0 0 0  0 2 0 1] [1 0 0 0  0 1 0 0  0 0 1 0  0 0 5 1] [\"\"] "
        "\"vertex mpoint Pref\" [1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1]\n"
        // "frequency" is also a standard attribute name (a string): here it is the shader's number.
        "Surface \"KMStarfield\" \"frequency\" 3\n"
        "ObjectBegin 2\nSphere 1 -1 1 360\nObjectEnd\nObjectInstance 2\n",
        diagnostics);
    CHECK(scene.shapes.size() == 2u);
    CHECK_THAT(ribErrorOf("WorldBegin\nObjectInstance 7\n"), Catch::Matchers::Contains("no object \"7\" was defined"));
    // After an archive that is not found, an object it may have defined is warned about, not fatal.
    Diagnostics lenient(false);
    Scene rest = parseRib("WorldBegin\nReadArchive \"objects.rib\"\nObjectInstance 1\nSphere 1 -1 1 360\n", lenient);
    CHECK(rest.shapes.size() == 1u);
    CHECK(test::warningsContaining(lenient, "no object \"1\" was defined with ObjectBegin (perhaps in the archive") == 1);
}

TEST_CASE("a standard int name given a fraction is a plugin's own parameter: PxrDisney's or a light's specular 0.5",
          "[rib]") {
    // "specular" is also the visibility attribute's int; a Bxdf or a light means its own float by it.
    auto mean = [](std::string const& specular) {
        std::string rib = "Format 16 16 1\nWorldBegin\nBxdf \"PxrDisney\" \"d\" " + specular +
                          "\nSphere 1 -1 1 360\nWorldEnd\n";
        return test::meanChannel(test::renderRib(rib, test::withSpp(2)), 0, [](int, int) { return true; });
    };
    double const typed = mean("\"float specular\" [0.5]");
    CHECK(mean("\"specular\" [0.5]") == typed);
    CHECK(mean("\"specular\" [0]") < typed);
    Diagnostics diagnostics(false);
    Scene scene = parseRib("WorldBegin\nLight \"PxrRectLight\" \"key\" \"specular\" [0.5] \"diffuse\" [0.25]\n", diagnostics);
    REQUIRE(scene.lights.size() == 1u);
    CHECK(scene.lights[0]->specularMultiplier == 0.5f);
    CHECK(scene.lights[0]->diffuseMultiplier == 0.25f);
    // Where the standard name is meant, a fraction is still an error.
    CHECK_THAT(ribErrorOf("WorldBegin\nAttribute \"visibility\" \"specular\" [0.5]\n"),
               Catch::Matchers::Contains("parameter \"specular\" is an int but has value 0.5"));
}

TEST_CASE("a missing archive, sky image or texture is a warning naming what was tried, --strict makes it an error",
          "[rib]") {
    LoadOptions strict;
    strict.strict = true;
    std::string message = ribErrorOf("WorldBegin\nReadArchive \"nowhere.rib\"\n", strict);
    CHECK_THAT(message, Catch::Matchers::StartsWith("bad.rib:2:1"));
    CHECK_THAT(message, Catch::Matchers::Contains("nowhere.rib"));
    CHECK_THAT(message, Catch::Matchers::Contains("tried"));
    // A name the file system refuses outright (longer than any file name) is not found either.
    std::string longName(5000, 'x');
    CHECK_THAT(ribErrorOf("WorldBegin\nReadArchive \"" + longName + "\"\n", strict), Catch::Matchers::Contains("not found"));
    CHECK_THAT(ribErrorOf("WorldBegin\nLight \"PxrDomeLight\" \"d\" \"string lightColorMap\" [\"" + longName + "\"]\n", strict),
               Catch::Matchers::Contains("does not exist"));
    // A device is not an archive, strict or not.
    CHECK_THAT(ribErrorOf("WorldBegin\nReadArchive \"/dev/zero\"\n"), Catch::Matchers::Contains("not a regular file"));

    // A texture a used pattern or classic shader names: located at its parameter.
    std::string const texture = "WorldBegin\nPattern \"PxrTexture\" \"t\" \"string filename\" [\"no-such.tx\"]\n"
                                "Bxdf \"PxrDiffuse\" \"d\" \"reference color diffuseColor\" [\"t:resultRGB\"]\n"
                                "Sphere 1 -1 1 360\nWorldEnd\n";
    CHECK_THAT(ribErrorOf(texture, strict), Catch::Matchers::StartsWith("bad.rib:2:26: Pattern \"PxrTexture\" \"t\": "
                                                                        "texture \"no-such.tx\" does not exist"));
    CHECK_THAT(ribErrorOf("WorldBegin\nSurface \"paintedplastic\" \"texturename\" \"no-such.tex\"\nSphere 1 -1 1 360\n",
                          strict),
               Catch::Matchers::StartsWith("bad.rib:2:26: Surface \"paintedplastic\": texture \"no-such.tex\" does not exist"));

    // Without --strict the scene is read on, as RenderMan does, with one located warning each.
    Diagnostics diagnostics(false);
    Scene scene = parseRib("WorldBegin\nReadArchive \"nowhere.rib\"\nLight \"PxrDomeLight\" \"d\" \"string lightColorMap\" "
                           "[\"no-sky.exr\"]\nSphere 1 -1 1 360\n",
                           diagnostics, "lenient.rib");
    CHECK(scene.shapes.size() == 1u);
    REQUIRE(scene.lights.size() == 1u);  // the dome light, with its plain colour
    std::vector<std::string> warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 2u);
    CHECK_THAT(warnings[0], Catch::Matchers::StartsWith("lenient.rib:2:1:") && Catch::Matchers::Contains("tried"));
    CHECK_THAT(warnings[1], Catch::Matchers::StartsWith("lenient.rib:3:1:") &&
                                Catch::Matchers::Contains("\"no-sky.exr\" does not exist (looked for from the current folder"));
    Diagnostics textureWarnings(false);
    Scene textured = parseRib(texture, textureWarnings, "lenient.rib");
    CHECK(textured.missingTextures == std::set<std::string>{"no-such.tx"});
    CHECK(test::warningTexts(textureWarnings).size() == 1u);

    // An exporter's scene read without its archive files: each missing one is named, the places
    // tried only for the first three (a MayaMan scene names 52, nine places each).
    Diagnostics many(false);
    parseRib("WorldBegin\nReadArchive \"a1\"\nReadArchive \"a2\"\nReadArchive \"a3\"\nReadArchive \"a4\"\n"
             "ReadArchive \"a5\"\n",
             many, "lenient.rib");
    std::vector<std::string> missing = test::warningTexts(many);
    REQUIRE(missing.size() == 5u);
    for (size_t i = 0; i < 5; ++i) {
        INFO(missing[i]);
        CHECK_THAT(missing[i], Catch::Matchers::Contains("archive \"a" + std::to_string(i + 1) + "\" not found"));
        CHECK((missing[i].find("tried:") != std::string::npos) == (i < 3));
        CHECK((missing[i].find('\n') == std::string::npos) == (i >= 3));
    }
    CHECK_THAT(missing[4], Catch::Matchers::Contains("(looked for as the archives above)"));
    // Each place once: the folder of the file that names it is the one the renderer runs in here.
    bool const namesBoth = missing[0].find("\n    a1\n") != std::string::npos &&
                           missing[0].find("\n    ./a1\n") != std::string::npos;
    CHECK_FALSE(namesBoth);
}
