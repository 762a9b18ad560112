// What older and exported RIB files need from the scene reader: frames,
// motion blocks, named coordinate systems, the RI defaults, classic surface
// shaders, negative quadric radii and general polygons.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "accel/RayTracer.h"
#include "scene/Camera.h"
#include "scene/SceneBuilder.h"
#include "scene/ShaderSource.h"
#include "scene/lights/MeshLight.h"
#include "scene/shapes/Curves.h"
#include "scene/shapes/Quadrics.h"
#include "scene/shapes/TriangleMesh.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

HitRecord trace(RayTracer const& tracer, Vec3 org, Vec3 dir) {
    RayCounts counts;
    return tracer.intersect(org, glm::normalize(dir), 0.0f, kInfinity, 0.0f, RayKind::Camera, counts);
}

/// How far along +z from `org` a ray meets the one shape `shape` (a line after WorldBegin) makes,
/// -1 for a miss; `normal`, when given, receives the shading normal there. The shape must read
/// without a warning.
float distanceAlongZ(std::string const& shape, Vec3 org, Vec3* normal = nullptr) {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\n" + shape, diagnostics);
    CHECK(diagnostics.entries().empty());
    REQUIRE(scene.shapes.size() == 1u);
    RayTracer tracer(scene);
    HitRecord h = trace(tracer, org, Vec3(0, 0, 1));
    if (!h.hit()) return -1.0f;
    if (normal) *normal = scene.shapes[0]->basics(h).N;
    return h.t;
}

std::string const kTwoFrames =
    "FrameBegin 1\n  Display \"a.exr\" \"file\" \"rgba\"\n  Format 32 16 1\n  Projection \"perspective\" \"fov\" [40]\n"
    "  WorldBegin\n    Sphere 1 -1 1 360\n  WorldEnd\nFrameEnd\n"
    "FrameBegin 2\n  Display \"b.exr\" \"file\" \"rgba\"\n  Translate 0 0 3\n"
    "  WorldBegin\n    Disk 0 1 360\n    Disk 1 1 360\n  WorldEnd\nFrameEnd\n";

/// The mean red and the mean blue of a render of `rib` at 4 samples a pixel.
using RedAndBlue = std::pair<double, double>;
RedAndBlue meanRedAndBlue(std::string const& rib) {
    auto r = test::renderRib(rib, test::withSpp(4));
    auto all = [](int, int) { return true; };
    return {test::meanChannel(r, 0, all), test::meanChannel(r, 2, all)};
}

}  // namespace

TEST_CASE("each frame is its own scene: options, camera and world, none piled on another", "[rib][frames]") {
    Diagnostics diagnostics(false);
    Scene scene;
    SceneBuilder builder(scene, diagnostics);
    struct Seen {
        int frame;
        std::string display, projection;
        int xres;
        size_t shapes;
        float cameraZ;
    };
    std::vector<Seen> frames;
    builder.setFrameSink([&](Scene& f) {
        frames.push_back({f.frame, f.display.name, f.camera.projection, f.xres, f.shapes.size(),
                          f.camera.worldToCamera[3][2]});
    });
    builder.readText(kTwoFrames, "frames.rib");
    REQUIRE(frames.size() == 2u);
    CHECK(frames[0].frame == 1);
    CHECK(frames[0].display == "a.exr");
    CHECK(frames[0].projection == "perspective");
    CHECK(frames[0].xres == 32);
    CHECK(frames[0].shapes == 1u);
    CHECK(frames[0].cameraZ == 0.0f);
    // Frame 2 starts from the options outside the frames: the first frame's Format and Projection are gone.
    CHECK(frames[1].frame == 2);
    CHECK(frames[1].display == "b.exr");
    CHECK(frames[1].projection == "orthographic");  // the RI default, as nothing outside the frames set one
    CHECK(frames[1].xres == 640);
    CHECK(frames[1].shapes == 2u);
    CHECK(frames[1].cameraZ == 3.0f);

    // Asking for one frame builds that one only.
    LoadOptions second;
    second.frame = 2;
    Scene only = test::parseRib(kTwoFrames, diagnostics, "frames.rib", second);
    CHECK(only.frame == 2);
    CHECK(only.shapes.size() == 2u);
}

TEST_CASE("without a Shutter, a motion block is seen at its first time, without a word", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nMotionBegin [0 1]\n  Translate 2 0 0\n  Translate 9 0 0\nMotionEnd\n"
                                 "Sphere 1 -1 1 360\nMotionBegin [0 0.5 1]\n Sphere 1 -1 1 360\n Sphere 3 -3 3 360\n"
                                 " Sphere 5 -5 5 360\nMotionEnd\n",
                                 diagnostics);
    REQUIRE(scene.shapes.size() == 2u);
    RayTracer tracer(scene);
    HitRecord hit = trace(tracer, Vec3(2, 0, -10), Vec3(0, 0, 1));
    REQUIRE(hit.hit());
    CHECK(hit.t == Approx(9.0f).epsilon(1e-5));  // the sphere of radius 1 at x = 2
    CHECK_FALSE(scene.shapes[0]->moves());
    // The shutter opens and closes at 0 (RenderMan's default): nothing is lost by not blurring.
    CHECK(diagnostics.entries().empty());
}

TEST_CASE("named coordinate systems: CoordinateSystem, ScopedCoordinateSystem and CoordSysTransform", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "WorldBegin\nAttributeBegin\n  Translate 0 0 5\n  CoordinateSystem \"table\"\nAttributeEnd\n"
        "AttributeBegin\n  Translate 7 0 0\n  ScopedCoordinateSystem \"aside\"\n"
        "  Identity\n  CoordSysTransform \"aside\"\n  Sphere 1 -1 1 360\nAttributeEnd\n"
        "CoordSysTransform \"table\"\nSphere 1 -1 1 360\nCoordSysTransform \"aside\"\nDisk 0 1 360\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 3u);
    auto center = [&](size_t i) { return transformPoint(dynamic_cast<Quadric const&>(*scene.shapes[i]).objectToWorld(), Vec3(0)); };
    CHECK(center(0).x == Approx(7.0f));
    CHECK(center(1).z == Approx(5.0f));
    // "aside" was scoped to its attribute block: outside it, the transform is left as it was (with a warning).
    CHECK(center(2).z == Approx(5.0f));
    CHECK(test::warningsContaining(diagnostics, "no coordinate system \"aside\"") == 1);
}

TEST_CASE("Skew shears what follows: its first axis turns towards its second by the angle", "[rib]") {
    auto skewed = [](std::string const& skew, Vec3 point) {
        Diagnostics diagnostics(false);
        Scene scene = test::parseRib("WorldBegin\n" + skew + "\nSphere 1 -1 1 360\n", diagnostics);
        REQUIRE(scene.shapes.size() == 1u);
        return transformPoint(dynamic_cast<Quadric const&>(*scene.shapes[0]).objectToWorld(), point);
    };
    // The y axis leans 45 degrees towards x; points on the x axis and off the plane stay.
    Vec3 const y = skewed("Skew 45 0 1 0 1 0 0", Vec3(0, 1, 0));
    CHECK(y.x == Approx(1.0f));
    CHECK(y.y == Approx(1.0f));
    CHECK(y.z == Approx(0.0f).margin(1e-6));
    CHECK(skewed("Skew 45 0 1 0 1 0 0", Vec3(2, 0, 0)).x == Approx(2.0f));
    CHECK(skewed("Skew 45 0 1 0 1 0 0", Vec3(0, 0, 3)).z == Approx(3.0f));
    CHECK(skewed("Skew -30 0 1 0 1 0 0", Vec3(0, 1, 0)).x == Approx(-std::tan(glm::radians(30.0f))));
    // Axes that are not square to each other: (1 1 0) is 45 degrees from x, and 15 after turning
    // 30 degrees towards it, keeping its height above the x axis.
    Vec3 const diagonal = skewed("Skew 30 1 1 0 1 0 0", Vec3(1, 1, 0));
    CHECK(diagonal.y == Approx(1.0f));
    CHECK(glm::degrees(std::atan2(diagonal.y, diagonal.x)) == Approx(15.0f));
    // The axis cannot be turned onto the line of the other, nor can axes that are one line.
    Diagnostics bad(false);
    CHECK_THROWS_WITH(
        test::parseRib("WorldBegin\nSkew 90 0 1 0 1 0 0\n", bad),
        Catch::Matchers::Contains("test.rib:2:1: Skew: the axes are 90 degrees apart, so the angle must "
                                  "lie between -90 and 90 (not 90)"));
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nSkew -140 1 1 0 1 0 0\n", bad),
                      Catch::Matchers::Contains("must lie between -135 and 45 (not -140)"));
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nSkew 10 1 0 0 -2 0 0\n", bad),
                      Catch::Matchers::Contains("Skew: the two axes are parallel"));
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nSkew 10 0 0 0 1 0 0\n", bad),
                      Catch::Matchers::Contains("Skew: an axis is the zero vector"));
}

TEST_CASE("Bound is a hint for renderers that dice: read without a word", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "WorldBegin\nBound [-1 1 -1 1 -1 1]\nBound -1 1 -1 1 -1 1\nSphere 1 -1 1 360\n", diagnostics);
    CHECK(scene.shapes.size() == 1u);
    CHECK(diagnostics.warningCount() == 0);
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nBound [-1 1 -1 1]\n", diagnostics),
                      Catch::Matchers::Contains("test.rib:2:7: Bound: expected 6 numbers"));
}

TEST_CASE("a shape with no surface is skipped with one warning a kind, as RenderMan draws nothing for it",
          "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "WorldBegin\nSphere 0 -1 1 360\nSphere 0 -1 1 360\nDisk 0 0 360\n"
        "Cylinder 0 -1 1 360\nParaboloid 0 0 1 360\nParaboloid 1 -1 0 360\n"
        "Hyperboloid 1 0 0 1 0 0 360\nTorus 1 0 0 360 360\nSphere 1 -1 1 360\n",
        diagnostics);
    CHECK(scene.shapes.size() == 1u);  // the last sphere alone
    // One warning for each of the six kinds, each at its first statement.
    CHECK(diagnostics.warningCount() == 6);
    auto said = [&](std::string const& text) {
        for (auto const& entry : diagnostics.entries())
            if (entry.text == text) return true;
        return false;
    };
    CHECK(said("test.rib:2:1: Sphere with radius 0 describes no surface; skipped"));
    CHECK(said("test.rib:6:1: Paraboloid with rmax 0 describes no surface; skipped"));
    CHECK(said("test.rib:9:1: Torus with a radius 0 describes no surface; skipped"));
    // A polygon of two points is a line, and a mesh's face of two points no more: the rest of the mesh is
    // drawn.
    Scene polygons = test::parseRib(
        "WorldBegin\nPolygon \"P\" [0 0 0 1 0 0]\n"
        "PointsPolygons [3 2] [0 1 2 0 1] \"P\" [0 0 0 1 0 0 0 1 0]\n",
        diagnostics);
    REQUIRE(polygons.shapes.size() == 1u);
    CHECK(said("test.rib:2:1: Polygon with fewer than 3 vertices describes no surface; skipped"));
    CHECK(said(
        "test.rib:3:1: PointsPolygons with a face of fewer than 3 vertices describes no surface; skipped"));
    RayTracer tracer(polygons);
    CHECK(trace(tracer, Vec3(0.2f, 0.2f, -5.0f), Vec3(0, 0, 1)).hit());
    // A negative radius is not an empty surface: the torus still says what it needs.
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nTorus 1 -0.5 0 360 360\n", diagnostics),
                      Catch::Matchers::Contains("test.rib:2:1: Torus: radii must be positive"));
}

TEST_CASE("a cone of height 0 is the disk it stands on", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nCone 0 1 360\n", diagnostics);
    REQUIRE(scene.shapes.size() == 1u);
    CHECK(std::string(scene.shapes[0]->kind()) == "Disk");
    CHECK(diagnostics.entries().empty());
    RayTracer tracer(scene);
    HitRecord inside = trace(tracer, Vec3(0.5f, 0.25f, -5.0f), Vec3(0, 0, 1));
    REQUIRE(inside.hit());
    CHECK(inside.t == Approx(5.0f).epsilon(1e-5));
    CHECK_FALSE(trace(tracer, Vec3(1.2f, 0.0f, -5.0f), Vec3(0, 0, 1)).hit());  // past the radius
}

TEST_CASE("Rotate by 0 needs no axis, in or out of a motion block", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "Shutter 0 1\nWorldBegin\nRotate 0 0 0 0\nTranslate 2 0 0\nSphere 1 -1 1 360\n"
        "MotionBegin [0 1]\n  Rotate 0 0 0 0\n  Rotate 90 0 0 1\nMotionEnd\n"
        "Sphere 1 -1 1 360\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 2u);
    CHECK(diagnostics.entries().empty());
    RayTracer tracer(scene);
    HitRecord hit = trace(tracer, Vec3(2, 0, -10), Vec3(0, 0, 1));
    REQUIRE(hit.hit());
    CHECK(hit.t == Approx(9.0f).epsilon(1e-5));
    CHECK_FALSE(scene.shapes[0]->moves());
    CHECK(scene.shapes[1]->moves());  // the block's two steps: no turn, then a quarter turn
    CHECK_THROWS_WITH(test::parseRib("Rotate 30 0 0 0\n", diagnostics),
                      Catch::Matchers::Contains("only a rotation by 0 may have no axis"));
}

TEST_CASE("a surface shader of the scene's own is rendered as the standard one its name or its Ks suggests, else as matte",
          "[rib][classic]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nColor [0 1 0]\nLightSource \"ambientlight\" 1 \"intensity\" [0.2]\n"
                                 "Surface \"RCPlastic\" \"Ks\" [.5] \"Kd\" [.4] \"roughness\" [.2] \"Kr\" [1]\nSphere 1 -1 1 360\n"
                                 "Surface \"LGRustyMetal\" \"metalKa\" [1]\nSphere 1 -1 1 360\n"
                                 "Surface \"wood2\" \"Ks\" [.3] \"ringscale\" [10]\nSphere 1 -1 1 360\n"
                                 "Surface \"TLconstantMap\" \"mapname\" [\"\"]\nSphere 1 -1 1 360\n"
                                 "Surface \"GNember\"\nSphere 1 -1 1 360\n"
                                 "Surface \"specsurf\" \"float Ka\" 1 \"float Kd\" 0.8 \"float Kr\" 0.5\n"
                                 "Sphere 1 -1 1 360\n",
                                 diagnostics);
    REQUIRE(scene.shapes.size() == 6u);
    auto materialOf = [&](size_t i) -> MaterialDesc const& {
        return scene.materials[static_cast<size_t>(scene.shapes[i]->material)];
    };
    CHECK(materialOf(0).params.getString("shader", "") == "plastic");
    CHECK(materialOf(0).params.getFloat("Kd", 0.0f) == 0.4f);
    CHECK(materialOf(0).params.getFloat("roughness", 0.0f) == 0.2f);
    CHECK_FALSE(materialOf(0).params.has("Kr"));  // its own parameters stay behind, without a warning each
    CHECK(materialOf(1).params.getString("shader", "") == "metal");
    CHECK(materialOf(2).params.getString("shader", "") == "plastic");
    CHECK(materialOf(3).params.getString("shader", "") == "constant");
    // Neither a name nor a Ks to go by: matte, which most shaders of a scene's own grew from (its
    // Ka * ambient() then lit by the scene's ambientlight, as theirs would be).
    CHECK(materialOf(4).params.getString("shader", "") == "matte");
    CHECK(materialOf(4).params.getColor("ambient", Vec3(0.0f)).y > 0.0f);
    CHECK(materialOf(5).params.getString("shader", "") == "matte");
    CHECK(materialOf(5).params.getFloat("Kd", 0.0f) == 0.8f);
    CHECK(materialOf(5).params.getFloat("Ka", 0.0f) == 1.0f);
    CHECK_FALSE(materialOf(5).params.has("Kr"));
    CHECK(test::warningsContaining(diagnostics, "test.rib:4:1: Surface \"RCPlastic\" is a shader this renderer does not "
                                                "have: rendered as \"plastic\", the standard one its name suggests") == 1);
    CHECK(test::warningsContaining(diagnostics, "Surface \"wood2\" is a shader this renderer does not have: rendered as "
                                                "\"plastic\", the standard one its specular weight Ks suggests") == 1);
    CHECK(test::warningsContaining(diagnostics, "Surface \"GNember\" is a shader this renderer does not have: rendered "
                                                "as \"matte\", the standard shader most shaders of a scene's own grew "
                                                "from") == 1);
    CHECK(test::warningsContaining(diagnostics, "has no parameter") == 0);
}

TEST_CASE("Surface naming one of RenderMan's Bxdfs says how a Bxdf is given", "[rib]") {
    Diagnostics diagnostics(false);
    test::parseRib("WorldBegin\nSurface \"PxrDisney\"\nSphere 1 -1 1 360\n", diagnostics);
    CHECK(test::warningsContaining(diagnostics, "test.rib:2:1: Surface \"PxrDisney\" is a shader this renderer does "
                                                "not have") == 1);
    CHECK(test::warningsContaining(diagnostics, "; \"PxrDisney\" is a Bxdf, given with Bxdf \"PxrDisney\" "
                                                "\"handle\"") == 1);
    // RenderMan's Lama family is named by its prefix too; a shader of a scene's own gets no such hint.
    Diagnostics lama(false);
    test::parseRib("WorldBegin\nSurface \"LamaDiffuse\"\nSphere 1 -1 1 360\nSurface \"myDisney\"\nSphere 1 -1 1 360\n",
                   lama);
    CHECK(test::warningsContaining(lama, "\"LamaDiffuse\" is a Bxdf, given with Bxdf") == 1);
    CHECK(test::warningsContaining(lama, "\"myDisney\" is a Bxdf") == 0);
}

TEST_CASE("a glass shader of a scene's own says that it renders opaque", "[rib]") {
    Diagnostics diagnostics(false);
    test::parseRib("WorldBegin\nSurface \"glass\" \"float ior\" [1.5]\nSphere 1 -1 1 360\n"
                   "Surface \"CT\" \"float Ks\" [0.1]\nSphere 1 -1 1 360\n"
                   "Surface \"thinfilm\" \"float eta\" [1.33]\nSphere 1 -1 1 360\n",
                   diagnostics);
    CHECK(test::warningsContaining(diagnostics, "the light it refracts is not rendered, so it is opaque") == 2);
    CHECK(test::warningsContaining(diagnostics, "Surface \"CT\" is a shader this renderer does not have: rendered as "
                                                "\"plastic\"") == 1);
}

