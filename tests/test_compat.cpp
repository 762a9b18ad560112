// RIB as exporters write it: a file full of unsupported requests renders with
// one located warning per kind; quadrics, patch meshes and instancing. (The
// corpus of real-world files is checked file by file: tests/compat.)
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "scene/SceneBuilder.h"
#include "scene/shapes/TriangleMesh.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

struct FileRender {
    std::vector<float> rgba;
    std::vector<Diagnostics::Entry> messages;
};

FileRender renderFile(std::string const& path) {
    Diagnostics diagnostics(false);
    Scene scene = loadScene(path, diagnostics);
    RenderSettings settings;
    settings.spp = 1;
    FileRender out;
    {
        Renderer renderer(scene, settings, diagnostics);
        out.rgba = renderer.render().rgba();
    }
    out.messages = diagnostics.entries();
    return out;
}

void checkSensible(FileRender const& r) {
    double lit = 0.0;
    for (size_t i = 0; i < r.rgba.size(); ++i) {
        REQUIRE(std::isfinite(r.rgba[i]));
        if (i % 4 != 3) lit = std::max(lit, static_cast<double>(r.rgba[i]));
    }
    CHECK(lit > 0.05);  // something visible and lit
}

}  // namespace

TEST_CASE("an exporter's RIB with many unsupported requests renders with one located warning per kind", "[compat]") {
    FileRender r = renderFile(std::string(TEST_SCENES_DIR) + "/dcc-export.rib");
    checkSensible(r);
    std::set<std::string> warnings;
    for (auto const& m : r.messages)
        if (m.severity == Diagnostics::Severity::Warning) {
            CHECK_THAT(m.text, Catch::Matchers::Contains("dcc-export.rib:"));  // located
            warnings.insert(m.text);
        }
    // Six kinds of statement it does not use, some repeated: each kind once. Its
    // Attribute "user" and IfBegin are read (conditions use them), its trace depth is
    // read, its depth display is made and its Quantize accepted, so none of them is
    // warned about (its trace "bias" is).
    CHECK(warnings.size() <= 22u);
    CHECK(warnings.size() >= 6u);
    for (auto const& w : warnings) {
        CHECK(w.find("IfBegin") == std::string::npos);
        CHECK(w.find("Attribute \"user\"") == std::string::npos);
        CHECK(w.find("Display") == std::string::npos);
        CHECK(w.find("Quantize") == std::string::npos);
        CHECK(w.find("maxdiffusedepth") == std::string::npos);
    }
    int dice = 0;  // Attribute "dice" is written three times
    for (auto const& w : warnings) dice += w.find("Attribute \"dice\"") != std::string::npos;
    CHECK(dice == 1);
}

TEST_CASE("quadrics, patch meshes, instances and inline archives", "[compat]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "WorldBegin\n"
        "Cone 2 1 360\nParaboloid 1 0 2 360\nHyperboloid 1 0 0.5 1 0 -0.5 270\nTorus 1 0.25 0 360 360\n"
        "Basis \"catmull-rom\" 1 \"b-spline\" 1\n"
        "PatchMesh \"bicubic\" 5 \"nonperiodic\" 4 \"nonperiodic\" \"P\" ["
        "0 0 0 1 0 0 2 0 0 3 0 0 4 0 0  0 1 0 1 1 1 2 1 0 3 1 1 4 1 0  0 2 0 1 2 1 2 2 0 3 2 1 4 2 0  0 3 0 1 3 0 2 3 0 3 3 0 4 3 0]\n"
        "ObjectBegin \"ball\"\n  Sphere 1 -1 1 360\nObjectEnd\n"
        "Translate 5 0 0\nObjectInstance \"ball\"\nTranslate 5 0 0\nObjectInstance \"ball\"\n"
        "ArchiveBegin \"ring\"\n  Disk 0 1 360\nArchiveEnd\nReadArchive \"ring\"\n"
        "WorldEnd\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 4u + 1u + 2u + 1u);
    CHECK(std::string(scene.shapes[0]->kind()) == "Cone");
    CHECK(std::string(scene.shapes[4]->kind()) == "PatchMesh");
    CHECK(std::string(scene.shapes[5]->kind()) == "Sphere");
    // Without a Bxdf the surfaces use the stock PxrDiffuse.
    CHECK(scene.materials[static_cast<size_t>(scene.shapes[0]->material)].plugin == "PxrDiffuse");
    // The catmull-rom x b-spline mesh has (5-4+1) x (4-4+1) = 2 patches of 12x12 quads.
    auto const& mesh = dynamic_cast<TriangleMesh const&>(*scene.shapes[4]);
    CHECK(mesh.data().triangleCount() == 2u * 12u * 12u * 2u);
}