TEST_CASE("ColorSamples: colours are written with its numbers and read as the RGB its nRGB gives", "[rib]") {
    auto materialOf = [](Scene const& scene, size_t shape) -> MaterialDesc const& {
        return scene.materials[static_cast<size_t>(scene.shapes.at(shape)->material)];
    };
    Diagnostics diagnostics(false);
    // One sample, a grey: a colour is one number (no "given one number" warning: that is its size now).
    Scene grey = test::parseRib(
        "ColorSamples [1 1 1] [.3 .59 .11]\nWorldBegin\nColor [0.5]\nOpacity 0.75\n"
        "Surface \"matte\"\nSphere 1 -1 1 360\n"
        "Bxdf \"PxrDiffuse\" \"d\" \"color diffuseColor\" [0.25]\nSphere 1 -1 1 360\n",
        diagnostics);
    CHECK(diagnostics.entries().empty());
    CHECK(materialOf(grey, 0).params.getColor("surfaceColor", Vec3(0)) == Vec3(0.5f));
    CHECK(materialOf(grey, 0).params.getColor("surfaceOpacity", Vec3(0)) == Vec3(0.75f));
    CHECK(materialOf(grey, 1).params.getColor("diffuseColor", Vec3(0)) == Vec3(0.25f));
    // Two samples, one red and one blue; an array of two colours takes four numbers.
    Scene two = test::parseRib(
        "ColorSamples [1 0 0  0 0 1] [1 0  0 0  0 1]\nWorldBegin\nColor 0.2 0.7\n"
        "Surface \"matte\"\nSphere 1 -1 1 360\n"
        "Bxdf \"PxrDiffuse\" \"d\" \"color diffuseColor\" [0.4 0.6]\nSphere 1 -1 1 360\n",
        diagnostics);
    CHECK(materialOf(two, 0).params.getColor("surfaceColor", Vec3(0)) == Vec3(0.2f, 0.0f, 0.7f));
    CHECK(materialOf(two, 1).params.getColor("diffuseColor", Vec3(0)) == Vec3(0.4f, 0.0f, 0.6f));
    CHECK_THROWS_WITH(
        test::parseRib("ColorSamples [1 0 0  0 0 1] [1 0  0 0  0 1]\nWorldBegin\nColor [1 0 0]\n",
                       diagnostics),
        Catch::Matchers::Contains("test.rib:3:7") && Catch::Matchers::Contains("expected 2 numbers"));
    CHECK_THROWS_WITH(
        test::parseRib("ColorSamples [1 1 1] [1 1]\n", diagnostics),
        Catch::Matchers::Contains("ColorSamples needs nRGB and RGBn of 3 numbers per colour sample each"));
    // An option, it ends with its frame: the next frame writes colours as RGB again.
    LoadOptions second;
    second.frame = 2;
    Scene after = test::parseRib("FrameBegin 1\nColorSamples [1 1 1] [.3 .59 .11]\nWorldBegin\nColor [0.5]\n"
                                 "Surface \"matte\"\nSphere 1 -1 1 360\nWorldEnd\nFrameEnd\n"
                                 "FrameBegin 2\nWorldBegin\nColor [0.1 0.2 0.3]\nSurface \"matte\"\n"
                                 "Sphere 1 -1 1 360\nWorldEnd\nFrameEnd\n",
                                 diagnostics, "frames.rib", second);
    CHECK(materialOf(after, 0).params.getColor("surfaceColor", Vec3(0)) == Vec3(0.1f, 0.2f, 0.3f));
}

TEST_CASE("classic Surface shaders become the ClassicSurface Bxdf with the Color in effect, a Bxdf wins", "[rib]") {
    // A scene's own copy of a standard shader ("shaders/plastic") is read as the standard one, with a warning.
    for (std::string const folder : {"", "shaders/"}) {
        CAPTURE(folder);
        Diagnostics diagnostics(false);
        std::string const rib = "WorldBegin\nColor [1 0 0]\nSurface \"" + folder + "plastic\" \"Ks\" [0.7]\n" +
                                "Sphere 1 -1 1 360\nSurface \"" + folder + "wobbly\"\nSphere 1 -1 1 360\n" +
                                "Surface \"matte\"\nBxdf \"PxrDiffuse\" \"d\"\nSphere 1 -1 1 360\n";
        Scene scene = test::parseRib(rib, diagnostics);
        CHECK(test::warningsContaining(diagnostics, "test.rib:3:1: Surface \"shaders/plastic\" is a shader file of "
                                                    "the scene's own") == (folder.empty() ? 0 : 1));
        REQUIRE(scene.shapes.size() == 3u);
        MaterialDesc const& plastic = scene.materials[static_cast<size_t>(scene.shapes[0]->material)];
        CHECK(plastic.plugin == "ClassicSurface");
        CHECK(plastic.params.getString("shader", "") == "plastic");
        CHECK(plastic.params.getFloat("Ks", 0.0f) == 0.7f);
        CHECK(plastic.params.getColor("surfaceColor", Vec3(0)) == Vec3(1, 0, 0));
        // An unknown shader: one warning, and the standard matte in the current Color.
        MaterialDesc const& unknown = scene.materials[static_cast<size_t>(scene.shapes[1]->material)];
        CHECK(unknown.plugin == "ClassicSurface");
        CHECK(unknown.params.getString("shader", "") == "matte");
        CHECK(unknown.params.getColor("surfaceColor", Vec3(0)) == Vec3(1, 0, 0));
        CHECK(test::warningsContaining(diagnostics, "Surface \"" + folder + "wobbly\"") == 1);
        CHECK(scene.materials[static_cast<size_t>(scene.shapes[2]->material)].plugin == "PxrDiffuse");
        CHECK(scene.materials[static_cast<size_t>(scene.shapes[2]->material)].handle == "d");
    }
}

TEST_CASE("a classic shader takes a shape's own Cs, and a negative component of it reflects nothing",
          "[rib]") {
    // Files give Cs data for their own shaders (renderman.org's toon examples: a red below 0); the standard
    // shaders standing in read it as a colour, and no channel of the image goes below black.
    RenderSettings settings;
    settings.spp = 1;
    auto r = test::renderRib(
        "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\nWorldBegin\n"
        "Translate 0 0 5\nSurface \"constant\"\nPatch \"bilinear\" \"P\" [-1 -1 0  1 -1 0  -1 1 0  1 1 0] "
        "\"varying color Cs\" [-0.5 0.25 1  -0.5 0.25 1  -0.5 0.25 1  -0.5 0.25 1]\n",
        settings);
    for (int x : {1, 6}) {
        CHECK(r.channel(x, 4, 0) == 0.0f);
        CHECK(r.channel(x, 4, 1) == Approx(0.25f));
        CHECK(r.channel(x, 4, 2) == Approx(1.0f));
    }
}

TEST_CASE("a classic shader's parameters are its own: others are warned about by the shader's name", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nSurface \"metal\" \"Kd\" [0.5] \"roughnes\" [0.2] \"Ks\" [0.8] "
                                 "\"string __materialid\" [\"m\"]\nSphere 1 -1 1 360\n"
                                 "Surface \"shinymetal\" \"Kr\" [1] \"texturename\" [\"env.tex\"]\nSphere 1 -1 1 360\n",
                                 diagnostics);
    std::vector<std::string> const warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 3u);
    CHECK(warnings[0] == "test.rib:2:17: Surface \"metal\" has no parameter \"Kd\"; ignored (its parameters: Ka, Ks, roughness)");
    CHECK_THAT(warnings[1], Catch::Matchers::StartsWith("test.rib:2:28: Surface \"metal\" has no parameter \"roughnes\"; "
                                                        "ignored (did you mean \"roughness\"?"));
    // shinymetal's reflection of an environment: one warning for both of its parameters.
    CHECK_THAT(warnings[2], Catch::Matchers::Contains("Surface \"shinymetal\": its reflection of an environment map"));
    REQUIRE(scene.shapes.size() == 2u);
    MaterialDesc const& metal = scene.materials[static_cast<size_t>(scene.shapes[0]->material)];
    CHECK(metal.params.getFloat("Ks", 0.0f) == 0.8f);
    CHECK_FALSE(metal.params.has("Kd"));  // not handed on: ClassicSurface's metal would have no use for it
    CHECK(scene.patterns.empty());              // no texture is read for shinymetal
}

TEST_CASE("a surface shader's source gives its declared defaults of plain numbers", "[rib]") {
    std::string const source =
        "/* a wood of the scene's own */\n#include \"common.h\"\n"
        "surface wood(float Ka = 1.2; float Kd = .04, Ks = 0.55; // weights\n"
        "  uniform float roughness = (0.1 + 0); color specularcolor = color \"rgb\" (1, 0.5, 0.25);\n"
        "  string texturename = \"a;b\"; output varying color Cbase = 1; float Kr = -2)\n{ Ci = 0; }\n";
    ShaderDefaults const declared = surfaceShaderDefaults(source, "wood");
    CHECK(declared.at("Ka") == std::vector<float>{1.2f});
    CHECK(declared.at("Kd") == std::vector<float>{0.04f});
    CHECK(declared.at("Ks") == std::vector<float>{0.55f});  // shares Kd's declaration
    CHECK(declared.at("specularcolor") == std::vector<float>{1.0f, 0.5f, 0.25f});
    CHECK(declared.at("Cbase") == std::vector<float>{1.0f, 1.0f, 1.0f});
    CHECK(declared.at("Kr") == std::vector<float>{-2.0f});
    CHECK(declared.count("roughness") == 0);    // an expression is not read
    CHECK(declared.count("texturename") == 0);  // nor a string
    CHECK(surfaceShaderDefaults(source, "oak").empty());
    CHECK(surfaceShaderDefaults("surface wood(float Kd = 1;", "wood").empty());  // never closed
    CHECK(surfaceShaderDefaults("surface wood(float Kd = 1)", "wo.od").empty());
    // A megabyte of space where a parser might recurse once per character: read without a crash.
    std::string const spaces(1 << 20, ' ');
    ShaderDefaults const spaced =
        surfaceShaderDefaults("surface" + spaces + "wood" + spaces + "(color Cs = (" + spaces + "1, 1, 1))", "wood");
    CHECK(spaced.empty());
}

TEST_CASE("a shader of the scene's own is rendered with the defaults its source declares for the standard "
          "parameters",
          "[rib]") {
    // wood.sl dims its diffuse to 0.04: the scene's lights are bright for it. The RIB gives roughness only.
    std::string const folder = test::outputDir() + "/shader-source";
    std::filesystem::create_directories(folder);
    std::ofstream(folder + "/wood.sl") << "surface wood(float Ka = 1.2; float Kd = .04; float Ks = 0.55;\n"
                                          "  float roughness = .1; color specularcolor = (1, 0.5, 0.25))\n{ }\n";
    std::string const world = "WorldBegin\nSurface \"wood\" \"roughness\" [0.3]\nSphere 1 -1 1 360\n";
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("Option \"searchpath\" \"string shader\" [\"" + folder + "\"]\n" + world, diagnostics);
    REQUIRE(scene.shapes.size() == 1u);
    MaterialDesc const& wood = scene.materials[static_cast<size_t>(scene.shapes[0]->material)];
    CHECK(wood.params.getString("shader", "") == "plastic");  // its source declares a Ks
    CHECK(wood.params.getFloat("Kd", 1.0f) == 0.04f);
    CHECK(wood.params.getFloat("Ka", 1.0f) == 1.2f);
    CHECK(wood.params.getFloat("Ks", 1.0f) == 0.55f);
    CHECK(wood.params.getFloat("roughness", 1.0f) == 0.3f);  // what the RIB gives wins
    CHECK(wood.params.getColor("specularcolor", Vec3(0.0f)) == Vec3(1.0f, 0.5f, 0.25f));
    CHECK(test::warningsContaining(diagnostics, "and the defaults its source wood.sl declares for Ka, Kd, "
                                                "Ks, specularcolor") == 1);
    // A copy of a standard shader the scene brings, declared in one list of floats.
    std::filesystem::create_directories(folder + "/shaders");
    std::ofstream(folder + "/shaders/metal.sl") << "surface\nmetal\n(\n  float Ka=1,\n  Ks=3,\n  roughness=.1;)\n{ }\n";
    Diagnostics copies(false);
    Scene copied = test::parseRib("WorldBegin\nSurface \"shaders/metal\"\nSphere 1 -1 1 360\n", copies,
                                  folder + "/copy.rib");
    MaterialDesc const& metal = copied.materials[static_cast<size_t>(copied.shapes[0]->material)];
    CHECK(metal.params.getString("shader", "") == "metal");
    CHECK(metal.params.getFloat("Ks", 1.0f) == 3.0f);
    CHECK(test::warningsContaining(copies, "rendered as the standard \"metal\" with the defaults its source "
                                           "metal.sl declares for Ka, Ks, roughness") == 1);
    // Without its source, the standard shader's own defaults.
    Diagnostics without(false);
    Scene alone = test::parseRib(world, without);
    MaterialDesc const& plain = alone.materials[static_cast<size_t>(alone.shapes[0]->material)];
    CHECK(plain.params.getString("shader", "") == "matte");
    CHECK_FALSE(plain.params.has("Kd"));
    CHECK(test::warningsContaining(without, "declares") == 0);
}

TEST_CASE("a shader whose source never reads Cs is coloured by a colour parameter of its own", "[rib]") {
    std::string const brick = "surface brick(float Ka = 1, Kd = 1; color specularcolor = 1;\n"
                              "  output color Cout = 0; color brickcolor = color (.5, .15, .14), mortarcolor = .5)\n"
                              "{ Ci = brickcolor * Kd * diffuse(N); /* Cs is not read */ }\n";
    using Names = std::vector<std::string>;
    CHECK(ownSurfaceColours(brick, "brick") == Names{"brickcolor"});  // not the specular colour, nor an output
    CHECK(ownSurfaceColours(brick + "surface other(color Cbase = 1) { Ci = Cs; }", "brick").empty());  // reads Cs
    CHECK(ownSurfaceColours("surface s(color specularcolor = 1; color envColor = 1) { Ci = 1; }", "s").empty());
    CHECK(ownSurfaceColours("surface s(color CsTint = 1) { Ci = CsTint; }", "s") == Names{"CsTint"});  // a longer word
    // A set: the checker's two colours, or lettered ones, but not a colour of another name between them.
    CHECK(ownSurfaceColours("surface c(color color1 = 0, mortar = 1, color2 = 1) { Ci = 1; }", "c") ==
          Names{"color1", "color2"});
    CHECK(ownSurfaceColours("surface c(color colorA = 0; color colorB = 1) { Ci = 1; }", "c") ==
          Names{"colorA", "colorB"});

    std::string const folder = test::outputDir() + "/own-colour";
    std::filesystem::create_directories(folder);
    std::ofstream(folder + "/brick.sl") << brick;
    std::ofstream(folder + "/tinted.sl") << "surface tinted(float Kd = 1; color tint = (0, 1, 0)) { Ci = Cs * tint; }\n";
    std::ofstream(folder + "/checks.sl") << "surface checks(color color1 = 0, color2 = 1) { Ci = diffuse(N); }\n";
    std::string const head = "Option \"searchpath\" \"string shader\" [\"" + folder + "\"]\nWorldBegin\nColor [0 0 1]\n";
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(head + "Surface \"brick\"\nSphere 1 -1 1 360\n"
                                        "Surface \"brick\" \"color brickcolor\" [0.2 0.3 0.4]\nSphere 1 -1 1 360\n"
                                        "Surface \"tinted\"\nSphere 1 -1 1 360\n"
                                        "Surface \"checks\" \"color color2\" [0 1 0]\nSphere 1 -1 1 360\n",
                                 diagnostics);
    REQUIRE(scene.shapes.size() == 4u);
    auto colourOf = [&](size_t shape) {
        return scene.materials[static_cast<size_t>(scene.shapes[shape]->material)].params.getColor("surfaceColor",
                                                                                                   Vec3(-1.0f));
    };
    CHECK(colourOf(0) == Vec3(0.5f, 0.15f, 0.14f));  // its default, not the blue Color
    CHECK(colourOf(1) == Vec3(0.2f, 0.3f, 0.4f));    // the RIB's value
    CHECK(colourOf(2) == Vec3(0.0f, 0.0f, 1.0f));    // a shader that reads Cs keeps Color
    CHECK(colourOf(3) == Vec3(0.0f, 0.5f, 0.0f));    // the average of black and the green given
    CHECK(test::warningsContaining(diagnostics, "coloured by the average of its color1 (its default) and color2 "
                                                "(as given)") == 1);
    CHECK(test::warningsContaining(diagnostics, "coloured by its brickcolor (its default), since its source never "
                                                "reads Cs") == 1);
}

TEST_CASE("a shader of its own colour whose source reads no light is rendered as constant", "[rib]") {
    CHECK(readsNoLight("surface glow(float attenuation = 2) { Ci = Cs * pow(abs(N.I), attenuation); }"));
    CHECK(readsNoLight("surface sky(color skycolor = 1) { /* Ci = diffuse(N); */ Ci = skycolor; }"));  // a comment
    CHECK_FALSE(readsNoLight("surface nothing(float Kd = 1) { }"));  // sets no colour: nothing to go by
    CHECK_FALSE(readsNoLight("surface m() { Ci = Cs * diffuse(normalize(N)); }"));
    CHECK_FALSE(readsNoLight("surface m() { illuminance(P, N, PI/2) { Ci += Cl; } }"));
    CHECK_FALSE(readsNoLight("#include \"material.h\"\nsurface m() { Ci = MaterialPlastic(N); }"));  // unknown

    std::string const folder = test::outputDir() + "/unlit";
    std::filesystem::create_directories(folder);
    std::ofstream(folder + "/KMPuffyclouds.sl") << "surface KMPuffyclouds(float Ka = 0, Kd = 0; color skycolor = "
                                                   "color(.15, .15, .6); color cloudcolor = 1)\n"
                                                   "{ Ci = mix(skycolor, cloudcolor, noise(P)); }\n";
    // A glow of Cs reads no light either, but shows mostly darker than Cs: it keeps its look-alike.
    std::ofstream(folder + "/RCGlow.sl") << "surface RCGlow(float attenuation = 2)\n"
                                            "{ Ci = Cs * pow(abs(normalize(N).normalize(I)), attenuation); }\n";
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("Option \"searchpath\" \"string shader\" [\"" + folder +
                                     "\"]\nWorldBegin\nSurface \"KMPuffyclouds\"\nSphere 1 -1 1 360\n"
                                     "Surface \"RCGlow\"\nSphere 1 -1 1 360\n",
                                 diagnostics);
    REQUIRE(scene.shapes.size() == 2u);
    CHECK(scene.materials[static_cast<size_t>(scene.shapes[1]->material)].params.getString("shader", "") == "matte");
    MaterialDesc const& sky = scene.materials[static_cast<size_t>(scene.shapes[0]->material)];
    CHECK(sky.params.getString("shader", "") == "constant");
    CHECK(sky.params.getColor("surfaceColor", Vec3(-1.0f)) == Vec3(0.15f, 0.15f, 0.6f));
    CHECK(test::warningsContaining(diagnostics, "rendered as \"constant\", as its source KMPuffyclouds.sl reads no "
                                                "light") == 1);
}

TEST_CASE("texturename raytrace is RenderMan's traced lookup and never a missing texture", "[rib]") {
    // Classic scenes hand "raytrace" to environment() and shadow() to trace rays instead of reading a map.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nSurface \"back\" \"Ad\" [0.05] \"texturename\" [\"raytrace\"]\n"
                                 "Sphere 1 -1 1 360\n"
                                 "Surface \"paintedplastic\" \"texturename\" [\"raytrace\"]\nSphere 1 -1 1 360\n"
                                 "Surface \"shinymetal\" \"texturename\" [\"raytrace\"]\nSphere 1 -1 1 360\n",
                                 diagnostics);
    std::vector<std::string> const warnings = test::warningTexts(diagnostics);
    for (std::string const& w : warnings) CHECK_THAT(w, !Catch::Matchers::Contains("does not exist"));
    REQUIRE(warnings.size() == 3u);
    CHECK_THAT(warnings[0], Catch::Matchers::Contains("Surface \"back\" is a shader this renderer does not have"));
    CHECK_THAT(warnings[0], !Catch::Matchers::Contains("maps its colour"));
    CHECK_THAT(warnings[1], Catch::Matchers::StartsWith("test.rib:2:"));
    CHECK_THAT(warnings[1], Catch::Matchers::Contains("texturename \"raytrace\" is RenderMan's name for a lookup"));
    CHECK_THAT(warnings[2], Catch::Matchers::Contains("Surface \"shinymetal\": its ray-traced reflection"));
    CHECK(scene.patterns.empty());  // no texture node: nothing is read
}

TEST_CASE("Imager background and clamptoalpha, and PxrBackgroundDisplayFilter, finish each pixel", "[rib][film]") {
    // A 4 x 4 view whose left half is a square glowing 3, whose right half is empty.
    auto render = [](std::string const& imager) {
        return test::renderRib("Format 4 4 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n" + imager +
                               "\nWorldBegin\nTranslate 0 0 5\nBxdf \"PxrConstant\" \"c\" \"color emitColor\" [3 2 1]\n"
                               "Patch \"bilinear\" \"P\" [-1 1 0  0 1 0  -1 -1 0  0 -1 0]\nWorldEnd\n",
                               test::withSpp(4));
    };
    auto pixel = [](test::RenderOutcome const& r, int x) {
        return std::vector<float>{r.channel(x, 2, 0), r.channel(x, 2, 1), r.channel(x, 2, 2), r.channel(x, 2, 3)};
    };
    using V = std::vector<float>;
    auto plain = render("");
    CHECK(pixel(plain, 0) == V{3, 2, 1, 1});
    CHECK(pixel(plain, 3) == V{0, 0, 0, 0});
    // The specification's background: the colour under the image, alpha made 1.
    auto classic = render("Imager \"background\" \"background\" [0.25 0.5 0.75]");
    CHECK(pixel(classic, 0) == V{3, 2, 1, 1});
    CHECK(pixel(classic, 3) == V{0.25f, 0.5f, 0.75f, 1});
    CHECK(classic.messages.empty());
    // RenderMan 21's form, with the background's alpha, and a script's "bgcolor".
    CHECK(pixel(render("Imager \"background\" \"color color\" [0 0 0.5] \"float alpha\" [0]"), 3) == V{0, 0, 0.5f, 0});
    CHECK(pixel(render("Imager \"background\" \"color bgcolor\" [1 0 0]"), 3) == V{1, 0, 0, 1});
    // RenderMan's display filter keeps alpha as rendered.
    auto filter = render("DisplayFilter \"PxrBackgroundDisplayFilter\" \"bg\" \"color backgroundColor\" [0 1 0]");
    CHECK(pixel(filter, 3) == V{0, 1, 0, 0});
    CHECK(pixel(filter, 0) == V{3, 2, 1, 1});
    // Its sample filter does the same to every sample: the same pixels.
    auto samples = render("SampleFilter \"PxrBackgroundSampleFilter\" \"bg\" \"color backgroundColor\" [0 1 0]");
    CHECK(pixel(samples, 3) == V{0, 1, 0, 0});
    CHECK(pixel(samples, 0) == V{3, 2, 1, 1});
    CHECK(samples.messages.empty());
    auto otherSamples = render("SampleFilter \"PxrGradeSampleFilter\" \"g\" \"color gain\" [2 2 2]");
    CHECK(pixel(otherSamples, 0) == V{3, 2, 1, 1});
    CHECK(otherSamples.anyMessageContains("test.rib:4:1: SampleFilter \"PxrGradeSampleFilter\" is not one this renderer has"));
    // Combiners name the filters they combine by handle, in RenderMan's own parameter types.
    CHECK(render("SampleFilter \"PxrSampleFilterCombiner\" \"all\" \"reference samplefilter[2] filter\" [\"a\" \"b\"]")
              .anyMessageContains("SampleFilter \"PxrSampleFilterCombiner\" is not one"));
    CHECK(render("DisplayFilter \"PxrDisplayFilterCombiner\" \"all\" \"reference displayfilter[2] filter\" [\"a\" \"b\"]")
              .anyMessageContains("DisplayFilter \"PxrDisplayFilterCombiner\" is not one"));
    // clamptoalpha: no channel above alpha.
    CHECK(pixel(render("Imager \"clamptoalpha\""), 0) == V{1, 1, 1, 1});
    // Another imager or display filter: a warning, and the image as it is.
    auto other = render("Imager \"vignette\" \"float radius\" [0.8]");
    CHECK(pixel(other, 3) == V{0, 0, 0, 0});
    CHECK(other.anyMessageContains("test.rib:4:1: Imager \"vignette\" is not an imager this renderer has"));
    CHECK(render("DisplayFilter \"PxrEdgeDetect\" \"e\"").anyMessageContains("DisplayFilter \"PxrEdgeDetect\" is not one"));
    // Exposure gain gamma, after the imager: (gain c)^(1/gamma).
    V const exposed = pixel(render("Imager \"clamptoalpha\"\nExposure 0.5 2"), 0);
    CHECK(exposed[0] == Approx(std::sqrt(0.5f)));
    CHECK(exposed[3] == 1.0f);
    CHECK(pixel(render("Exposure 2 1"), 0) == V{6, 4, 2, 1});
    CHECK_THROWS_WITH(render("Exposure 1 0"), Catch::Matchers::Contains("test.rib:4:1: Exposure: the gamma must be more than 0"));
    // RenderMan 21 and later write the exposure (and filter) as the image Display's parameters.
    CHECK(pixel(render("Display \"x.exr\" \"openexr\" \"rgba\" \"float[2] exposure\" [2 1]"), 0) ==
          V{6, 4, 2, 1});
}

TEST_CASE("the image's Display may name its pixel filter, as RenderMan for Maya 21 writes it",
          "[rib][filter]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "PixelFilter \"box\" 1 1\nDisplay \"shot\" \"it\" \"rgba\" \"string filter\" [\"gaussian\"] "
        "\"float[2] filterwidth\" [3 2] \"int[4] quantize\" [0 0 0 0] \"float dither\" [0]\n"
        "WorldBegin\nWorldEnd\n",
        diagnostics);
    CHECK(scene.pixelFilter.name == "gaussian");
    CHECK(scene.pixelFilter.xwidth == 3.0f);
    CHECK(scene.pixelFilter.ywidth == 2.0f);
    // Without widths, the filter keeps the widths in effect; a secondary display's filter is not the image's.
    Scene kept = test::parseRib(
        "PixelFilter \"box\" 2 2\nDisplay \"shot\" \"it\" \"rgba\" \"string filter\" [\"triangle\"]\n"
        "Display \"+depth\" \"it\" \"z\" \"string filter\" [\"sinc\"]\nWorldBegin\nWorldEnd\n",
        diagnostics);
    CHECK(kept.pixelFilter.name == "triangle");
    CHECK(kept.pixelFilter.xwidth == 2.0f);
}

TEST_CASE("DepthOfField: a thin lens blurs a point by its circle of confusion, and keeps the focal plane sharp",
          "[rib][camera]") {
    // A small glowing square (2.4 pixels wide at depth 20) on the axis at depth z, seen by a
    // 64 x 64 camera with a 30 degree view; some 1,500 of the samples hit it.
    auto render = [](std::string const& camera, float z, std::string const& integrator = "") {
        std::ostringstream rib;
        rib << "Format 64 64 1\nProjection \"perspective\" \"fov\" [30]\n" << camera << "\n" << integrator
            << "\nWorldBegin\nBxdf \"PxrConstant\" \"c\" \"color emitColor\" [1 1 1]\nTranslate 0 0 " << z
            << "\nPolygon \"P\" [-0.2 -0.2 0  0.2 -0.2 0  0.2 0.2 0  -0.2 0.2 0]\nWorldEnd\n";
        return test::renderRib(rib.str(), test::withSpp(256));
    };
    // The image's total, and the variance of x over it (pixels squared).
    auto spread = [](test::RenderOutcome const& r) {
        double total = 0.0, sumX = 0.0, sumXX = 0.0;
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x) {
                double const w = r.channel(x, y, 0), px = x + 0.5;
                total += w;
                sumX += w * px;
                sumXX += w * px * px;
            }
        double const mean = sumX / total;
        return std::pair<double, double>{total, sumXX / total - mean * mean};
    };
    // Lens diameter A = 0.5 / 1; sharp at depth 5. A point at depth 20 spreads over a disc of
    // diameter A |20 - 5| / (20 5) on the plane z = 1, whose variance along x is radius^2 / 4.
    double const pixel = 2.0 * std::tan(glm::radians(15.0)) / 64.0;
    double const radius = 0.5 * (0.5 * 15.0 / 100.0) / pixel;
    auto [pinholeTotal, pinholeSpread] = spread(render("", 20.0f));
    auto [lensTotal, lensSpread] = spread(render("DepthOfField 1 0.5 5", 20.0f));
    CHECK(lensTotal == Approx(pinholeTotal).epsilon(0.06));  // every lens point sees the same area
    CHECK(lensSpread - pinholeSpread == Approx(radius * radius / 4.0).epsilon(0.08));
    // RenderMan 21's camera parameters say the same.
    auto [cameraTotal, cameraSpread] =
        spread(render("Projection \"PxrCamera\" \"fov\" [30] \"fStop\" [1] \"focalLength\" [0.5] \"focalDistance\" [5]", 20.0f));
    CHECK(cameraSpread == Approx(lensSpread).epsilon(0.03));
    // On the focal plane, the lens changes nothing.
    auto [focusedTotal, focusedSpread] = spread(render("DepthOfField 1 0.5 5", 5.0f));
    auto [pinholeNearTotal, pinholeNearSpread] = spread(render("", 5.0f));
    CHECK(focusedSpread == Approx(pinholeNearSpread).margin(0.02));
    // An fstop of 1e38 or a focal length of 0 (what exporters write for none) is a pinhole, sample for sample.
    CHECK(render("DepthOfField 1e38 1e-10 1", 20.0f).rgba == render("", 20.0f).rgba);
    CHECK(render("Projection \"PxrPerspective\" \"fov\" [30] \"fStop\" [1e38] \"focalLength\" [0] \"focalDistance\" [0]",
                 20.0f)
              .rgba == render("", 20.0f).rgba);
    // PxrVCM joins light paths to a pinhole: it says it renders no depth of field.
    auto vcm = render("DepthOfField 1 0.5 5", 20.0f, "Integrator \"PxrVCM\" \"v\"");
    CHECK(vcm.anyMessageContains("joins light paths to a pinhole camera: depth of field is not rendered"));
    CHECK(spread(vcm).second == Approx(pinholeSpread).margin(0.05));
    CHECK_THROWS_WITH(render("DepthOfField 0 0.5 5", 20.0f),
                      Catch::Matchers::Contains("test.rib:3:1: DepthOfField: fstop, focallength and focaldistance must be"));
}

TEST_CASE("a negative quadric radius turns the surface inside out", "[rib][geometry]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nTranslate 0 0 5\nDisk 0 -1 360\n", diagnostics);
    REQUIRE(scene.shapes.size() == 1u);
    RayTracer tracer(scene);
    HitRecord hit = trace(tracer, Vec3(0.2f, 0, 0), Vec3(0, 0, 1));
    REQUIRE(hit.hit());
    CHECK(hit.t == Approx(5.0f));
    CHECK(scene.shapes[0]->basics(hit).Ng.z == Approx(-1.0f));  // a positive radius faces +z
}

TEST_CASE("Option Ri and Attribute Ri, as RenderMan 21 and later write requests, are read as the requests", "[rib]") {
    // The header a RenderMan 23 export starts with, against the same camera written as requests.
    std::string const asOption =
        "Option \"Ri\" \"int Frame\" [1] \"float PixelVariance\" [0.015] \"int[2] FormatResolution\" [64 32]\n"
        "  \"float FormatPixelAspectRatio\" [1] \"float[2] Clipping\" [0.1 10000] \"float[4] ScreenWindow\" [-2 2 -1 1]\n"
        "  \"float[4] CropWindow\" [0 1 0 1] \"float[2] Exposure\" [1 2.2]\n"
        "Projection \"perspective\" \"fov\" [30]\nWorldBegin\n";
    std::string const asRequests = "Format 64 32 1\nScreenWindow -2 2 -1 1\nProjection \"perspective\" \"fov\" [30]\nWorldBegin\n";
    Diagnostics diagnostics(false);
    Scene viaOption = test::parseRib(asOption, diagnostics);
    Scene viaRequests = test::parseRib(asRequests, diagnostics);
    CHECK(viaOption.xres == 64);
    CHECK(viaOption.yres == 32);
    CHECK(viaOption.pixelAspect == 1.0f);
    REQUIRE(viaOption.camera.hasScreenWindow);
    for (int i = 0; i < 4; ++i) CHECK(viaOption.camera.screenWindow[i] == viaRequests.camera.screenWindow[i]);
    // Requests this renderer skips are named as such; the ones it needs no value from are not mentioned.
    CHECK(test::warningsContaining(diagnostics, "CropWindow") == 0);  // the whole image: nothing to skip
    CHECK(viaOption.pixelVariance == Approx(0.015f));
    CHECK(test::warningsContaining(diagnostics, "PixelVariance") == 0);
    CHECK(test::warningsContaining(diagnostics, "\"Exposure\" is not used") == 1);
    CHECK(test::warningsContaining(diagnostics, "FormatResolution") == 0);
    CHECK(test::warningsContaining(diagnostics, "Clipping") == 0);
    CHECK(test::warningsContaining(diagnostics, "Option \"Ri\" is not used") == 0);

    // A resolution that cannot be rendered is an error at the parameter, as Format's is.
    try {
        test::parseRib("Option \"Ri\" \"int[2] FormatResolution\" [0 32]\nWorldBegin\n", diagnostics, "bad.rib");
        FAIL("a zero width was accepted");
    } catch (RibError const& e) {
        CHECK_THAT(e.what(), Catch::Contains("bad.rib:1:13") && Catch::Contains("whole numbers of at least 1 pixel"));
    }

    // Attribute "Ri" "Orientation" turns a disk over as Orientation does; Sides and Matte 0 are accepted quietly.
    Diagnostics quiet(false);
    Scene inside = test::parseRib("WorldBegin\nTranslate 0 0 5\nAttribute \"Ri\" \"string Orientation\" [\"inside\"] "
                                  "\"int Sides\" [2] \"int Matte\" [0] \"float ShadingRate\" [1]\nDisk 0 1 360\n",
                                  quiet);
    REQUIRE(inside.shapes.size() == 1u);
    RayTracer tracer(inside);
    HitRecord hit = trace(tracer, Vec3(0.2f, 0, 0), Vec3(0, 0, 1));
    REQUIRE(hit.hit());
    CHECK(inside.shapes[0]->basics(hit).Ng.z == Approx(-1.0f));  // outside, a disk faces +z
    CHECK(test::warningsContaining(quiet, "Ri") == 0);
    // A holdout is not modelled, and says so.
    test::parseRib("WorldBegin\nAttribute \"Ri\" \"int Matte\" [1]\nSphere 1 -1 1 360\n", quiet);
    CHECK(test::warningsContaining(quiet, "\"Matte\" [1] (a holdout) is not modelled") == 1);
}

TEST_CASE("FrameAspectRatio shapes the default screen window, and the image keeps the Format's size", "[rib]") {
    // The screen-x where a perspective ray through the right edge of the middle row crosses z = 1 (fov 90).
    auto rightEdge = [](std::string const& options) {
        Diagnostics diagnostics(false);
        Scene scene = test::parseRib(options + "Projection \"perspective\" \"fov\" [90]\nWorldBegin\n", diagnostics);
        Camera camera(scene.camera, scene.xres, scene.yres, scene.pixelAspect);
        Vec3 org, dir;
        camera.generateRay(static_cast<float>(scene.xres), 0.5f * static_cast<float>(scene.yres), org, dir);
        return dir.x / dir.z;
    };
    CHECK(rightEdge("Format 64 32 1\n") == Approx(2.0f));
    CHECK(rightEdge("Format 64 32 1\nFrameAspectRatio 2\n") == Approx(2.0f));  // what the books' files write
    CHECK(rightEdge("Format 64 32 1\nFrameAspectRatio 1\n") == Approx(1.0f));  // a square frame stretched wide
    CHECK(rightEdge("Format 64 32 1\nOption \"Ri\" \"float FrameAspectRatio\" [1.5]\n") == Approx(1.5f));
    CHECK(rightEdge("Format 64 32 1\nFrameAspectRatio 1\nScreenWindow -3 3 -1 1\n") == Approx(3.0f));  // a window wins
    // RenderMan 23 writes -1 for "the Format's".
    CHECK(rightEdge("Format 64 32 1\nOption \"Ri\" \"float FrameAspectRatio\" [-1]\n") == Approx(2.0f));
}

TEST_CASE("Clipping: camera rays see only what lies between the near and far planes", "[rib]") {
    // A red wall 2 units in front of the camera and a blue one 6 units away, both filling the view; a camera
    // turned and scaled, so that the planes are measured in camera space. The mean red and blue of the image.
    auto seen = [](std::string const& options) {
        std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\n" + options +
                          "Integrator \"PxrDirectLighting\" \"d\"\nRotate 30 0 1 0\nScale 2 2 2\nWorldBegin\n"
                          "Rotate -30 0 1 0\n"
                          "AttributeBegin\nBxdf \"PxrConstant\" \"near\" \"color emitColor\" [1 0 0]\n"
                          "Polygon \"P\" [-5 -5 1  5 -5 1  5 5 1  -5 5 1]\nAttributeEnd\n"
                          "Bxdf \"PxrConstant\" \"far\" \"color emitColor\" [0 0 1]\n"
                          "Polygon \"P\" [-50 -50 3  50 -50 3  50 50 3  -50 50 3]\nWorldEnd\n";
        return meanRedAndBlue(rib);
    };
    using Seen = RedAndBlue;
    CHECK(seen("") == Seen(1.0, 0.0));
    CHECK(seen("Clipping 0.1 4\n") == Seen(1.0, 0.0));
    CHECK(seen("Clipping 3 100\n") == Seen(0.0, 1.0));
    CHECK(seen("Clipping 3 5\n") == Seen(0.0, 0.0));  // nothing between
    CHECK(seen("Option \"Ri\" \"float[2] Clipping\" [3 1e30]\n") == Seen(0.0, 1.0));
    // Planes the wrong way round are skipped, with a warning.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("Clipping 5 1\nWorldBegin\n", diagnostics);
    CHECK(test::warningsContaining(diagnostics, "Clipping takes two distances") == 1);
    CHECK(scene.camera.clipNear == 0.0f);
}

TEST_CASE("Camera saves the camera under a name, and a Display's camera picks the one it is seen from", "[rib]") {
    // A red wall in front of the origin (z = 2) and a blue one behind it (z = -2). Camera "front" looks down +z,
    // "back" is turned round; the transform at WorldBegin is the front one again. The mean red and blue.
    auto seen = [](std::string const& display, std::string const& backParams = "") {
        std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\n"
                          "Integrator \"PxrDirectLighting\" \"d\"\n" + display +
                          "Camera \"front\"\nRotate 180 0 1 0\nCamera \"back\"" + backParams + "\nIdentity\n"
                          "DisplayChannel \"color Ci\"\nWorldBegin\n"
                          "AttributeBegin\nBxdf \"PxrConstant\" \"r\" \"color emitColor\" [1 0 0]\n"
                          "Polygon \"P\" [-5 -5 2  5 -5 2  5 5 2  -5 5 2]\nAttributeEnd\n"
                          "Bxdf \"PxrConstant\" \"b\" \"color emitColor\" [0 0 1]\n"
                          "Polygon \"P\" [-5 -5 -2  5 -5 -2  5 5 -2  -5 5 -2]\nWorldEnd\n";
        return meanRedAndBlue(rib);
    };
    using Seen = RedAndBlue;
    std::string const display = "Display \"x.exr\" \"openexr\" \"rgba\" \"string camera\" ";
    CHECK(seen("") == Seen(1.0, 0.0));  // no Display names a camera: the one at WorldBegin
    CHECK(seen(display + "[\"back\"]\n") == Seen(0.0, 1.0));
    CHECK(seen(display + "[\"front\"]\n") == Seen(1.0, 0.0));
    // The camera's nearClip and farClip: "back" sees nothing nearer than 3.
    CHECK(seen(display + "[\"back\"]\n", " \"float nearClip\" [3] \"float farClip\" [100]") == Seen(0.0, 0.0));

    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("Display \"x.exr\" \"openexr\" \"rgba\" \"string camera\" [\"side\"]\n"
                                 "Display \"+y.exr\" \"openexr\" \"z\" \"string camera\" [\"top\"]\n"
                                 "DisplayChannel \"color lpe:C<RD>L\" \"string filter\" [\"box\"]\n"
                                 "Camera \"top\" \"float nearClip\" [2] \"float apertureNSides\" [5]\n"
                                 // What exporters write: RenderMan's defaults, the plain camera this renderer has.
                                 "Camera \"exported\" \"float shutterOpenTime\" [0] \"float shutterCloseTime\" [1] "
                                 "\"int apertureNSides\" [0] \"float apertureAngle\" [0] \"float apertureRoundness\" [0] "
                                 "\"float apertureDensity\" [0] \"float dofaspect\" [1]\n"
                                 "Camera \"maya\" \"float[2] shutteropening\" [0 1]\n"  // RenderMan 21's
                                 "Translate 0 0 5\nWorldBegin\nWorldEnd\n",
                                 diagnostics);
    // A camera no Camera request named: the one at WorldBegin, with a warning.
    CHECK(test::warningsContaining(diagnostics, "which no Camera request has named") == 1);
    CHECK(scene.camera.worldToCamera[3][2] == 5.0f);
    // A further display is seen from the first one's camera, with a warning.
    CHECK(test::warningsContaining(diagnostics, "every image of a render is seen from one camera") == 1);
    // The lens shape is not modelled: warned where it is not RenderMan's plain default. DisplayChannel is
    // read, and the Display says whether its channel is made.
    CHECK(test::warningsContaining(diagnostics, "apertureNSides") == 1);
    CHECK(test::warningsContaining(diagnostics, "Camera: parameter") == 1);
    CHECK(test::warningsContaining(diagnostics, "DisplayChannel") == 0);
    CHECK(scene.camera.clipNear == 2.0f);
}

TEST_CASE("Detail and DetailRange draw the one representation of a model meant for its size on the image",
          "[rib]") {
    // After aqsis's level-of-detail example: a unit sphere given three times, red for a model under 20-30
    // pixels of the image, green up to 500-600, blue above, at a distance. Which of red, green and blue
    // shows.
    auto drawn = [](float distance, std::string const& options = "",
                    std::string const& detail = "Detail [-1 1 -1 1 -1 1]\n") {
        std::string const rib = "Format 64 64 1\nProjection \"perspective\" \"fov\" [40]\n" + options +
                                "WorldBegin\nTranslate 0 0 " + std::to_string(distance) +
                                "\nAttributeBegin\n" + detail +
                                "DetailRange [0 0 20 30]\nBxdf \"PxrConstant\" \"r\" \"color emitColor\" [1 "
                                "0 0]\nSphere 1 -1 1 360\n"
                                "DetailRange [20 30 500 600]\nBxdf \"PxrConstant\" \"g\" \"color emitColor\" "
                                "[0 1 0]\nSphere 1 -1 1 360\n"
                                "DetailRange [500 600 1e38 1e38]\nBxdf \"PxrConstant\" \"b\" \"color "
                                "emitColor\" [0 0 1]\nSphere 1 -1 1 360\n"
                                "AttributeEnd\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(4));
        auto all = [](int, int) { return true; };
        std::string shown;
        for (int c = 0; c < 3; ++c)
            if (test::meanChannel(r, c, all) > 0.0) shown += "rgb"[c];
        return shown;
    };
    // The bound's nearest face spans 2 / (2 (d - 1) tan 20 deg) of the image's 64 pixels: about 7700 square
    // pixels at 3, 85 at 20 and 3 at 100.
    CHECK(drawn(3.0f) == "b");
    CHECK(drawn(20.0f) == "g");
    CHECK(drawn(100.0f) == "r");
    // RelativeDetail scales the detail: a thousandth of 7700 is red's.
    CHECK(drawn(3.0f, "RelativeDetail 0.001\n") == "r");
    // A bound that reaches the eye is as detailed as can be.
    CHECK(drawn(3.0f, "", "Detail [-1 1 -1 1 -5 1]\n") == "b");

    // Without a Detail, the finest representation, with a warning; what was left out is listed.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "WorldBegin\nDetailRange [0 0 1 2]\nSphere 1 -1 1 360\nDetailRange [1 2 1e38 1e38]\n"
        "Sphere 2 -2 2 360\nWorldEnd\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 1);
    CHECK(test::warningsContaining(diagnostics, "DetailRange with no Detail bound before it") == 1);
    CHECK(std::count_if(scene.dropped.begin(), scene.dropped.end(), [](std::string const& line) {
              return line.find("1 shape is a representation that DetailRange does not draw") == 0;
          }) == 1);
    // Numbers that decrease are an error at their line.
    Diagnostics bad(false);
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nDetailRange [0 10 5 20]\n", bad),
                      Catch::Matchers::StartsWith("test.rib:2:1: DetailRange: minvisible"));
}

TEST_CASE("Sides 1 hides the back of a surface from the camera, and from no other ray", "[rib]") {
    // Two quads side by side in front of a green wall, wound opposite ways: whatever the
    // winding rule, one shows the camera its outside and the other its back.
    auto scene = [](char const* sides, std::string const& extra) {
        return std::string("Format 16 8 1\nProjection \"orthographic\"\nScreenWindow -2 2 -1 1\n") +
               "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n" + extra +
               "AttributeBegin\nBxdf \"PxrConstant\" \"wall\" \"color emitColor\" [0 1 0]\n"
               "Polygon \"P\" [-3 -2 10  3 -2 10  3 2 10  -3 2 10]\nAttributeEnd\n"
               "AttributeBegin\nSides " + sides + "\nBxdf \"PxrConstant\" \"quads\" \"color emitColor\" [1 0 0]\n"
               "Polygon \"P\" [-2 -1 5  0 -1 5  0 1 5  -2 1 5]\n"   // left half
               "Polygon \"P\" [0 -1 5  0 1 5  2 1 5  2 -1 5]\n"     // right half, wound the other way
               "AttributeEnd\nWorldEnd\n";
    };
    auto red = [](test::RenderOutcome const& r, bool left) {
        return test::meanChannel(r, 0, [left](int x, int) { return (x < 8) == left; });
    };
    auto green = [](test::RenderOutcome const& r, bool left) {
        return test::meanChannel(r, 1, [left](int x, int) { return (x < 8) == left; });
    };
    auto twoSided = test::renderRib(scene("2", ""), test::withSpp(4));
    auto const& simulated = twoSided.stats.effects.simulated;
    CHECK(std::find_if(simulated.begin(), simulated.end(),
                       [](std::string const& e) { return e.find("Sides 1") != std::string::npos; }) == simulated.end());
    CHECK(red(twoSided, true) == Approx(1.0));
    CHECK(red(twoSided, false) == Approx(1.0));
    auto oneSided = test::renderRib(scene("1", ""), test::withSpp(4));
    // Exactly one half is culled: there the wall behind shows.
    auto const& culling = oneSided.stats.effects.simulated;
    CHECK(std::find_if(culling.begin(), culling.end(),
                       [](std::string const& e) { return e.find("Sides 1") != std::string::npos; }) != culling.end());
    bool const leftShown = red(oneSided, true) > 0.5;
    CHECK(red(oneSided, !leftShown) == Approx(0.0).margin(1e-6));
    CHECK(green(oneSided, !leftShown) == Approx(1.0));
    CHECK(red(oneSided, leftShown) == Approx(1.0));
    CHECK(green(oneSided, leftShown) == Approx(0.0).margin(1e-6));
    // ReverseOrientation turns the outside over: the other half shows.
    auto reversed = test::renderRib(scene("1", "ReverseOrientation\n"), test::withSpp(4));
    CHECK(red(reversed, leftShown) == Approx(0.0).margin(1e-6));
    CHECK(red(reversed, !leftShown) == Approx(1.0));

    // A quadric from inside: a one-sided sphere around the camera hides nothing.
    auto around = [](char const* sides) {
        return test::renderRib(std::string("Format 8 8 1\nProjection \"perspective\" \"fov\" [40]\nWorldBegin\n") +
                                   "Bxdf \"PxrConstant\" \"wall\" \"color emitColor\" [0 1 0]\n"
                                   "Polygon \"P\" [-9 -9 10  9 -9 10  9 9 10  -9 9 10]\n"
                                   "AttributeBegin\nSides " + sides +
                                   "\nBxdf \"PxrConstant\" \"shell\" \"color emitColor\" [1 0 0]\nSphere 3 -3 3 360\n"
                                   "AttributeEnd\nWorldEnd\n",
                               test::withSpp(4));
    };
    auto all = [](int, int) { return true; };
    CHECK(test::meanChannel(around("2"), 0, all) == Approx(1.0));
    CHECK(test::meanChannel(around("1"), 0, all) == Approx(0.0).margin(1e-6));
    CHECK(test::meanChannel(around("1"), 1, all) == Approx(1.0));

    // Shadow rays still meet the back: a one-sided blocker, unseen by the camera, shadows the wall
    // whichever way it faces.
    auto sunlit = [](std::string const& blocker) {
        return test::renderRib(std::string("Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n") +
                                   "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n"
                                   // from the camera's side, along +z; the sun's small disc needs the exposure
                                   "Light \"PxrDistantLight\" \"sun\" \"float exposure\" [15]\n"
                                   "Bxdf \"PxrDiffuse\" \"wall\"\nPolygon \"P\" [-5 -5 10  5 -5 10  5 5 10  -5 5 10]\n" +
                                   blocker + "WorldEnd\n",
                               test::withSpp(4));
    };
    std::string const blocker = "Attribute \"visibility\" \"int camera\" [0]\nPolygon \"P\" [-5 -5 5  5 -5 5  5 5 5  -5 5 5]\n";
    REQUIRE(test::meanChannel(sunlit(""), 0, all) > 0.1);
    CHECK(test::meanChannel(sunlit("AttributeBegin\nSides 1\n" + blocker + "AttributeEnd\n"), 0, all) ==
          Approx(0.0).margin(1e-6));
    CHECK(test::meanChannel(sunlit("AttributeBegin\nSides 1\nReverseOrientation\n" + blocker + "AttributeEnd\n"), 0, all) ==
          Approx(0.0).margin(1e-6));
}

TEST_CASE("BMRT's Attribute \"render\" \"casts_shadows\" \"none\" hides an object from shadow rays only", "[rib]") {
    // A sky sphere around a scene (the RenderMan Repository's planet files) must not shadow it.
    auto render = [](std::string const& casts) {
        return test::renderRib(std::string("Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\n"
                                           "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n"
                                           "Light \"PxrDistantLight\" \"sun\" \"float exposure\" [15]\n"
                                           "Bxdf \"PxrDiffuse\" \"d\"\nPolygon \"P\" [-5 -5 10  5 -5 10  5 5 10  -5 5 10]\n"
                                           "AttributeBegin\nSides 1\n") +  // seen from inside: the camera sees the wall
                                   casts + "Sphere 50 -50 50 360\nAttributeEnd\nWorldEnd\n",
                               test::withSpp(4));
    };
    auto all = [](int, int) { return true; };
    test::RenderOutcome const open = render("Attribute \"render\" \"casts_shadows\" [\"none\"]\n");
    CHECK(test::meanChannel(open, 0, all) > 0.1);
    CHECK_FALSE(open.anyMessageContains("casts_shadows"));
    CHECK(test::meanChannel(render(""), 0, all) == Approx(0.0).margin(1e-6));
    CHECK(test::meanChannel(render("Attribute \"render\" \"string casts_shadows\" \"opaque\"\n"), 0, all) ==
          Approx(0.0).margin(1e-6));
}

TEST_CASE("RenderMan's bookkeeping parameters (a leading __) are accepted on any node without a warning", "[rib]") {
    // What exporters add to lights, materials and patterns; a misspelt real parameter is still named.
    auto r = test::renderRib("Format 4 4 1\nProjection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nWorldBegin\n"
                             "Light \"PxrDomeLight\" \"sky\" \"string __category\" [\"keys\"] \"int __islight\" [1]\n"
                             "Pattern \"PxrFractal\" \"noise\" \"string __instanceid\" [\"noise_0\"]\n"
                             "Bxdf \"PxrDisney\" \"paint\" \"string __materialid\" [\"paint\"] \"string __instanceid\" [\"paint_0\"] "
                             "\"float roughnes\" [0.2]\nSphere 1 -1 1 360\n");
    CHECK_FALSE(r.anyMessageContains("__"));
    CHECK(r.anyMessageContains("\"roughnes\""));
}

TEST_CASE("lights and integrators type a parameter written without a type, as RenderMan types it from their declarations",
          "[rib]") {
    auto scene = [](std::string const& light, std::string const& integrator) {
        return "Format 8 8 1\nProjection \"perspective\" \"fov\" [40]\n" + integrator +
               "\nTranslate 0 0 5\nWorldBegin\nAttributeBegin\nTranslate 0 0 -3\nRotate 180 0 1 0\n" + light +
               "\nAttributeEnd\nBxdf \"PxrDiffuse\" \"d\"\nSphere 1 -1 1 360\nWorldEnd\n";
    };
    auto untyped = test::renderRib(scene("Light \"PxrRectLight\" \"key\" \"lightColor\" [1 0.5 0.25] \"exposure\" [2]",
                                         "Integrator \"PxrPathTracer\" \"p\" \"maxPathLength\" [2]"));
    auto typed = test::renderRib(
        scene("Light \"PxrRectLight\" \"key\" \"color lightColor\" [1 0.5 0.25] \"float exposure\" [2]",
              "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [2]"));
    CHECK(untyped.rgba == typed.rgba);
    CHECK(test::meanChannel(typed, 0, [](int, int) { return true; }) > 0.0);
    CHECK_FALSE(untyped.anyMessageContains("type"));
    // A value that cannot be the declared type is a located error.
    try {
        test::renderRib(scene("Light \"PxrRectLight\" \"key\" \"lightColor\" [1 0.5]", ""), {}, "light.rib");
        FAIL("a colour of two numbers was accepted");
    } catch (RibError const& e) {
        CHECK_THAT(e.what(), Catch::Contains("light.rib:9:28") && Catch::Contains("\"lightColor\" is a color"));
    }
}

TEST_CASE("what exporters always write is accepted quietly: the whole CropWindow, Shutter, ShadingRate", "[rib]") {
    Diagnostics quiet(false);
    test::parseRib("CropWindow 0 1 0 1\nShutter 0 0\nShadingRate 1\nOption \"Ri\" \"float[4] CropWindow\" [0 1 0 1] "
                   "\"float[2] Shutter\" [0 1]\nErrorHandler \"printonce\"\nErrorHandler \"abort\"\n"
                   "WorldBegin\nShadingRate 10\n",
                   quiet);
    CHECK(quiet.warningCount() == 0);
    // A handler that is none of the standard ones is named, once.
    Diagnostics handler(false);
    test::parseRib("ErrorHandler \"mine\"\nErrorHandler \"mine\"\nWorldBegin\n", handler, "handler.rib");
    CHECK(test::warningsContaining(handler, "handler.rib:1:1: ErrorHandler \"mine\" is not a standard handler") == 1);
    CHECK(handler.warningCount() == 1);
    // A part of the image is not rendered alone: that changes the picture, so it is said.
    Diagnostics cropped(false);
    test::parseRib("CropWindow 0.25 0.75 0 1\nWorldBegin\n", cropped, "crop.rib");
    CHECK(test::warningsContaining(cropped, "crop.rib:1:1: CropWindow (a part of the image) is not supported") == 1);
    Diagnostics croppedRi(false);
    test::parseRib("Option \"Ri\" \"float[4] CropWindow\" [0 0.5 0 0.5]\nWorldBegin\n", croppedRi, "crop.rib");
    CHECK(test::warningsContaining(croppedRi, "Option \"Ri\" \"CropWindow\" (a part of the image) is not supported") == 1);
}

TEST_CASE("a stand-in reads the material's parameters also when they are written without a type", "[rib][plugins]") {
    auto scene = [](std::string const& params) {
        return "Format 16 16 1\nProjection \"perspective\" \"fov\" [30]\nTranslate 0 0 5\nWorldBegin\n"
               "Light \"PxrDomeLight\" \"sky\"\nBxdf \"PxrSurface\" \"skin\" " + params + "\nSphere 1 -1 1 360\nWorldEnd\n";
    };
    auto untyped = test::renderRib(scene("\"diffuseGain\" [0.55] \"diffuseColor\" [0.68 0.36 0.22] \"specularRoughness\" [0.38]"));
    auto typed = test::renderRib(
        scene("\"float diffuseGain\" [0.55] \"color diffuseColor\" [0.68 0.36 0.22] \"float specularRoughness\" [0.38]"));
    CHECK(untyped.rgba == typed.rgba);
    auto all = [](int, int) { return true; };
    CHECK(test::meanChannel(untyped, 0, all) > 1.05 * test::meanChannel(untyped, 2, all));  // orange, not grey
}

TEST_CASE("RenderMan for Maya's primtype record on a shape passes silently, another string is warned about",
          "[rib][geometry]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nPointsGeneralPolygons [1] [3] [0 1 2] \"P\" [0 0 0 1 0 0 0 1 0] "
                                 "\"constant string primtype\" [\"mesh\"]\n"
                                 "Sphere 1 -1 1 360 \"constant string label\" [\"ball\"]\n",
                                 diagnostics);
    CHECK(scene.shapes.size() == 2u);
    std::vector<std::string> const warnings = test::warningTexts(diagnostics);
    REQUIRE(warnings.size() == 1u);
    CHECK_THAT(warnings[0], Catch::Matchers::Contains("Sphere: parameter \"label\" is not used"));
}

TEST_CASE("GeneralPolygon and PointsGeneralPolygons: holes are holes", "[rib][geometry]") {
    Diagnostics diagnostics(false);
    // A square with a triangular hole (either winding of the hole).
    for (std::string hole : {"-1 -1 5  1 -1 5  0 1 5", "0 1 5  1 -1 5  -1 -1 5"}) {
        Scene scene = test::parseRib("WorldBegin\nGeneralPolygon [4 3] \"P\" [-2 -2 5  2 -2 5  2 2 5  -2 2 5  " + hole + "]\n",
                                     diagnostics);
        REQUIRE(scene.shapes.size() == 1u);
        RayTracer tracer(scene);
        CHECK(trace(tracer, Vec3(1.8f, 1.8f, 0), Vec3(0, 0, 1)).hit());
        CHECK(trace(tracer, Vec3(-1.5f, 0.5f, 0), Vec3(0, 0, 1)).hit());
        CHECK_FALSE(trace(tracer, Vec3(0.0f, -0.5f, 0), Vec3(0, 0, 1)).hit());  // in the hole
        CHECK_FALSE(trace(tracer, Vec3(2.5f, 0, 0), Vec3(0, 0, 1)).hit());
    }
    // Two holes side by side in one face of a mesh.
    Scene scene = test::parseRib("WorldBegin\nPointsGeneralPolygons [3] [4 4 4] [0 1 2 3  4 5 6 7  8 9 10 11] \"P\" ["
                                 "-3 -1 5  3 -1 5  3 1 5  -3 1 5   -2 -0.5 5  -1 -0.5 5  -1 0.5 5  -2 0.5 5   "
                                 "1 -0.5 5  2 -0.5 5  2 0.5 5  1 0.5 5]\n",
                                 diagnostics);
    RayTracer tracer(scene);
    CHECK_FALSE(trace(tracer, Vec3(-1.5f, 0, 0), Vec3(0, 0, 1)).hit());
    CHECK_FALSE(trace(tracer, Vec3(1.5f, 0, 0), Vec3(0, 0, 1)).hit());
    CHECK(trace(tracer, Vec3(0.0f, 0, 0), Vec3(0, 0, 1)).hit());
    CHECK(trace(tracer, Vec3(2.5f, 0.8f, 0), Vec3(0, 0, 1)).hit());
}

TEST_CASE("a face of a million vertices is triangulated in about as many steps, an absurd one is refused",
          "[rib][geometry][errors]") {
    // A star: every other vertex reflex, the worst kind of face for a naive ear clipper.
    size_t const n = 1'000'000;
    std::ostringstream rib;
    rib << "WorldBegin\nPolygon \"P\" [";
    for (size_t i = 0; i < n; ++i) {
        double angle = 2.0 * 3.14159265358979 * static_cast<double>(i) / n, r = i % 2 ? 1.0 : 0.999;
        rib << r * std::cos(angle) << ' ' << r * std::sin(angle) << " 5 ";
    }
    rib << "]\n";
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(rib.str(), diagnostics);
    REQUIRE(scene.shapes.size() == 1u);
    auto const& mesh = dynamic_cast<TriangleMesh const&>(*scene.shapes[0]);
    CHECK(mesh.data().triangleCount() == n - 2);
    RayTracer tracer(scene);
    CHECK(trace(tracer, Vec3(0.3f, 0.2f, 0), Vec3(0, 0, 1)).hit());
}

TEST_CASE(
    "RenderMan's camera plugins are perspective cameras but PxrOrthographic and no Projection is "
    "orthographic",
    "[rib]") {
    Diagnostics diagnostics(false);
    Scene pxr = test::parseRib("Projection \"PxrCamera\" \"float fov\" [35]\nWorldBegin\n", diagnostics);
    CHECK(pxr.camera.projection == "perspective");
    CHECK(pxr.camera.fov == 35.0f);
    CHECK(test::warningsContaining(diagnostics, "PxrCamera") == 1);
    Scene ortho = test::parseRib("Projection \"PxrOrthographic\"\nWorldBegin\n", diagnostics);
    CHECK(ortho.camera.projection == "orthographic");
    CHECK(test::warningsContaining(diagnostics, "PxrOrthographic") == 0);
    Scene none = test::parseRib("WorldBegin\n", diagnostics);
    CHECK(none.camera.projection == "orthographic");
}

namespace {

/// What a ray from (x, y, 0) along +z finds on the one shape of `rib`: its
/// parameters and every primvar's value there. The scene must use all it gives.
struct SurfaceSample {
    SurfaceParameters at;
    std::map<std::string, std::vector<float>> values;
};
SurfaceSample sampleAlongZ(std::string const& rib, float x, float y) {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(rib + "\n", diagnostics);
    CHECK(test::warningsContaining(diagnostics, "not used") == 0);
    REQUIRE(scene.shapes.size() == 1u);
    RayTracer tracer(scene);
    HitRecord hit = trace(tracer, Vec3(x, y, 0.0f), Vec3(0, 0, 1));
    REQUIRE(hit.hit());
    Shape const& shape = *scene.shapes[0];
    SurfaceSample seen{shape.parameters(hit), {}};
    for (Primvar const& var : shape.primvars.all()) {
        std::vector<float> value(static_cast<size_t>(var.components));
        shape.primvar(var, hit, value.data());
        seen.values[var.name] = value;
    }
    return seen;
}

/// The error a scene stops with, or nothing when it reads.
std::string readingError(std::string const& rib) {
    Diagnostics diagnostics(false);
    try {
        test::parseRib(rib, diagnostics);
    } catch (std::exception const& e) {
        return e.what();
    }
    return "";
}

/// Each primvar, given to `shape` (a request on line 3), stops the scene at that line with its message.
void checkCountErrors(std::string const& shape,
                      std::vector<std::pair<std::string, std::string>> const& primvarsAndMessages) {
    for (auto const& [primvar, message] : primvarsAndMessages) {
        CAPTURE(primvar);
        CHECK_THAT(readingError(shape + primvar + "\n"),
                   Catch::Matchers::Contains("test.rib:3:") && Catch::Matchers::Contains(message));
    }
}

}  // namespace

TEST_CASE("a subdivision surface keeps its primvars: vertex, varying, facevarying (s and t from st) and uniform",
          "[rib][geometry][primvars]") {
    // A 2 x 2 grid of quads over [-1, 1]^2, its border kept (interpolateboundary 1), seen from z = 0.
    std::string const grid = "WorldBegin\nTranslate 0 0 5\nSubdivisionMesh \"catmull-clark\" [4 4 4 4] "
                             "[0 1 4 3  1 2 5 4  3 4 7 6  4 5 8 7] [\"interpolateboundary\"] [1 0] [1] [] "
                             "\"P\" [-1 -1 0  0 -1 0  1 -1 0  -1 0 0  0 0 0  1 0 0  -1 1 0  0 1 0  1 1 0] ";
    auto look = [&](std::string const& primvars, float x, float y) { return sampleAlongZ(grid + primvars, x, y); };
    SECTION("one UV sheet over the faces (facevarying st): s and t run across the whole mesh, not each face") {
        // Each face's corners, in its own order, given its quarter of [0, 1]^2.
        std::string const st = "\"facevarying float[2] st\" [0 0  0.5 0  0.5 0.5  0 0.5   0.5 0  1 0  1 0.5  0.5 0.5   "
                               "0 0.5  0.5 0.5  0.5 1  0 1   0.5 0.5  1 0.5  1 1  0.5 1]";
        for (Vec2 xy : {Vec2(-0.5f, -0.5f), Vec2(0.0f, 0.0f), Vec2(0.5f, -0.3f), Vec2(-0.7f, 0.6f)}) {
            CAPTURE(xy.x, xy.y);
            SurfaceSample seen = look(st, xy.x, xy.y);
            // A linear layout stays linear under subdivision.
            CHECK(seen.at.s == Approx(0.5f * (xy.x + 1.0f)).margin(0.01));
            CHECK(seen.at.t == Approx(0.5f * (xy.y + 1.0f)).margin(0.01));
            CHECK(seen.values.at("st")[0] == Approx(seen.at.s));
        }
        // "s" and "t" given apart do the same.
        std::string const apart = "\"facevarying float s\" [0 0.5 0.5 0  0.5 1 1 0.5  0 0.5 0.5 0  0.5 1 1 0.5] "
                                  "\"facevarying float t\" [0 0 0.5 0.5  0 0 0.5 0.5  0.5 0.5 1 1  0.5 0.5 1 1]";
        SurfaceSample seen = look(apart, 0.5f, -0.3f);
        CHECK(seen.at.s == Approx(0.75f).margin(0.01));
        CHECK(seen.at.t == Approx(0.35f).margin(0.01));
    }
    SECTION("a seam: the right column's faces map to an island of their own, and s jumps across the centre line") {
        std::string const st = "\"facevarying float[2] st\" [0 0  0.4 0  0.4 0.5  0 0.5   0.6 0  1 0  1 0.5  0.6 0.5   "
                               "0 0.5  0.4 0.5  0.4 1  0 1   0.6 0.5  1 0.5  1 1  0.6 1]";
        CHECK(look(st, -0.01f, 0.3f).at.s == Approx(0.4f).margin(0.01));
        CHECK(look(st, 0.01f, 0.3f).at.s == Approx(0.6f).margin(0.01));
    }
    SECTION("vertex values are subdivided as the points are, varying ones linearly, uniform ones per face") {
        std::string const vars = "\"vertex float height\" [-1 0 1  -1 0 1  -1 0 1] "
                                 "\"varying float across\" [-1 -1 -1  0 0 0  1 1 1] "
                                 "\"uniform float face\" [0 1 2 3] \"varying color Cs\" [1 0 0  1 0 0  1 0 0  0 1 0  0 1 0  "
                                 "0 1 0  0 0 1  0 0 1  0 0 1]";
        SurfaceSample seen = look(vars, 0.5f, 0.3f);
        CHECK(seen.values.at("height")[0] == Approx(0.5f).margin(0.01));
        CHECK(seen.values.at("across")[0] == Approx(0.3f).margin(0.01));
        CHECK(seen.values.at("face")[0] == 3.0f);
        CHECK(seen.values.at("Cs")[1] == Approx(0.7f).margin(0.01));  // 0.3 of the way from green to blue
        CHECK(seen.values.at("Cs")[2] == Approx(0.3f).margin(0.01));
        CHECK(look(vars, -0.5f, -0.5f).values.at("face")[0] == 0.0f);
        CHECK(look(vars, 0.5f, -0.5f).values.at("face")[0] == 1.0f);
    }
    SECTION("a primvar with the wrong number of values is an error at its parameter") {
        checkCountErrors(grid,
                         {{"\"facevarying float[2] st\" [0 0  1 0  1 1]",
                           "needs 16 values here (one per face corner), got 3"},
                          {"\"vertex float h\" [0 1 2 3]", "needs 9 values here (one per point), got 4"}});
    }
}

TEST_CASE("a patch mesh's (u, v) run over the whole mesh, and its primvars follow the RI specification's layout",
          "[rib][geometry][primvars][patches]") {
    // A 3 x 3 bilinear mesh (2 x 2 patches) over [-1, 1]^2, seen from z = 0.
    std::string const grid = "WorldBegin\nTranslate 0 0 5\nPatchMesh \"bilinear\" 3 \"nonperiodic\" 3 \"nonperiodic\" "
                             "\"P\" [-1 -1 0  0 -1 0  1 -1 0  -1 0 0  0 0 0  1 0 0  -1 1 0  0 1 0  1 1 0] ";
    auto const look = sampleAlongZ;
    SECTION("u, v and the default s, t go from 0 to 1 across the mesh, not across each patch") {
        for (Vec2 xy : {Vec2(-0.5f, -0.5f), Vec2(0.3f, -0.7f), Vec2(0.6f, 0.2f)}) {
            CAPTURE(xy.x, xy.y);
            SurfaceSample seen = look(grid, xy.x, xy.y);
            CHECK(seen.at.u == Approx(0.5f * (xy.x + 1.0f)).margin(1e-4));
            CHECK(seen.at.v == Approx(0.5f * (xy.y + 1.0f)).margin(1e-4));
            CHECK(seen.at.s == Approx(seen.at.u));
            CHECK(seen.at.t == Approx(seen.at.v));
        }
    }
    SECTION("varying values (one per patch corner) give s and t and other primvars; uniform ones one per patch") {
        std::string const vars = "\"varying float[2] st\" [1 0  0.5 0  0 0   1 0.5  0.5 0.5  0 0.5   1 1  0.5 1  0 1] "
                                 "\"uniform float patch\" [0 1 2 3] \"varying color Cs\" [0 0 0  0 0 0  0 0 0  "
                                 "0 0 0  1 1 1  0 0 0  0 0 0  0 0 0  0 0 0]";
        SurfaceSample seen = look(grid + vars, 0.3f, -0.7f);
        CHECK(seen.at.s == Approx(1.0f - 0.5f * 1.3f).margin(1e-4));  // s runs the other way
        CHECK(seen.at.t == Approx(0.15f).margin(1e-4));
        CHECK(seen.values.at("patch")[0] == 1.0f);
        CHECK(seen.values.at("Cs")[0] == Approx(0.7f * 0.3f).margin(1e-4));  // bilinear toward the centre corner
        CHECK(look(grid + vars, -0.5f, 0.5f).values.at("patch")[0] == 2.0f);
        CHECK(look(grid + vars, 0.5f, 0.5f).values.at("patch")[0] == 3.0f);
    }
    SECTION("vertex values of a bicubic patch go through its basis, as its points do") {
        // A flat Bezier patch over [-1, 1]^2 whose "x" primvar is each control point's x: it reproduces x.
        std::string const patch = "WorldBegin\nTranslate 0 0 5\nPatch \"bicubic\" \"P\" [-1 -1 0  -0.3 -1 0  0.3 -1 0  1 -1 0  "
                                  "-1 -0.3 0  -0.3 -0.3 0  0.3 -0.3 0  1 -0.3 0  -1 0.3 0  -0.3 0.3 0  0.3 0.3 0  1 0.3 0  "
                                  "-1 1 0  -0.3 1 0  0.3 1 0  1 1 0] \"vertex float x\" [-1 -0.3 0.3 1  -1 -0.3 0.3 1  "
                                  "-1 -0.3 0.3 1  -1 -0.3 0.3 1]";
        for (float x : {-0.8f, 0.1f, 0.55f}) CHECK(look(patch, x, 0.2f).values.at("x")[0] == Approx(x).margin(2e-3));
    }
    SECTION("a bent bilinear patch interpolates its corners' varying values") {
        std::string const patch = "WorldBegin\nTranslate 0 0 5\nPatch \"bilinear\" \"P\" [-1 -1 0  1 -1 0.5  -1 1 0.5  1 1 0] "
                                  "\"varying float w\" [0 1 2 3]";
        CHECK(look(patch, 0.0f, 0.0f).values.at("w")[0] == Approx(1.5f).margin(0.02));
        CHECK(look(patch, 0.9f, -0.9f).values.at("w")[0] == Approx(1.0f).margin(0.1));
    }
    SECTION("a count that does not fit the layout is an error at the parameter") {
        checkCountErrors(
            grid, {{"\"varying float w\" [0 1 2 3]", "needs 9 values here (one per patch corner), got 4"},
                   {"\"uniform float w\" [0 1 2]", "needs 4 values here (one per patch), got 3"}});
    }
}

TEST_CASE(
    "a NuPatch's primvars follow the RI specification's layout: per control point, segment corner and "
    "segment",
    "[rib][geometry][primvars][nurbs]") {
    // Linear in u over two segments (knots 0 0 1 2 2: x = u - 1), one segment in v (y = 2 v - 1), seen from z
    // = 0.
    std::string const strip =
        "WorldBegin\nTranslate 0 0 5\nNuPatch 3 2 [0 0 1 2 2] 0 2 2 2 [0 0 1 1] 0 1 "
        "\"P\" [-1 -1 0  0 -1 0  1 -1 0  -1 1 0  0 1 0  1 1 0] ";
    auto const look = sampleAlongZ;
    SECTION(
        "varying values sit at the segments' corners, uniform ones on the segments, and st gives s and t") {
        std::string const vars =
            "\"varying float w\" [0 1 2  10 11 12] \"uniform float segment\" [5 7] "
            "\"varying float[2] st\" [0 1  0.5 1  1 1  0 0  0.5 0  1 0]";
        SurfaceSample seen = look(strip + vars, 0.3f, -0.6f);  // u = 1.3, v = 0.2
        CHECK(seen.at.u == Approx(1.3f).margin(1e-4));
        CHECK(seen.at.v == Approx(0.2f).margin(1e-4));
        CHECK(seen.values.at("w")[0] == Approx(1.3f + 10.0f * 0.2f).margin(1e-4));
        CHECK(seen.values.at("segment")[0] == 7.0f);
        CHECK(look(strip + vars, -0.3f, -0.6f).values.at("segment")[0] == 5.0f);
        CHECK(seen.at.s == Approx(0.65f).margin(1e-4));
        CHECK(seen.at.t == Approx(0.8f).margin(1e-4));  // t runs the other way
    }
    SECTION("vertex values go through the rational basis, as the points do") {
        // A quadratic arc of weights 1 2 1, flat in z = 0, whose x at u is (2u - 1) / (1 + 2u - 2u^2): the
        // primvar "x", each control point's x, gives that only when weighted as the points are (unweighted,
        // it would be 2u - 1, up to 0.09 away). It is compared at the u the hit reports, as a tessellated
        // surface's u is itself interpolated.
        std::string const rational =
            "WorldBegin\nTranslate 0 0 5\nNuPatch 3 3 [0 0 0 1 1 1] 0 1 2 2 [0 0 1 1] 0 1 "
            "\"Pw\" [-1 -1 0 1  0 -2 0 2  1 -1 0 1  -1 1 0 1  0 2 0 2  1 1 0 1] "
            "\"vertex float x\" [-1 0 1  -1 0 1] \"point Pref\" [-1 -1 0  0 -1 0  1 -1 0  "
            "-1 1 0  0 1 0  1 1 0]";
        for (float x : {-0.7f, 0.3f, 0.8f}) {
            CAPTURE(x);
            SurfaceSample seen = look(rational, x, 0.4f);
            float const u = seen.at.u, surfaceX = (2 * u - 1) / (1 + 2 * u - 2 * u * u);
            CHECK(surfaceX == Approx(x).margin(0.03));  // the hit's u is near where x is
            CHECK(seen.values.at("x")[0] == Approx(surfaceX).margin(1e-4));
            CHECK(seen.values.at("Pref")[0] == Approx(surfaceX).margin(1e-4));
            CHECK(seen.values.at("Pref")[1] == Approx(0.4f).margin(1e-4));
        }
    }
    SECTION("a count that does not fit the layout is an error at the parameter") {
        checkCountErrors(
            strip, {{"\"varying float w\" [0 1 2]", "needs 6 values here (one per segment corner), got 3"},
                    {"\"uniform float w\" [0 1 2]", "needs 2 values here (one per segment), got 3"},
                    {"\"vertex float w\" [0 1 2 3]", "needs 6 values here (one per control point), got 4"}});
    }
}

TEST_CASE("Curves keep their primvars: one per curve, per segment end and per control vertex",
          "[rib][geometry][primvars][curves]") {
    // Vertical tubes 0.4 wide in the plane z = 5, seen from z = 0; a segment's parameter runs up them.
    std::string const head = "WorldBegin\nTranslate 0 0 5\n";
    std::string const twoLines = head +
                                 "Curves \"linear\" [2 2] \"nonperiodic\" \"constantwidth\" [0.4] "
                                 "\"P\" [-1.5 -0.5 0  -1.5 0.5 0  1 -0.5 0  1 0.5 0] ";
    auto const look = sampleAlongZ;
    SECTION("uniform values are one per curve, varying ones blend along each segment") {
        std::string const vars =
            "\"varying color Cs\" [1 0 0  0 0 1  0 1 0  1 1 0] \"uniform float id\" [1 2]";
        SurfaceSample left = look(twoLines + vars, -1.5f, 0.2f), right = look(twoLines + vars, 1.0f, -0.3f);
        CHECK(left.values.at("id")[0] == 1.0f);
        CHECK(right.values.at("id")[0] == 2.0f);
        CHECK(left.values.at("Cs")[0] == Approx(0.3f).margin(0.01));
        CHECK(left.values.at("Cs")[2] == Approx(0.7f).margin(0.01));
        CHECK(right.values.at("Cs")[0] == Approx(0.2f).margin(0.01));
        CHECK(right.values.at("Cs")[1] == Approx(1.0f).margin(1e-4));
        // A varying st gives the curves' s and t.
        SurfaceSample textured = look(twoLines + "\"varying float[2] st\" [0 0  0 1  1 0  1 1]", 1.0f, -0.3f);
        CHECK(textured.at.s == Approx(1.0f));
        CHECK(textured.at.t == Approx(0.2f).margin(0.01));
    }
    SECTION("vertex values of a cubic curve go through its basis, as its points do") {
        // A b-spline of six vertices evenly up y (three segments): the primvar "h", each vertex's y,
        // is the height of the curve wherever it is hit.
        std::string const spline = head +
                                   "Basis \"b-spline\" 1 \"b-spline\" 1\n"
                                   "Curves \"cubic\" [6] \"nonperiodic\" \"constantwidth\" [0.4] "
                                   "\"P\" [0 -1 0  0 -0.6 0  0 -0.2 0  0 0.2 0  0 0.6 0  0 1 0] "
                                   "\"vertex float h\" [-1 -0.6 -0.2 0.2 0.6 1]";
        for (float y : {-0.45f, 0.1f, 0.5f})
            CHECK(look(spline, 0.0f, y).values.at("h")[0] == Approx(y).margin(0.01));
    }
    SECTION("a count that does not fit the curves is an error at the parameter") {
        checkCountErrors(
            twoLines,
            {{"\"varying float w\" [0 1 2]", "needs 4 values here (one per segment end), got 3"},
             {"\"uniform float w\" [1 2 3]", "needs 2 values here (one per curve), got 3"},
             {"\"vertex float w\" [1 2 3]", "needs 4 values here (one per control vertex), got 3"}});
    }
}

TEST_CASE("free-form shapes: subdivision surface, NURBS patch, curves, points and blobby", "[rib][geometry]") {
    auto hitDistance = [](std::string const& rib, Vec3 org = Vec3(0.0f), Vec3 dir = Vec3(0, 0, 1)) {
        Diagnostics diagnostics(false);
        Scene scene = test::parseRib("WorldBegin\n" + rib, diagnostics);
        REQUIRE(scene.shapes.size() == 1u);
        RayTracer tracer(scene);
        HitRecord hit = trace(tracer, org, dir);
        if (!hit.hit()) return -1.0f;
        SurfaceBasics b = scene.shapes[0]->basics(hit);
        CHECK(std::fabs(glm::dot(b.N, dir)) > 0.5f);  // a normal across the surface, not along it
        return hit.t;
    };
    SECTION("a Catmull-Clark cube shrinks toward a rounded blob inside its cage") {
        std::string cube = "Translate 0 0 5\nSubdivisionMesh \"catmull-clark\" [4 4 4 4 4 4] "
                           "[0 1 3 2  2 3 7 6  6 7 5 4  4 5 1 0  1 5 7 3  4 0 2 6] [\"interpolateboundary\"] [0 0] [] [] "
                           "\"P\" [-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1  1 1 1]\n";
        float t = hitDistance(cube);
        CHECK(t > 4.05f);  // inside the cage (its face is at 4)
        CHECK(t < 4.5f);
        // A sharp crease along every edge keeps the cube's faces flat.
        std::string creased = "Translate 0 0 5\nSubdivisionMesh \"catmull-clark\" [4 4 4 4 4 4] "
                              "[0 1 3 2  2 3 7 6  6 7 5 4  4 5 1 0  1 5 7 3  4 0 2 6] "
                              "[\"crease\" \"crease\" \"crease\" \"crease\" \"crease\" \"crease\"] [5 1 5 1 2 1 2 1 2 1 2 1] "
                              "[0 1 3 2 0  4 5 7 6 4  0 4  1 5  3 7  2 6] [10 10 10 10 10 10] "
                              "\"P\" [-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1  1 1 1]\n";
        CHECK(hitDistance(creased, Vec3(0.3f, 0.2f, 0.0f)) == Approx(4.0f).margin(0.02));
    }
    SECTION("a hole is not rendered but keeps shaping the faces around it, as in RenderMan; also in a hierarchical mesh") {
        // The cube with its +x face a hole: the -z face in front of the ray keeps the shape the whole
        // cube gives it (exporters split meshes into pieces that hold their neighbours as holes, and
        // the pieces must meet), and a ray through the hole reaches the inside of the far face.
        std::string const faces = "[4 4 4 4 4 4] [0 1 3 2  2 3 7 6  6 7 5 4  4 5 1 0  1 5 7 3  4 0 2 6] ";
        std::string const cage = "\"P\" [-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1  1 1 1]\n";
        std::string const whole = "Translate 0 0 5\nSubdivisionMesh \"catmull-clark\" " + faces +
                                  "[\"interpolateboundary\"] [0 0] [] [] " + cage;
        std::string const holed = "Translate 0 0 5\nSubdivisionMesh \"catmull-clark\" " + faces +
                                  "[\"interpolateboundary\" \"hole\"] [0 0 1 0] [4] [] " + cage;
        for (float x : {0.0f, 0.6f})
            CHECK(hitDistance(holed, Vec3(x, 0.0f, 0.0f)) == Approx(hitDistance(whole, Vec3(x, 0.0f, 0.0f))).epsilon(1e-5));
        CHECK(hitDistance(holed, Vec3(5.0f, 0.0f, 5.0f), Vec3(-1, 0, 0)) > 5.5f);  // through the hole to the -x face
        CHECK(hitDistance(whole, Vec3(5.0f, 0.0f, 5.0f), Vec3(-1, 0, 0)) < 4.5f);
        // A hierarchical mesh gives three counts per tag (integers, floats, strings), as RenderMan
        // for Maya writes it: the same cube, read with a string argument in front.
        std::string const hierarchical = "Translate 0 0 5\nHierarchicalSubdivisionMesh \"catmull-clark\" " + faces +
                                         "[\"creasemethod\" \"interpolateboundary\" \"hole\"] [0 0 1  1 0 0  1 0 0] [1 4] [] "
                                         "[\"chaikin\"] " + cage;
        for (Vec3 org : {Vec3(0.0f), Vec3(0.6f, 0.0f, 0.0f), Vec3(5.0f, 0.0f, 5.0f)}) {
            Vec3 const dir = org.x > 1.0f ? Vec3(-1, 0, 0) : Vec3(0, 0, 1);
            CHECK(hitDistance(hierarchical, org, dir) == Approx(hitDistance(holed, org, dir)).epsilon(1e-6));
        }
    }
    SECTION("a patch given as a height field (\"Pz\") spans [0, 1] in x and y") {
        CHECK(hitDistance("Translate -0.5 -0.5 5\nPatchMesh \"bilinear\" 3 \"nonperiodic\" 3 \"nonperiodic\" "
                          "\"Pz\" [0.5 0.5 0.5  0.5 0.5 0.5  0.5 0.5 0.5]\n") == Approx(5.5f).epsilon(1e-5));
        CHECK(hitDistance("Translate -0.5 -0.5 5\nPatch \"bilinear\" \"Pz\" [0 0 0 0]\n", Vec3(0.45f, 0.45f, 0.0f)) ==
              Approx(5.0f).epsilon(1e-5));
        CHECK(hitDistance("Translate -0.5 -0.5 5\nPatch \"bilinear\" \"Pz\" [0 0 0 0]\n", Vec3(0.55f, 0.0f, 0.0f)) < 0.0f);
    }
    SECTION("a NuPatch of order 2 is its control quad; Pw divides by w") {
        CHECK(hitDistance("NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"P\" [-1 -1 5  1 -1 5  -1 1 5  1 1 5]\n") ==
              Approx(5.0f).epsilon(1e-4));
        CHECK(hitDistance("NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"Pw\" [-2 -2 10 2  2 -2 10 2  -2 2 10 2  2 2 10 2]\n") ==
              Approx(5.0f).epsilon(1e-4));
    }
    SECTION("a linear curve is a tube of its width; a point is a sphere of its width") {
        CHECK(hitDistance("Curves \"linear\" [2] \"nonperiodic\" \"P\" [-1 0 5  1 0 5] \"constantwidth\" [0.2]\n") ==
              Approx(4.9f).epsilon(1e-3));
        CHECK(hitDistance("Points \"P\" [0 0 5] \"constantwidth\" [1]\n") == Approx(4.5f).epsilon(1e-4));
        // "width" in each storage class: one value in all, one per curve, one per vertex.
        CHECK(hitDistance("Curves \"linear\" [2] \"nonperiodic\" \"P\" [-1 0 5  1 0 5] \"constant float width\" [0.2]\n") ==
              Approx(4.9f).epsilon(1e-3));
        std::string const twoCurves = "Curves \"linear\" [2 2] \"nonperiodic\" \"P\" [-1 0 5  1 0 5  -1 2 5  1 2 5] ";
        CHECK(hitDistance(twoCurves + "\"uniform float width\" [0.2 0.6]\n") == Approx(4.9f).epsilon(1e-3));
        CHECK(hitDistance(twoCurves + "\"uniform float width\" [0.6 0.2]\n") == Approx(4.7f).epsilon(1e-3));
        CHECK(hitDistance("Curves \"linear\" [3] \"nonperiodic\" \"P\" [-2 0 5  0 0 5  2 0 5] "
                          "\"vertex float width\" [0.1 0.4 0.1]\n") == Approx(4.8f).epsilon(1e-3));
        CHECK_THROWS_WITH(hitDistance(twoCurves + "\"uniform float width\" [0.2]\n"),
                          Catch::Matchers::Contains("\"width\" has too few values for the curves (uniform: 1 given)"));
        // A cubic curve (b-spline basis) through points on x = 0: hit from the side.
        CHECK(hitDistance("Basis \"b-spline\" 1 \"b-spline\" 1\nCurves \"cubic\" [4] \"nonperiodic\" "
                          "\"P\" [0 -3 5  0 -1 5  0 1 5  0 3 5] \"constantwidth\" [0.5]\n") == Approx(4.75f).epsilon(1e-2));
    }
    SECTION("a lone blobby ellipsoid is its unit sphere") {
        CHECK(hitDistance("Blobby 1 [1001 0] [1 0 0 0  0 1 0 0  0 0 1 0  0 0 5 1] [\"\"]\n") == Approx(4.0f).epsilon(0.01));
    }
}

TEST_CASE("Points keep a value per particle (\"varying color Cs\"), as a lecture's particle scene gives them", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nPoints \"P\" [-1 0 5  1 0 5] \"constantwidth\" [0.5] "
                                 "\"varying color Cs\" [0.2 0.9 0.3  0.8 0.1 0.6] \"uniform float id\" [7]\n",
                                 diagnostics);
    REQUIRE(scene.shapes.size() == 1u);
    CHECK(diagnostics.entries().empty());  // nothing left unused
    Shape const& points = *scene.shapes[0];
    Primvar const* Cs = points.primvars.find("Cs");
    Primvar const* id = points.primvars.find("id");
    REQUIRE(Cs);
    REQUIRE(id);
    RayTracer tracer(scene);
    for (int i = 0; i < 2; ++i) {
        HitRecord hit = trace(tracer, Vec3(i == 0 ? -1.0f : 1.0f, 0.0f, 0.0f), Vec3(0, 0, 1));
        REQUIRE(hit.hit());
        float color[3], value = 0.0f;
        points.primvar(*Cs, hit, color);
        points.primvar(*id, hit, &value);
        CHECK(color[0] == (i == 0 ? 0.2f : 0.8f));
        CHECK(color[2] == (i == 0 ? 0.3f : 0.6f));
        CHECK(value == 7.0f);  // one value: the whole shape's
    }
}

TEST_CASE("Points with normals are disks facing them and points without are spheres as in RenderMan",
          "[rib]") {
    // Each scene is one particle of width 1 (radius 0.5) at z = 5, seen along +z (distanceAlongZ: "N" is
    // used, not warned about).
    std::string const at = "Points \"P\" [0 0 5] \"constantwidth\" [1] ";
    CHECK(distanceAlongZ(at, Vec3(0.0f)) == Approx(4.5f).epsilon(1e-4));  // a sphere's front
    Vec3 n;
    CHECK(distanceAlongZ(at + "\"N\" [0 0 -1]", Vec3(0.0f), &n) ==
          Approx(5.0f).epsilon(1e-4));  // a flat disk
    CHECK(n.z == Approx(-1.0f));
    CHECK(distanceAlongZ(at + "\"N\" [0 0 -1]", Vec3(0.45f, 0.0f, 0.0f)) == Approx(5.0f).epsilon(1e-4));
    CHECK(distanceAlongZ(at + "\"N\" [0 0 -1]", Vec3(0.55f, 0.0f, 0.0f)) < 0.0f);  // beyond its radius
    // Tilted 45 degrees about x: the plane (p - c) . (0, 1, -1) = 0 meets the ray at y = 0.2 at z = 5.2.
    CHECK(distanceAlongZ(at + "\"varying normal N\" [0 1 -1]", Vec3(0.0f, 0.2f, 0.0f), &n) ==
          Approx(5.2f).epsilon(1e-4));
    CHECK(n.y == Approx(std::sqrt(0.5f)).epsilon(1e-4));
    // Edge on: the disk lies in the plane x = 0, which a ray beside it never crosses.
    CHECK(distanceAlongZ(at + "\"N\" [1 0 0]", Vec3(0.1f, 0.0f, 0.0f)) < 0.0f);
    // Normals turn with the object: rotated 90 degrees about y, a disk facing +x faces -z.
    CHECK(distanceAlongZ(
              "Translate 0 0 5\nRotate 90 0 1 0\nPoints \"P\" [0 0 0] \"constantwidth\" [1] \"N\" [1 0 0]",
              Vec3(0.0f), &n) == Approx(5.0f).epsilon(1e-4));
    CHECK(n.z == Approx(-1.0f).epsilon(1e-4));
    // Two points, one normal for both: both are disks.
    CHECK(distanceAlongZ("Points \"P\" [0 0 5  1 0 5] \"constantwidth\" [0.5] \"constant normal N\" [0 0 -1]",
                         Vec3(1, 0, 0)) == Approx(5.0f).epsilon(1e-4));
    Diagnostics diagnostics(false);
    CHECK_THROWS_WITH(
        test::parseRib("WorldBegin\nPoints \"P\" [0 0 5  1 0 5] \"N\" [0 0 -1  0 0 -1  0 0 -1]\n",
                       diagnostics),
        Catch::Matchers::Contains("test.rib:2:27") &&
            Catch::Matchers::Contains("\"N\" needs one normal per point (2) or one for all, got 9 numbers"));
    // A normal with no direction (zero, or collapsed by a Scale 0) is warned about: the points are spheres.
    Scene aimless =
        test::parseRib("WorldBegin\nPoints \"P\" [0 0 5  1 0 5] \"N\" [0 0 -1  0 0 0]\n", diagnostics);
    REQUIRE(diagnostics.entries().size() == 1u);
    CHECK_THAT(diagnostics.entries()[0].text,
               Catch::Matchers::Contains("\"N\" of point 1 has no direction for a disk to face") &&
                   Catch::Matchers::Contains("drawn as spheres"));
    CHECK(static_cast<Points const&>(*aimless.shapes.at(0)).normals().empty());
}

TEST_CASE("Curves with normals are flat ribbons facing them and curves without are round tubes", "[rib]") {
    // Each scene is one curve along x at z = 5, of width 0.2, seen along +z (distanceAlongZ: "N" is used, not
    // warned about).
    std::string const line =
        "Curves \"linear\" [2] \"nonperiodic\" \"P\" [-1 0 5  1 0 5] \"constantwidth\" [0.2] ";
    CHECK(distanceAlongZ(line, Vec3(0.0f)) == Approx(4.9f).epsilon(1e-3));  // a tube's front
    Vec3 n;
    CHECK(distanceAlongZ(line + "\"N\" [0 0 -1  0 0 -1]", Vec3(0.0f), &n) ==
          Approx(5.0f).epsilon(1e-3));  // flat
    CHECK(std::fabs(n.z) == Approx(1.0f).epsilon(1e-3));
    CHECK(distanceAlongZ(line + "\"N\" [0 0 -1  0 0 -1]", Vec3(0.3f, 0.09f, 0.0f)) ==
          Approx(5.0f).epsilon(1e-3));
    CHECK(distanceAlongZ(line + "\"N\" [0 0 -1  0 0 -1]", Vec3(0.3f, 0.11f, 0.0f)) <
          0.0f);  // beyond its half width
    // Facing +y it is edge on to the camera: a ray just beside the curve's line misses it...
    CHECK(distanceAlongZ(line + "\"N\" [0 1 0  0 1 0]", Vec3(0.3f, 0.03f, 0.0f)) < 0.0f);
    // ...and a ribbon that turns from facing the camera to facing +y narrows along its length.
    std::string const twist = line + "\"N\" [0 0 -1  0 1 0]";
    CHECK(distanceAlongZ(twist, Vec3(-0.9f, 0.08f, 0.0f)) > 0.0f);
    CHECK(distanceAlongZ(twist, Vec3(0.9f, 0.08f, 0.0f)) < 0.0f);
    // One normal for the whole curve, and vertex normals of a cubic curve through its basis.
    CHECK(distanceAlongZ(line + "\"constant normal N\" [0 0 -1]", Vec3(0.5f, 0.09f, 0.0f)) ==
          Approx(5.0f).epsilon(1e-3));
    CHECK(distanceAlongZ("Basis \"b-spline\" 1 \"b-spline\" 1\nCurves \"cubic\" [4] \"nonperiodic\" "
                         "\"P\" [-3 0 5  -1 0 5  1 0 5  3 0 5] \"constantwidth\" [0.2] "
                         "\"vertex normal N\" [0 0 -1  0 0 -1  0 0 -1  0 0 -1]",
                         Vec3(0.0f, 0.09f, 0.0f)) == Approx(5.0f).epsilon(1e-3));
    Diagnostics diagnostics(false);
    CHECK_THROWS_WITH(
        test::parseRib("WorldBegin\n" + line + "\"N\" [0 0 -1]\n", diagnostics),
        Catch::Matchers::Contains("\"N\" has too few values for the curves (varying: 3 numbers given)"));
    Scene aimless =
        test::parseRib("WorldBegin\nScale 1 0 1\n" + line + "\"N\" [0 0 -1  0 0 -1]\n", diagnostics);
    CHECK_THAT(diagnostics.entries().back().text,
               Catch::Matchers::Contains("\"N\" value 0 has no direction for a ribbon to face") &&
                   Catch::Matchers::Contains("drawn as round tubes"));
    CHECK(static_cast<Curves const&>(*aimless.shapes.at(0)).data().normals.empty());
}

TEST_CASE("area lights from geometry: AreaLightSource and PxrMeshLight shapes become lights or glow", "[rib][lights]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nAttributeBegin\n"
                                 "AreaLightSource \"PxrStdAreaLight\" \"key\" \"float exposure\" [2]\n"
                                 "Translate 0 3 0\nSphere 0.5 -0.5 0.5 360\nDisk 0 1 360\nAttributeEnd\n"
                                 "AttributeBegin\nLight \"PxrMeshLight\" \"panel\" \"float intensity\" [3]\n"
                                 "Polygon \"P\" [0 0 4  1 0 4  1 1 4  0 1 4]\nTorus 1 0.2 0 360 360\nAttributeEnd\n"
                                 "Sphere 1 -1 1 360\n",
                                 diagnostics);
    // The sphere and the disk are lights of their own kind, the polygon a mesh light of
    // two triangles; the torus glows; the last sphere is ordinary.
    REQUIRE(scene.lights.size() == 3u);
    CHECK(std::string(scene.lights[0]->kind()) == "PxrSphereLight");
    CHECK(std::string(scene.lights[1]->kind()) == "PxrDiskLight");
    CHECK(std::string(scene.lights[2]->kind()) == "PxrMeshLight");
    CHECK(scene.lights[0]->color.r == Approx(4.0f));  // 2^exposure
    CHECK(scene.lights[2]->color.r == Approx(3.0f));
    CHECK(static_cast<MeshLight const&>(*scene.lights[2]).surfaceArea() == Approx(1.0f));
    REQUIRE(scene.shapes.size() == 2u);
    CHECK(std::string(scene.shapes[0]->kind()) == "Torus");
    MaterialDesc const& glow = scene.materials[static_cast<size_t>(scene.shapes[0]->material)];
    CHECK(glow.plugin == "PxrConstant");
    CHECK(glow.params.getColor("emitColor", Vec3(0)) == Vec3(3.0f));
    CHECK(scene.materials[static_cast<size_t>(scene.shapes[1]->material)].plugin == "PxrDiffuse");
}

TEST_CASE("RenderMan 20's distant light is Geometry distantlight under an area light: the same light as PxrDistantLight",
          "[rib][lights]") {
    Diagnostics diagnostics(false);
    auto both = [&](std::string const& angle, std::string const& extent) {
        return test::parseRib(
            "WorldBegin\nAttributeBegin\nRotate 30 1 0 0\n"
            "AreaLightSource \"PxrStdAreaLight\" \"sun\" \"float exposure\" [12] \"string rman__Shape\" [\"distant\"]\n"
            "Geometry \"distantlight\" \"constant float anglesubtended\" [" + angle + "]\nAttributeEnd\n"
            "AttributeBegin\nRotate 30 1 0 0\nLight \"PxrDistantLight\" \"sun2\" \"float exposure\" [12]" + extent +
                "\nAttributeEnd\n",
            diagnostics);
    };
    // -1, as RenderMan for Maya writes it, is the default size (the sun's); a positive angle is the light's own.
    for (auto const& [angle, extent] : {std::pair<std::string, std::string>{"-1", ""}, {"4", " \"float angleExtent\" [4]"}}) {
        Scene scene = both(angle, extent);
        REQUIRE(scene.lights.size() == 2u);
        CHECK(std::string(scene.lights[0]->kind()) == "PxrDistantLight");
        CHECK(scene.lights[0]->color.r == Approx(scene.lights[1]->color.r));
        Vec3 const P(0.0f);
        LightSample a = scene.lights[0]->sample(P, Vec2(0.3f, 0.6f)), b = scene.lights[1]->sample(P, Vec2(0.3f, 0.6f));
        CHECK(glm::length(a.wi - b.wi) < 1e-5f);
        CHECK(a.radiance.r == Approx(b.radiance.r));
    }
    CHECK(test::warningsContaining(diagnostics, "distantlight") == 0);

    // An area light with no shape in its block lights nothing, and says so where it was given.
    Diagnostics unshaped(false);
    Scene none = test::parseRib("WorldBegin\nAttributeBegin\nAreaLightSource \"PxrStdAreaLight\" \"lost\"\nAttributeEnd\n"
                                "Sphere 1 -1 1 360\n",
                                unshaped, "lost.rib");
    CHECK(none.lights.empty());
    CHECK(test::warningsContaining(unshaped, "lost.rib:3:1: AreaLightSource \"PxrStdAreaLight\" \"lost\": no shape follows") == 1);
}

TEST_CASE("RenderMan 20's environment lights: an envsphere is the light at infinity, whatever its shader is called",
          "[rib][lights]") {
    // RenderMan for Maya 20 compiles each light into a shader named after its node.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(
        "WorldBegin\nAttributeBegin\nAreaLightSource \"proj/shaders/PxrStdEnvMapLightShape1_rfm\" \"env\" "
        "\"float exposure\" [1]\nGeometry \"envsphere\"\nAttributeEnd\n"
        "AttributeBegin\nAreaLightSource \"proj/shaders/PxrStdEnvDayLightShape1_rfm\" \"day\" \"vector direction\" "
        "[0 1 0] \"float haziness\" [3]\nGeometry \"envsphere\"\nAttributeEnd\n"
        "AttributeBegin\nAreaLightSource \"arealight\" \"plain\" \"intensity\" [0.5]\nGeometry \"envsphere\"\nAttributeEnd\n",
        diagnostics);
    REQUIRE(scene.lights.size() == 3u);
    CHECK(std::string(scene.lights[0]->kind()) == "PxrDomeLight");
    CHECK(scene.lights[0]->color.r == Approx(2.0f));  // 2^exposure
    CHECK(std::string(scene.lights[1]->kind()) == "PxrEnvDayLight");
    CHECK(std::string(scene.lights[2]->kind()) == "PxrDomeLight");
    CHECK(scene.lights[2]->color.r == Approx(0.5f));
    for (auto const& light : scene.lights) CHECK(light->isInfinite());
    // The day light's sun is straight up: a ray toward the zenith sees it, one toward the horizon does not.
    float distance = 0.0f, pdf = 0.0f;
    RtColorRGB up, side;
    scene.lights[1]->intersect(Vec3(0.0f), Vec3(0, 1, 0), distance, up, pdf);
    scene.lights[1]->intersect(Vec3(0.0f), glm::normalize(Vec3(1, 0.2f, 0)), distance, side, pdf);
    CHECK(up.r > 1000.0f * side.r);
}

TEST_CASE("RenderMan's own materials and integrators that are not here get a stand-in, with one warning each",
          "[rib][plugins]") {
    std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrUnified\" \"v\" \"int maxPathLength\" [3]\n"
                      "WorldBegin\nLight \"PxrDomeLight\" \"sky\"\nTranslate 0 0 5\n"
                      "Bxdf \"PxrSurface\" \"s\" \"color diffuseColor\" [0.8 0.2 0.1] \"float diffuseGain\" [0.5]\n"
                      "Sphere 1 -1 1 360\nBxdf \"PxrSurface\" \"t\"\nSphere 0.5 -0.5 0.5 360\nWorldEnd\n";
    auto r = test::renderRib(rib, test::withSpp(4));
    int surfaceWarnings = 0, integratorWarnings = 0;
    for (auto const& m : r.messages) {
        surfaceWarnings += m.text.find("\"PxrSurface\" is one of RenderMan's materials") != std::string::npos;
        integratorWarnings += m.text.find("\"PxrUnified\" is one of RenderMan's") != std::string::npos;
    }
    CHECK(surfaceWarnings == 1);
    CHECK(integratorWarnings == 1);
    CHECK(r.stats.integrator == "PxrPathTracer");
    // The stand-in keeps the colour: the centre pixel is red-dominated (0.8 x 0.5 against 0.1 x 0.5).
    CHECK(r.channel(4, 4, 0) > 3.0f * r.channel(4, 4, 2));
    // A Lama conductor is a metal of its reflectivity: gold reflects the white sky gold.
    auto gold = test::renderRib("Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nWorldBegin\n"
                                "Light \"PxrDomeLight\" \"sky\"\nTranslate 0 0 5\nBxdf \"LamaConductor\" \"g\" "
                                "\"color reflectivity\" [0.95 0.78 0.37]\nSphere 1 -1 1 360\nWorldEnd\n",
                                test::withSpp(16));
    CHECK(gold.anyMessageContains("rendered as a PxrDisney metal of its reflectivity"));
    CHECK(gold.channel(4, 4, 0) > 2.0f * gold.channel(4, 4, 2));
    // A misspelt integrator of no known kind stays an error.
    CHECK_THROWS_WITH(test::renderRib("Integrator \"PxrNoSuch\" \"x\"\nWorldBegin\nWorldEnd\n"),
                      Catch::Matchers::Contains("not found"));
}

TEST_CASE("RenderMan's glass materials stand in as chapter 10's refracting glass", "[rib][plugins]") {
    // A clear, lossless glass ball under a uniform sky of radiance 1 shows the sky through it: the
    // centre pixel is about 1 (a reflecting-only stand-in would be near 0.04).
    auto centre = [](std::string const& bxdf) {
        std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [20]\n"
                          "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [12]\nWorldBegin\n"
                          "Light \"PxrDomeLight\" \"sky\"\nTranslate 0 0 5\n" +
                          bxdf + "\nSphere 1 -1 1 360\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(64));
        CHECK(r.anyMessageContains("rendered as a refracting glass"));
        return Vec3(r.channel(4, 4, 0), r.channel(4, 4, 1), r.channel(4, 4, 2));
    };
    Vec3 clear = centre("Bxdf \"PxrGlass\" \"g\" \"float ior\" [1.5]");
    CHECK(clear.x == Approx(1.0f).epsilon(0.05));
    CHECK(clear.z == Approx(1.0f).epsilon(0.05));
    // PxrSurface's glass lobe (refractionGain > 0) is the same glass; its refraction colour tints
    // each crossing (two, through a ball), its reflections stay white.
    CHECK(centre("Bxdf \"PxrSurface\" \"s\" \"float diffuseGain\" [0] \"float refractionGain\" [1] "
                 "\"float glassIor\" [1.5] \"float glassRoughness\" [0]") == clear);
    CHECK(centre("Bxdf \"LamaDielectric\" \"l\" \"float IOR\" [1.5]") == clear);
    Vec3 green = centre("Bxdf \"PxrLMGlass\" \"g\" \"float eta\" [1.5] \"color refractionColor\" [0.5 1 0.5]");
    CHECK(green.y == Approx(clear.y).epsilon(0.05));
    CHECK(green.x < 0.4f * green.y);
}

TEST_CASE("a stand-in whose textured colour cannot be loaded keeps the original's untextured colour", "[rib][plugins]") {
    // PxrSurface's diffuse colour from an absent pattern: the surface is PxrSurface's grey 0.18 (times
    // its gain), not the stand-in PxrDisney's own default base colour (0.2, 0.5, 0.8).
    std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nWorldBegin\nLight \"PxrDomeLight\" \"sky\"\n"
                      "Translate 0 0 5\nPattern \"NoSuchPattern\" \"tex\"\n"
                      "Bxdf \"PxrSurface\" \"s\" \"reference color diffuseColor\" [\"tex:resultRGB\"] \"float diffuseGain\" [0.5]\n"
                      "Sphere 1 -1 1 360\nWorldEnd\n";
    auto r = test::renderRib(rib, test::withSpp(16));
    CHECK(r.anyMessageContains("Pattern \"tex\" cannot be used"));
    float red = r.channel(4, 4, 0), blue = r.channel(4, 4, 2);
    CHECK(red == Approx(blue).epsilon(0.02));       // grey, not blue
    CHECK(red == Approx(0.09f).epsilon(0.1));       // 0.18 x 0.5 under a white sky of radiance 1
}

TEST_CASE("a stand-in keeps the gain on a textured colour: PxrSurface's diffuseGain scales its connected diffuseColor",
          "[rib][plugins]") {
    auto centre = [](float gain) {
        std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nWorldBegin\nLight \"PxrDomeLight\" \"sky\"\n"
                          "Translate 0 0 5\nPattern \"PxrMix\" \"tex\" \"color color1\" [1 0.2 0.2] \"float mix\" [0]\n"
                          "Bxdf \"PxrSurface\" \"s\" \"reference color diffuseColor\" [\"tex:resultRGB\"] \"float diffuseGain\" [" +
                          std::to_string(gain) + "]\nSphere 1 -1 1 360\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(16));
        return Vec3(r.channel(4, 4, 0), r.channel(4, 4, 1), r.channel(4, 4, 2));
    };
    Vec3 full = centre(1.0f), half = centre(0.5f);
    CHECK(full.x > 4.0f * full.y);  // still the texture's red
    CHECK(half.x == Approx(0.5f * full.x).epsilon(1e-4));
    CHECK(half.y == Approx(0.5f * full.y).epsilon(1e-4));
}

TEST_CASE("a PxrSurface with no diffuse and a coloured specular face (an exporter's metal) stands in as a metal of "
          "that colour, and with physical Fresnel the colour its index gives", "[rib][plugins]") {
    auto centre = [](std::string const& params) {
        std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrPathTracer\" \"p\"\n"
                          "WorldBegin\nLight \"PxrDomeLight\" \"sky\"\nTranslate 0 0 5\nBxdf \"PxrSurface\" \"s\" " + params +
                          "\nSphere 1 -1 1 360\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(16));
        return Vec3(r.channel(4, 4, 0), r.channel(4, 4, 1), r.channel(4, 4, 2));
    };
    // Gold under a white sky of radiance 1: about its face colour at normal view, not a black ball's grey glint.
    Vec3 const gold = centre("\"float diffuseGain\" [0] \"color specularFaceColor\" [0.9 0.6 0.2] \"float specularRoughness\" [0.1]");
    CHECK(gold.x == Approx(0.9f).epsilon(0.1));
    CHECK(gold.x > 3.0f * gold.z);
    // With a diffuse colour the face colour stays a dielectric's reflectance: the ball keeps its diffuse blue.
    Vec3 const plastic = centre("\"color diffuseColor\" [0.1 0.1 0.8] \"color specularFaceColor\" [0.9 0.6 0.2]");
    CHECK(plastic.z > 2.0f * plastic.x);
    // Physical Fresnel (specularFresnelMode 1) reads the index and extinction instead of the face colour:
    // glass's 1.5 reflects 4% at normal view, and gold's index (n 0.18 0.42 1.37, k 3.42 2.35 1.77) gold.
    std::string const black = "\"float diffuseGain\" [0] \"int specularFresnelMode\" [1] \"float specularRoughness\" [0.05] ";
    CHECK(centre(black + "\"color specularIor\" [1.5 1.5 1.5]").y == Approx(0.04f).epsilon(0.2));
    Vec3 const physicalGold = centre(black + "\"color specularIor\" [0.18 0.42 1.37] \"color specularExtinctionCoeff\" [3.42 2.35 1.77]");
    CHECK(physicalGold.x > 0.8f);
    CHECK(physicalGold.x > 2.0f * physicalGold.z);
    // Values no material has stay finite and reflect no more than arrives.
    CHECK(std::isfinite(centre(black + "\"color specularIor\" [-1 -1 -1]").x));
    CHECK(centre("\"float diffuseGain\" [0] \"color specularFaceColor\" [3 3 3]").x <= 1.01f);
}

TEST_CASE("PxrBlack stands in as what it is: black and opaque", "[rib][plugins]") {
    // A ball under a white sky of radiance 1, in front of a white wall that is seen around it.
    std::string const rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrPathTracer\" \"p\"\n"
                            "WorldBegin\nLight \"PxrDomeLight\" \"sky\"\nTranslate 0 0 5\nBxdf \"PxrBlack\" \"hole\"\n"
                            "Sphere 1 -1 1 360\nBxdf \"PxrDiffuse\" \"wall\" \"color diffuseColor\" [1 1 1]\n"
                            "Polygon \"P\" [-9 -9 1.2  9 -9 1.2  9 9 1.2  -9 9 1.2]\nWorldEnd\n";
    auto r = test::renderRib(rib, test::withSpp(16));
    for (int c = 0; c < 3; ++c) CHECK(r.channel(4, 4, c) == 0.0f);
    CHECK(r.channel(4, 4, 3) == 1.0f);      // opaque: nothing of the wall shows through
    CHECK(r.channel(0, 0, 0) > 0.3f);        // the wall around it is lit
    CHECK(r.anyMessageContains("PxrDiffuse in black, which is what PxrBlack is"));
}

TEST_CASE("a stand-in keeps a cut-out (presence below 1 or textured), but for glass, which says it renders it opaque",
          "[rib][plugins]") {
    auto render = [](std::string const& material, std::string const& params, std::string const& pattern = "") {
        std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nWorldBegin\nTranslate 0 0 5\n" + pattern +
                          "Bxdf \"" + material + "\" \"leaf\" " + params + "\nSphere 1 -1 1 360\nWorldEnd\n";
        return test::renderRib(rib, test::withSpp(1));
    };
    auto opaque = [](test::RenderOutcome const& r, std::string const& material) {
        return r.anyMessageContains("Bxdf \"" + material +
                                    "\" \"leaf\": its presence (a cut-out) is not rendered by the stand-in; the "
                                    "surface is opaque");
    };
    auto half = render("PxrSurface", "\"float presence\" [0.5]");
    CHECK_FALSE(opaque(half, "PxrSurface"));
    CHECK(half.stats.presencePoints > 0u);
    auto textured = render("PxrSurface", "\"reference float presence\" [\"alpha:resultR\"]",
                           "Pattern \"PxrMix\" \"alpha\" \"color color1\" [1 0 0]\n");
    CHECK_FALSE(opaque(textured, "PxrSurface"));
    CHECK(textured.stats.presencePoints > 0u);
    auto diffuse = render("PxrLMDiffuse", "\"float presence\" [0]");
    CHECK(diffuse.stats.presencePoints > 0u);
    CHECK(diffuse.stats.image.litFraction == 0.0);  // nothing left to see
    auto full = render("PxrSurface", "\"float presence\" [1]");
    CHECK(full.stats.presencePoints == 0u);
    CHECK(opaque(render("PxrGlass", "\"float presence\" [0.5]"), "PxrGlass"));
}

TEST_CASE("a PxrSurface stand-in glows as PxrSurface does: glowGain x glowColor, plain or textured, off by default",
          "[rib][plugins]") {
    // No light at all: what the camera sees of the ball is its own glow.
    auto centre = [](std::string const& params, std::string const& pattern = "") {
        std::string rib = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrPathTracer\" \"p\"\n"
                          "WorldBegin\nTranslate 0 0 5\n" + pattern + "Bxdf \"PxrSurface\" \"s\" " + params +
                          "\nSphere 1 -1 1 360\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(4));
        return Vec3(r.channel(4, 4, 0), r.channel(4, 4, 1), r.channel(4, 4, 2));
    };
    Vec3 const glow = centre("\"float glowGain\" [0.5] \"color glowColor\" [1 0.2 0.1]");
    CHECK(glow.x == Approx(0.5f));
    CHECK(glow.y == Approx(0.1f));
    CHECK(glow.z == Approx(0.05f));
    CHECK(centre("\"float glowGain\" [2]") == Vec3(2.0f));  // glowColor's default is white
    CHECK(centre("\"color glowColor\" [1 1 1]") == Vec3(0.0f));  // glowGain's default is 0
    CHECK(centre("\"float glowGain\" [1] \"color glowColor\" [-1 0.5 -1]") == Vec3(0.0f, 0.5f, 0.0f));  // no negative light
    Vec3 const textured = centre("\"reference color glowColor\" [\"tex:resultRGB\"] \"float glowGain\" [0.5]",
                                 "Pattern \"PxrMix\" \"tex\" \"color color1\" [0.2 0.4 0.8] \"float mix\" [0]\n");
    CHECK(textured.x == Approx(0.1f));
    CHECK(textured.z == Approx(0.4f));
}

TEST_CASE("primvars reach plugins (GetPrimVar): constant, per-face, per-vertex and per-corner values", "[rib][primvars]") {
    std::string const head = "Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                             "Integrator \"PxrDefault\" \"d\"\nWorldBegin\nTranslate 0 0 5\n";
    RenderSettings settings;
    settings.spp = 4;
    auto pixel = [](test::RenderOutcome const& r, int x, int y) {
        return Vec3(r.channel(x, y, 0), r.channel(x, y, 1), r.channel(x, y, 2));
    };
    SECTION("a constant color on a sphere") {
        auto r = test::renderRib(head + "Bxdf \"primvar\" \"p\"\nSphere 1 -1 1 360 \"constant color Cs\" [0.2 0.4 0.6]\n",
                                 settings);
        Vec3 c = pixel(r, 8, 8);
        CHECK(c.x == Approx(0.2f));
        CHECK(c.z == Approx(0.6f));
    }
    SECTION("a per-vertex float across a square: 0 on the left, 1 on the right") {
        auto r = test::renderRib(head + "Bxdf \"primvar\" \"p\" \"string floatPrimvar\" \"ramp\"\n"
                                        "Polygon \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] \"varying float ramp\" [0 1 1 0]\n",
                                 settings);
        CHECK(pixel(r, 1, 8).x < 0.15f);
        CHECK(pixel(r, 14, 8).x > 0.85f);
        CHECK(pixel(r, 8, 8).x == Approx(0.5f).margin(0.07));
    }
    SECTION("one colour per face of a mesh") {
        auto r = test::renderRib(head + "Bxdf \"primvar\" \"p\"\nPointsPolygons [4 4] [0 1 4 3  1 2 5 4] "
                                        "\"P\" [-1 -1 0  0 -1 0  1 -1 0  -1 1 0  0 1 0  1 1 0] "
                                        "\"uniform color Cs\" [1 0 0  0 0 1]\n",
                                 settings);
        CHECK(pixel(r, 3, 8) == Vec3(1, 0, 0));
        CHECK(pixel(r, 12, 8) == Vec3(0, 0, 1));
    }
    SECTION("RenderMan's form with a fill value: the fill where a shape lacks the primvar") {
        std::string const halves = "Polygon \"P\" [-1 -1 0  0 -1 0  0 1 0  -1 1 0] \"constant color Cs\" [1 0 0]\n"
                                   "Polygon \"P\" [0 -1 0  1 -1 0  1 1 0  0 1 0]\n";
        auto r = test::renderRib(head + "Bxdf \"primvar\" \"p\" \"color fill\" [0 0.5 0]\n" + halves, settings);
        CHECK(pixel(r, 3, 8) == Vec3(1, 0, 0));
        CHECK(pixel(r, 12, 8) == Vec3(0, 0.5f, 0));
        auto none = test::renderRib(
            head + "Bxdf \"primvar\" \"p\" \"string colorPrimvar\" \"absent\" \"color fill\" [0 0.5 0]\n" + halves,
            settings);
        CHECK(pixel(none, 3, 8) == Vec3(0, 0.5f, 0));
    }
    SECTION("texture coordinates, Rix::k_st, on every surface: its st primvar, TextureCoordinates, else (u, v)") {
        // A bilinear patch's u runs left to right and v top to bottom; blue is the filter radius (none here).
        std::string const patch = "Patch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\n";
        auto uv = test::renderRib(head + "Bxdf \"primvar\" \"p\" \"string pairPrimvar\" \"st\"\n" + patch, settings);
        CHECK(pixel(uv, 1, 8).x == Approx(1.5f / 16).margin(0.02));
        CHECK(pixel(uv, 14, 8).x == Approx(14.5f / 16).margin(0.02));
        CHECK(pixel(uv, 8, 1).y == Approx(1.5f / 16).margin(0.02));
        CHECK(pixel(uv, 8, 14).y == Approx(14.5f / 16).margin(0.02));
        CHECK(pixel(uv, 8, 8).z == 0.0f);
        auto mapped = test::renderRib(head + "Bxdf \"primvar\" \"p\" \"string pairPrimvar\" \"st\"\n"
                                             "TextureCoordinates 1 0  0 0  1 1  0 1\n" + patch,
                                      settings);
        CHECK(pixel(mapped, 1, 8).x == Approx(14.5f / 16).margin(0.02));  // s reversed
        auto given = test::renderRib(head + "Bxdf \"primvar\" \"p\" \"string pairPrimvar\" \"st\"\n"
                                            "Polygon \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] "
                                            "\"facevarying float[2] st\" [0.25 0.5  0.25 0.5  0.25 0.5  0.25 0.5]\n",
                                     settings);
        CHECK(pixel(given, 8, 8) == Vec3(0.25f, 0.5f, 0.0f));
        auto other = test::renderRib(head + "Bxdf \"primvar\" \"p\" \"string pairPrimvar\" \"absent\"\n" + patch,
                                     settings);
        CHECK(pixel(other, 8, 8) == Vec3(0.0f));  // another float[2] name: the fill
    }
    SECTION("four corner values over a quadric's (u, v); none on a second shape") {
        // A disk's u runs around it and v inward from the rim: the corners give v = 0 black, v = 1 white.
        auto r = test::renderRib(head + "Bxdf \"primvar\" \"p\" \"string floatPrimvar\" \"g\"\n"
                                        "Disk 0 1 360 \"varying float g\" [0 0 1 1]\nTranslate 5 0 0\nSphere 0.5 -0.5 0.5 360\n",
                                 settings);
        CHECK(pixel(r, 8, 8).x > 0.8f);   // the centre: v near 1
        CHECK(pixel(r, 8, 0).x < 0.2f);   // the rim
    }
    SECTION("the default material shows Cs: a mesh coloured per vertex, lit") {
        auto r = test::renderRib("Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                                 "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\nLightSource \"distantlight\" 1\n"
                                 "Translate 0 0 5\nPolygon \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] "
                                 "\"varying color Cs\" [1 0 0  1 0 0  0 1 0  0 1 0]\n",
                                 settings);
        CHECK(pixel(r, 8, 14).x > 3.0f * pixel(r, 8, 14).y);  // bottom rows red
        CHECK(pixel(r, 8, 1).y > 3.0f * pixel(r, 8, 1).x);    // top rows green
    }
}

TEST_CASE("TextureCoordinates map a parametric surface's (u, v) to (s, t)", "[rib][primvars]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nTextureCoordinates 0 0 2 0 0 4 2 4\nTranslate 0 0 5\n"
                                 "Patch \"bilinear\" \"P\" [-1 -1 0  1 -1 0  -1 1 0  1 1 0]\n",
                                 diagnostics);
    REQUIRE(scene.shapes.size() == 1u);
    CHECK(scene.shapes[0]->hasTextureCoordinates);
    CHECK(scene.shapes[0]->textureCoordinates[6] == 2.0f);
    CHECK(scene.shapes[0]->textureCoordinates[7] == 4.0f);
}

TEST_CASE("PxrLightEmission glows with a light's intensity * 2^exposure * lightColor", "[rib][lights]") {
    RenderSettings settings;
    settings.spp = 1;
    auto r = test::renderRib("Format 4 4 1\nProjection \"orthographic\"\nScreenWindow -0.1 0.1 -0.1 0.1\n"
                             "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\nTranslate 0 0 5\n"
                             "Bxdf \"PxrLightEmission\" \"glow\" \"float intensity\" [3] \"float exposure\" [1] "
                             "\"color lightColor\" [1 0.5 0.25]\nSphere 1 -1 1 360\n",
                             settings);
    CHECK(r.channel(2, 2, 0) == Approx(6.0f));
    CHECK(r.channel(2, 2, 2) == Approx(1.5f));
}

TEST_CASE("a bilinear patch's N shades it: the blend of its corners' normals, as RenderMan interpolates them",
          "[scene][patches]") {
    // A flat square facing the camera, lit straight on by a distant light (PxrDistantLight shines along
    // +z, the way the camera looks): a diffuse surface shows cos of its shading normal's tilt.
    auto render = [](std::string const& patch) {
        std::string rib = "Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                          "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n"
                          "Light \"PxrDistantLight\" \"sun\" \"float angleExtent\" [0]\n"
                          "Bxdf \"PxrDiffuse\" \"d\" \"color diffuseColor\" [1 1 1]\nTranslate 0 0 5\n" +
                          patch + "\nWorldEnd\n";
        return test::renderRib(rib, test::withSpp(4));
    };
    std::string const corners = "\"P\" [-1 -1 0  1 -1 0  -1 1 0  1 1 0]";
    auto flat = render("Patch \"bilinear\" " + corners);
    double const s = std::sin(3.14159265 / 6), c = std::cos(3.14159265 / 6);
    std::string const tilted = std::to_string(s) + " 0 " + std::to_string(-c);
    auto even = render("Patch \"bilinear\" " + corners + " \"N\" [" + tilted + " " + tilted + " " + tilted + " " + tilted + "]");
    CHECK(even.channel(8, 8, 0) / flat.channel(8, 8, 0) == Approx(c).epsilon(1e-3));
    CHECK(even.channel(1, 14, 0) / flat.channel(1, 14, 0) == Approx(c).epsilon(1e-3));
    // A PatchMesh whose left corners lean one way and right corners the other: upright at the middle,
    // leaning (and darker) toward the sides, and the same on both.
    std::string const left = std::to_string(-s) + " 0 " + std::to_string(-c) + " ";
    std::string const right = std::to_string(s) + " 0 " + std::to_string(-c) + " ";
    auto mesh = render("PatchMesh \"bilinear\" 2 \"nonperiodic\" 2 \"nonperiodic\" " + corners + " \"varying normal N\" [" +
                       left + right + left + right + "]");
    CHECK(mesh.channel(8, 8, 0) / flat.channel(8, 8, 0) > 0.99);
    CHECK(mesh.channel(0, 8, 0) / flat.channel(0, 8, 0) < 0.93);
    CHECK(mesh.channel(0, 8, 0) == Approx(mesh.channel(15, 8, 0)).epsilon(1e-3));
    // A count that does not fit is a located error.
    CHECK_THROWS_WITH(render("PatchMesh \"bilinear\" 2 \"nonperiodic\" 2 \"nonperiodic\" " + corners + " \"N\" [0 0 -1]"),
                      Catch::Matchers::Contains("\"N\" needs one normal per control point (4), got 3 numbers"));
}

TEST_CASE("Surface \"defaultsurface\" shades by the angle it is seen at: Cs (Ka + Kd (I.N)^2), whatever the lights",
          "[rib][classic]") {
    // A unit sphere seen straight on: at a pixel centred (x, 0) the normal's z is sqrt(1 - x^2).
    auto render = [](std::string const& light) {
        return test::renderRib("Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                               "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n" + light +
                                   "Color [1 0.5 0.25]\nSurface \"defaultsurface\"\nTranslate 0 0 5\nSphere 1 -1 1 360\nWorldEnd\n",
                               test::withSpp(16));
    };
    auto dark = render("");
    auto lit = render("LightSource \"distantlight\" 1 \"intensity\" [3] \"from\" [0 5 0] \"to\" [0 0 5]\n");
    for (int x : {8, 11, 13}) {
        double const u = -1.0 + (x + 0.5) / 8.0, facingSq = 1.0 - u * u;
        INFO("pixel " << x);
        CHECK(dark.channel(x, 7, 0) == Approx(0.2 + 0.8 * facingSq).epsilon(0.03));
        CHECK(dark.channel(x, 7, 2) == Approx(0.25 * (0.2 + 0.8 * facingSq)).epsilon(0.03));
        CHECK(lit.channel(x, 7, 0) == Approx(dark.channel(x, 7, 0)).epsilon(1e-5));
    }
}

TEST_CASE("a NURBS sphere shades as smoothly as the quadric, its poles included", "[rib][geometry]") {
    // The rational quadratic unit sphere: a circle in u (9 points), a half circle in v (5), each
    // control point the product of the two, premultiplied by its weight. At its poles a whole row of
    // control points meets in one point, where dPdu is zero.
    double const s = std::sqrt(0.5);
    double const circle[9][3] = {{1, 0, 1}, {1, 1, s}, {0, 1, 1}, {-1, 1, s}, {-1, 0, 1}, {-1, -1, s}, {0, -1, 1}, {1, -1, s}, {1, 0, 1}};
    double const half[5][3] = {{0, -1, 1}, {1, -1, s}, {1, 0, 1}, {1, 1, s}, {0, 1, 1}};
    std::string Pw;
    for (auto const& v : half)
        for (auto const& u : circle) {
            double const w = u[2] * v[2];
            for (double x : {u[0] * v[0] * w, u[1] * v[0] * w, v[1] * w, w}) Pw += std::to_string(x) + " ";
        }
    auto render = [](std::string const& shape) {
        // PxrDefault's headlight: the shading follows the normal the camera sees.
        return test::renderRib("Format 64 64 1\nProjection \"orthographic\"\nScreenWindow -1.1 1.1 -1.1 1.1\nWorldBegin\n"
                               "Bxdf \"PxrDiffuse\" \"d\"\nTranslate 0 0 5\nRotate 60 1 1 0\n" + shape + "\nWorldEnd\n",
                               test::withSpp(16));
    };
    auto quadric = render("Sphere 1 -1 1 360");
    auto nurbs = render("NuPatch 9 3 [0 0 0 .25 .25 .5 .5 .75 .75 1 1 1] 0 1 5 3 [0 0 0 .5 .5 1 1 1] 0 1 \"Pw\" [" + Pw + "]");
    double sum = 0.0, worst = 0.0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            double d = std::fabs(quadric.channel(x, y, 0) - nurbs.channel(x, y, 0));
            sum += d;
            worst = std::max(worst, d);
        }
    // Tessellated with interpolated normals, about 0.002 on average and 0.015 at worst (on values
    // near 0.5); flat facets, which a zero normal at the poles once gave the whole sphere, 0.007 and 0.04.
    CHECK(sum / (64 * 64) < 0.0035);
    CHECK(worst < 0.025);
}

TEST_CASE("dicing controls and 8-bit or float quantizing are accepted without a word", "[rib]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("Quantize \"rgba\" 255 0 255 0.5\nQuantize \"z\" 0 0 0 0\n"
                                 "GeometricApproximation \"motionfactor\" 0\nWorldBegin\n"
                                 "ShadingInterpolation \"smooth\"\nShadingInterpolation \"constant\"\n"
                                 "Sphere 1 -1 1 360\nWorldEnd\n",
                                 diagnostics);
    CHECK(scene.shapes.size() == 1u);
    CHECK(diagnostics.entries().empty());
    // A depth the image formats here do not write is said; a misspelt interpolation is an error at its line.
    test::parseRib("Quantize \"rgba\" 65535 0 65535 0.5\n", diagnostics);
    CHECK(test::warningsContaining(diagnostics, "file format's own depth") == 1);
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nShadingInterpolation \"bumpy\"\nWorldEnd\n", diagnostics),
                      Catch::Contains("test.rib:2:1") && Catch::Contains("\"constant\" or \"smooth\""));
}

TEST_CASE("TrimCurve cuts a NuPatch where its loops say, for camera and shadow rays alike", "[rib][geometry]") {
    // A 2 x 2 patch at z = 5, (u, v) = ((x + 1) / 2, (y + 1) / 2): an outer loop around its whole
    // domain (linear) and a circle of radius 0.25 about its middle (rational quadratic, u and v
    // written times w, as homogeneous points are). The odd winding rule keeps the ring between them,
    // so a disk of radius 0.5 in the middle is cut out.
    std::string const trim = "TrimCurve [1 1] [2 3] [0 0 1 2 3 4 4  0 0 0 .25 .25 .5 .5 .75 .75 1 1 1] [0 0] [4 1] [5 9]\n"
                             "  [0 1 1 0 0  0.75 0.53033 0.5 0.176777 0.25 0.176777 0.5 0.53033 0.75]\n  [0 0 1 1 0  0.5 0.53033 0.75 0.53033 0.5 0.176777 0.25 0.176777 0.5]\n  [1 1 1 1 1  1 0.707107 1 0.707107 1 0.707107 1 0.707107 1]\n";
    std::string const patch = "NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"P\" [-1 -1 5  1 -1 5  -1 1 5  1 1 5]\n";
    CHECK(distanceAlongZ(patch, Vec3(0.0f)) == Approx(5.0f));
    CHECK(distanceAlongZ(trim + patch, Vec3(0.0f)) == -1.0f);
    CHECK(distanceAlongZ(trim + patch, Vec3(0.45f, 0.0f, 0.0f)) == -1.0f);  // just inside the circle
    CHECK(distanceAlongZ(trim + patch, Vec3(0.0f, -0.45f, 0.0f)) == -1.0f);
    CHECK(distanceAlongZ(trim + patch, Vec3(0.55f, 0.0f, 0.0f)) == Approx(5.0f));  // just outside it
    CHECK(distanceAlongZ(trim + patch, Vec3(0.36f, 0.36f, 0.0f)) == Approx(5.0f));  // 0.509 from the middle
    CHECK(distanceAlongZ(trim + patch, Vec3(0.34f, 0.34f, 0.0f)) == -1.0f);        // 0.481
    // "sense" "outside" keeps the disk alone.
    std::string const outside = "Attribute \"trimcurve\" \"sense\" \"outside\"\n";
    CHECK(distanceAlongZ(outside + trim + patch, Vec3(0.0f)) == Approx(5.0f));
    CHECK(distanceAlongZ(outside + trim + patch, Vec3(0.7f, 0.0f, 0.0f)) == -1.0f);
    // An attribute: a patch after the block that gave it is whole.
    CHECK(distanceAlongZ("AttributeBegin\n" + trim + "AttributeEnd\n" + patch, Vec3(0.0f)) == Approx(5.0f));

    // Shadow rays pass through the hole and stop on the ring.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\n" + trim + patch, diagnostics);
    RayTracer tracer(scene);
    RayCounts counts;
    CHECK_FALSE(tracer.occluded(Vec3(0.0f), Vec3(0, 0, 1), 0.0f, 10.0f, 0.0f, counts));
    CHECK(tracer.occluded(Vec3(0.7f, 0.0f, 0.0f), Vec3(0, 0, 1), 0.0f, 10.0f, 0.0f, counts));

    // Arrays that do not fit together are an error at the request.
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nTrimCurve [1] [2] [0 0 1 1] [0] [1] [2] [0 1] [0 1] [1]\n",
                                     diagnostics),
                      Catch::Matchers::Contains("test.rib:2:1") &&
                          Catch::Matchers::Contains("u, v and w need one value per control point (2)"));
    CHECK_THROWS_WITH(test::parseRib("WorldBegin\nTrimCurve [1] [2] [0 0 1] [0] [1] [2] [0 1] [0 1] [1 1]\n",
                                     diagnostics),
                      Catch::Matchers::Contains("knot needs 4 values, got 3"));
}
