// Motion blur: motion blocks read into moving transforms and deforming meshes,
// rays that carry a time, shapes whose answers at a hit agree with where the
// ray tracer found them at that time, and images in which what moves is
// smeared over the shutter in the right proportion.
#include <catch2/catch.hpp>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "accel/RayTracer.h"
#include "scene/Motion.h"
#include "scene/shapes/TriangleMesh.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

HitRecord traceAt(RayTracer const& tracer, Vec3 org, Vec3 dir, float time) {
    RayCounts counts;
    return tracer.intersect(org, glm::normalize(dir), 0.0f, kInfinity, time, RayKind::Camera, counts);
}

Scene sceneWith(std::string const& rib, Diagnostics& diagnostics) { return test::parseRib(rib, diagnostics); }

/// The shape's own point at a hit is where the ray met it, at the ray's time.
void checkHitAgrees(Shape const& shape, HitRecord const& hit) {
    Vec3 const onRay = hit.org + hit.t * hit.dir;
    SurfaceBasics const at = shape.basics(hit);
    CHECK(glm::length(at.P - onRay) < 1e-4f);
    CHECK(glm::length(at.N) == Approx(1.0f).epsilon(1e-5));
}

/// A white patch one view wide sweeping onto the view of an orthographic 16 x 2 image while the shutter
/// is open: column x (0..1 across the view) covered for the last 1 - x of the time, the effects report
/// saying `effect`, and the same image with 1 thread as with 2.
void checkSweep(std::string const& rib, std::string const& effect) {
    RenderSettings settings = test::withSpp(1024);
    settings.threads = 2;
    test::RenderOutcome const two = test::renderRib(rib, settings);
    REQUIRE(two.width == 16);
    for (int x = 0; x < 16; ++x) {
        INFO("column " << x);
        double const covered = 1.0 - (x + 0.5) / 16.0;
        for (int y = 0; y < 2; ++y) CHECK(two.channel(x, y, 0) == Approx(covered).margin(0.04));
    }
    auto const& simulated = two.stats.effects.simulated;
    CHECK(std::any_of(simulated.begin(), simulated.end(),
                      [&](std::string const& line) { return line.find(effect) == 0; }));
    settings.threads = 1;
    CHECK(test::renderRib(rib, settings).rgba == two.rgba);
}

}  // namespace

TEST_CASE("Motion: a transform over time and the shutter's evenly spaced steps", "[motion]") {
    TransformPath path{{0.0f, 1.0f}, {Mat4(1.0f), glm::translate(Mat4(1.0f), Vec3(2, 0, 0))}};
    CHECK(path.at(0.25f)[3].x == Approx(0.5f));
    CHECK(path.at(-1.0f)[3].x == 0.0f);  // before the first time: the first value
    CHECK(path.at(3.0f)[3].x == 2.0f);   // after the last: the last
    // Times that divide the shutter evenly are its steps; uneven ones get steps as close as their
    // nearest two.
    CHECK(shutterSteps({0.0f, 1.0f}, 0.0f, 1.0f).size() == 2);
    CHECK(shutterSteps({0.0f, 0.5f, 1.0f}, 0.0f, 1.0f).size() == 3);
    CHECK(shutterSteps({0.0f, 0.2f, 1.0f}, 0.0f, 1.0f).size() == 6);
    CHECK(shutterSteps({0.0f, 1e-6f, 1.0f}, 0.0f, 1.0f).size() == 33);
    std::vector<float> const half = shutterSteps({0.0f, 1.0f}, 0.5f, 1.0f);
    REQUIRE(half.size() == 2);
    CHECK(half.front() == 0.5f);
    CHECK(half.back() == 1.0f);
    // A shape moves relative to where it stands as the shutter opens.
    auto motion = shapeMotion(path, 0.5f, 1.0f);
    REQUIRE(motion);
    CHECK(motion->steps.front() == Mat4(1.0f));
    CHECK(motion->at(1.0f)[3].x == Approx(1.0f));
    CHECK(motion->rate(0.3f)[3].x == Approx(1.0f));  // one unit over the half of the shutter it sees
    CHECK_FALSE(shapeMotion(path, 0.0f, 0.0f));     // a shutter that opens and closes at once
    CHECK_FALSE(shapeMotion(TransformPath{{0.0f, 1.0f}, {Mat4(1.0f), Mat4(1.0f)}}, 0.0f, 1.0f));
}

TEST_CASE("Motion blocks move the transform: shapes are where it puts them at each ray's time", "[rib][motion]") {
    // The sphere moves 2 along x over the shutter; what is concatenated after the block moves with it.
    Diagnostics diagnostics(false);
    Scene scene = sceneWith(
        "Shutter 0 1\nWorldBegin\nTranslate 0 0 5\n"
        "MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 2 0 0\nMotionEnd\n"
        "Sphere 1 -1 1 360\nTranslate 0 3 0\nSphere 1 -1 1 360\nWorldEnd\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 2);
    for (auto const& shape : scene.shapes) {
        REQUIRE(shape->motion);
        CHECK(shape->motion->at(1.0f)[3].x == Approx(2.0f));
        CHECK(shape->motion->at(1.0f)[3].y == Approx(0.0f).margin(1e-6));
    }
    CHECK(test::warningsContaining(diagnostics, "motion") == 0);
    // A time that repeats the first does not make the block still: there and back again moves.
    Scene back = sceneWith("Shutter 0 1\nWorldBegin\nMotionBegin [0 0.5 1]\nTranslate 0 0 0\nTranslate 2 0 0\n"
                           "Translate 0 0 0\nMotionEnd\nSphere 1 -1 1 360\nWorldEnd\n",
                           diagnostics);
    REQUIRE(back.shapes.size() == 1);
    REQUIRE(back.shapes[0]->motion);
    CHECK(back.shapes[0]->motion->at(0.5f)[3].x == Approx(2.0f));
    CHECK(back.shapes[0]->motion->at(1.0f)[3].x == Approx(0.0f).margin(1e-6));
    RayTracer tracer(scene);
    // A ray along x = 2 misses the sphere as the shutter opens and meets it as it closes.
    CHECK_FALSE(traceAt(tracer, Vec3(2, 0, 0), Vec3(0, 0, 1), 0.0f).hit());
    HitRecord const late = traceAt(tracer, Vec3(2, 0, 0), Vec3(0, 0, 1), 1.0f);
    REQUIRE(late.hit());
    CHECK(late.t == Approx(4.0f).epsilon(1e-4));
    CHECK(late.time == 1.0f);
    // At any time, the shape's point, normal and speed agree with where the ray found it.
    for (float time : {0.3f, 0.55f, 0.8f, 1.0f}) {
        INFO("time " << time);
        Vec3 const centre(2.0f * time, 0.0f, 5.0f);
        HitRecord const hit = traceAt(tracer, Vec3(2.0f * time + 0.3f, 0.2f, 0.0f), Vec3(0, 0, 1), time);
        REQUIRE(hit.hit());
        checkHitAgrees(*scene.shapes[0], hit);
        SurfaceBasics const at = scene.shapes[0]->basics(hit);
        CHECK(glm::length(at.N - (at.P - centre)) < 1e-4f);  // a unit sphere's normal is its point less its centre
        Vec3 const velocity = scene.shapes[0]->velocity(hit);
        CHECK(velocity.x == Approx(2.0f).epsilon(1e-4));
        CHECK(std::abs(velocity.y) + std::abs(velocity.z) < 1e-4f);
        SurfaceTangents const tangents = scene.shapes[0]->tangents(hit);
        CHECK(std::abs(glm::dot(tangents.dPdu, at.N)) < 1e-4f);  // the tangents move with the surface
    }
}

TEST_CASE("Motion blocks: a turning transform moves triangles and quadrics alike", "[rib][motion]") {
    // A quarter turn about z in three steps; a patch, and a cylinder lying along x, turn with it.
    for (std::string const shape : {"Patch \"bilinear\" \"P\" [-1 -0.2 0  1 -0.2 0  -1 0.2 0  1 0.2 0]",
                                    "Rotate 90 0 1 0\nCylinder 0.2 -1 1 360"}) {
        Diagnostics diagnostics(false);
        Scene scene = sceneWith("Shutter 0 1\nWorldBegin\nTranslate 0 0 5\n"
                                "MotionBegin [0 0.5 1]\nRotate 0 0 0 1\nRotate 45 0 0 1\nRotate 90 0 0 1\nMotionEnd\n" +
                                    shape + "\nWorldEnd\n",
                                diagnostics);
        REQUIRE(scene.shapes.size() == 1);
        Shape const& turning = *scene.shapes[0];
        INFO(turning.kind());
        REQUIRE(turning.motion);
        CHECK(turning.motion->steps.size() == 3);
        RayTracer tracer(scene);
        // As the shutter opens the shape lies along x; as it closes, along y.
        Vec3 const alongX(0.8f, 0.0f, 0.0f), alongY(0.0f, 0.8f, 0.0f);
        CHECK(traceAt(tracer, alongX, Vec3(0, 0, 1), 0.0f).hit());
        CHECK_FALSE(traceAt(tracer, alongY, Vec3(0, 0, 1), 0.0f).hit());
        CHECK(traceAt(tracer, alongY, Vec3(0, 0, 1), 1.0f).hit());
        CHECK_FALSE(traceAt(tracer, alongX, Vec3(0, 0, 1), 1.0f).hit());
        for (float time : {0.1f, 0.4f, 0.7f, 0.95f}) {
            float const angle = glm::radians(90.0f * time);
            Vec3 const along(0.5f * std::cos(angle), 0.5f * std::sin(angle), 0.0f);
            HitRecord const hit = traceAt(tracer, along, Vec3(0, 0, 1), time);
            INFO("time " << time);
            REQUIRE(hit.hit());
            checkHitAgrees(turning, hit);
        }
    }
}

TEST_CASE("Motion blocks of polygons deform them, and other changes hold still with a warning", "[rib][motion]") {
    Diagnostics diagnostics(false);
    Scene scene = sceneWith(
        "Shutter 0 1\nWorldBegin\nTranslate 0 0 5\n"
        "MotionBegin [0 1]\nPolygon \"P\" [-1 -1 0  1 -1 0  0 0 0]\nPolygon \"P\" [-1 -1 0  1 -1 0  0 1 0]\nMotionEnd\n"
        "MotionBegin [0 1]\nColor 1 0 0\nColor 0 1 0\nMotionEnd\n"
        "TransformBegin\nTranslate 10 0 0\nMotionBegin [0 1]\nSphere 1 -1 1 360\nSphere 2 -2 2 360\nMotionEnd\n"
        "TransformEnd\n"
        "MotionBegin [0 0.5 1]\nCylinder 1 -1 1 360\nCylinder 1 -1 1 360\nCylinder 1 -1 1 360\nMotionEnd\n"
        "MotionBegin [0 1]\nTranslate 5 0 0\nMotionEnd\n"
        "WorldEnd\n",
        diagnostics);
    REQUIRE(scene.shapes.size() == 3);
    auto const* mesh = dynamic_cast<TriangleMesh const*>(scene.shapes[0].get());
    REQUIRE(mesh);
    REQUIRE(mesh->deformation());
    CHECK(mesh->deformation()->steps.size() == 2);
    CHECK(mesh->moves());
    CHECK_FALSE(mesh->motion);
    RayTracer tracer(scene);
    // The tip rises from y = 0 to y = 1: a point at y = 0.5 is covered from half way through.
    CHECK(traceAt(tracer, Vec3(0, 0.5f, 0), Vec3(0, 0, 1), 0.4f).geomID != 0);
    HitRecord const hit = traceAt(tracer, Vec3(0, 0.5f, 0), Vec3(0, 0, 1), 0.9f);
    REQUIRE(hit.geomID == 0);
    checkHitAgrees(*mesh, hit);
    Vec3 const velocity = mesh->velocity(hit);
    CHECK(velocity.y > 0.0f);
    CHECK(velocity.x == Approx(0.0f).margin(1e-5));
    // A sphere that changes its radius is not blurred: it keeps its first one, and says so.
    CHECK_FALSE(scene.shapes[1]->moves());
    CHECK(test::warningsContaining(diagnostics, "changes a Sphere") == 1);
    // One written again unchanged at every time is simply still.
    CHECK_FALSE(scene.shapes[2]->moves());
    CHECK(test::warningsContaining(diagnostics, "Cylinder") == 0);
    // A block with fewer requests than times holds still, with a warning; an attribute's first value holds.
    CHECK(test::warningsContaining(diagnostics, "has 2 times but 1 requests") == 1);
    CHECK(test::warningsContaining(diagnostics, "Color") == 0);
}

TEST_CASE("Motion blocks deform subdivision meshes, and fold a moving transform into the points", "[rib][motion]") {
    // A square cage whose top edge rises from y = 1 to y = 3 while the whole moves 1 along x.
    std::string const cage = "SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [\"interpolateboundary\"] [0 0] [] [] "
                             "\"P\" [-1 -1 0  1 -1 0  1 TOP 0  -1 TOP 0]\n";
    auto at = [&](std::string const& top) {
        std::string text = cage;
        text.replace(text.find("TOP"), 3, top);
        text.replace(text.find("TOP"), 3, top);
        return text;
    };
    Diagnostics diagnostics(false);
    Scene scene = sceneWith("Shutter 0 1\nWorldBegin\nTranslate 0 0 5\n"
                            "MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 1 0 0\nMotionEnd\n"
                            "MotionBegin [0 1]\n" + at("1") + at("3") + "MotionEnd\nWorldEnd\n",
                            diagnostics);
    REQUIRE(scene.shapes.size() == 1);
    Shape const& surface = *scene.shapes[0];
    REQUIRE(surface.deformation());
    CHECK_FALSE(surface.motion);  // the transform's motion is in the points
    CHECK(surface.deformation()->at(2, 1.0f) == Vec3(2.0f, 3.0f, 5.0f));
    RayTracer tracer(scene);
    // The top reaches y = 1.5 only late in the shutter; the left edge leaves x = -0.9 early on.
    CHECK_FALSE(traceAt(tracer, Vec3(0.5f, 1.5f, 0), Vec3(0, 0, 1), 0.0f).hit());
    CHECK(traceAt(tracer, Vec3(0.5f, 1.5f, 0), Vec3(0, 0, 1), 1.0f).hit());
    CHECK(traceAt(tracer, Vec3(-0.9f, 0.0f, 0), Vec3(0, 0, 1), 0.0f).hit());
    CHECK_FALSE(traceAt(tracer, Vec3(-0.9f, 0.0f, 0), Vec3(0, 0, 1), 1.0f).hit());
    for (float time : {0.25f, 0.5f, 0.75f}) {
        INFO("time " << time);
        HitRecord const hit = traceAt(tracer, Vec3(time, 0.2f, 0), Vec3(0, 0, 1), time);
        REQUIRE(hit.hit());
        SurfaceBasics const basics = surface.basics(hit);
        CHECK(std::abs(basics.N.z) == Approx(1.0f).epsilon(1e-3));  // the flat cage's limit surface faces z
        SurfaceTangents const tangents = surface.tangents(hit);
        CHECK(glm::length(tangents.dPdv) > 0.0f);
    }
}

TEST_CASE("Motion blocks under a shutter that does not open, or opens late", "[rib][motion]") {
    std::string const block = "MotionBegin [0 1]\nTranslate 0 0 0\nTranslate 2 0 0\nMotionEnd\nSphere 1 -1 1 360\n";
    Diagnostics diagnostics(false);
    // No Shutter: it opens and closes at 0, so the sphere stands still where the block's first time puts it.
    Scene still = sceneWith("WorldBegin\n" + block + "WorldEnd\n", diagnostics);
    REQUIRE(still.shapes.size() == 1);
    CHECK_FALSE(still.shapes[0]->moves());
    CHECK(still.shapes[0]->objectToWorld[3].x == 0.0f);
    // A shutter open from 0.5 to 1 sees the second half of the move: from x = 1 to x = 2.
    Scene late = sceneWith("Shutter 0.5 1\nWorldBegin\n" + block + "WorldEnd\n", diagnostics);
    REQUIRE(late.shapes.size() == 1);
    CHECK(late.shapes[0]->objectToWorld[3].x == Approx(1.0f));
    REQUIRE(late.shapes[0]->motion);
    CHECK(late.shapes[0]->motion->at(1.0f)[3].x == Approx(1.0f));
    CHECK_THROWS_WITH(sceneWith("Shutter 1 0\nWorldBegin\nWorldEnd\n", diagnostics),
                      Catch::Contains("closes before it opens"));
    CHECK_THROWS_WITH(sceneWith("WorldBegin\nMotionBegin [0 1 0.5]\nMotionEnd\nWorldEnd\n", diagnostics),
                      Catch::Contains("times must increase"));
    // A forgotten MotionEnd is said where the block is left, not read as a block that swallows the rest.
    CHECK_THROWS_WITH(
        sceneWith("WorldBegin\nMotionBegin [0 1]\nTranslate 0 0 0\nTranslate 1 0 0\nSphere 1 -1 1 360\nWorldEnd\n",
                  diagnostics),
        Catch::Contains("test.rib:6:1") && Catch::Contains("WorldEnd inside the motion block at test.rib:2:1"));
}

TEST_CASE("Motion blur: a patch sweeping across the view covers each column for its share of the shutter",
          "[render][motion]") {
    // After aqsis's mb_noise_test: the patch moves, from just left of the view onto it.
    std::string const rib =
        "Format 16 2 1\nShutter 0 1\nProjection \"orthographic\"\nScreenWindow 0 1 0 1\n"
        "Translate 0 0 1\nWorldBegin\nBxdf \"PxrConstant\" \"white\" \"color emitColor\" [1 1 1]\n"
        "MotionBegin [0 1]\nTranslate -1 0 0\nTranslate 0 0 0\nMotionEnd\n"
        "Patch \"bilinear\" \"P\" [0 -1 0  1 -1 0  0 2 0  1 2 0]\nWorldEnd\n";
    checkSweep(rib, "motion blur: 1 shape moves");
}

TEST_CASE("Motion blur: shadow rays leave at the time of the ray that found their point",
          "[render][motion]") {
    // The sweep above as a shadow: the camera sees a white wall at z = 2, lit along +z by a distant light
    // and by a sphere light far behind the camera and off to one side, out of the sun's way (a light sample
    // and a Bxdf sample per point, so each batch of points traces shadow rays twice). A strip the camera
    // cannot see sweeps between them as the patch does, so column x lies in its shadow for 1 - x of the time:
    // lit x of it.
    auto scene = [](bool occluder) {
        return std::string(
                   "Format 16 2 1\nShutter 0 1\nProjection \"orthographic\"\nScreenWindow 0 1 0 1\n"
                   "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n"
                   "AttributeBegin\nLight \"PxrDistantLight\" \"sun\" \"float intensity\" [50000] "
                   "\"float angleExtent\" [0]\nAttributeEnd\n"
                   "AttributeBegin\nTranslate 0 -300 -1000\nLight \"PxrSphereLight\" \"far\" "
                   "\"float intensity\" [4e5]\nAttributeEnd\n"
                   "Bxdf \"PxrDiffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                   "Patch \"bilinear\" \"P\" [-5 -5 2  5 -5 2  -5 5 2  5 5 2]\n") +
               (occluder ? "AttributeBegin\nAttribute \"visibility\" \"int camera\" [0]\n"
                           "MotionBegin [0 1]\nTranslate -1 0 0\nTranslate 0 0 0\nMotionEnd\n"
                           "Patch \"bilinear\" \"P\" [0 -1 1  1 -1 1  0 2 1  1 2 1]\nAttributeEnd\n"
                         : "") +
               "WorldEnd\n";
    };
    test::RenderOutcome const open = test::renderRib(scene(false), test::withSpp(64));
    test::RenderOutcome const swept = test::renderRib(scene(true), test::withSpp(1024));
    REQUIRE(swept.width == 16);
    double const lit = open.channel(8, 0, 0);
    REQUIRE(lit > 0.0);
    for (int x = 0; x < 16; ++x) {
        INFO("column " << x);
        for (int y = 0; y < 2; ++y)
            CHECK(swept.channel(x, y, 0) / lit == Approx((x + 0.5) / 16.0).margin(0.05));
    }
}

TEST_CASE("Motion blur: shading sees the time of its ray", "[render][motion]") {
    // PxrVariable "time" shows the builtin k_time: spread evenly over an open shutter, 0 when it does not open.
    std::string const world =
        "WorldBegin\nPattern \"PxrVariable\" \"when\" \"string variable\" [\"time\"]\n"
        "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"when:resultRGB\"]\n"
        "Patch \"bilinear\" \"P\" [-5 -5 2  5 -5 2  -5 5 2  5 5 2]\nWorldEnd\n";
    std::string const camera = "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\n";
    test::RenderOutcome const open = test::renderRib(camera + "Shutter 0 1\n" + world, test::withSpp(256));
    test::RenderOutcome const shut = test::renderRib(camera + world, test::withSpp(16));
    auto all = [](int, int) { return true; };
    CHECK(test::meanChannel(open, 0, all) == Approx(0.5).margin(0.01));
    CHECK(test::meanChannel(shut, 0, all) == 0.0);
}

TEST_CASE("Motion blur: a camera that moves while the shutter is open sees the world sweep past",
          "[render][motion]") {
    // The sweeping patch above, held still, and the camera moving instead: a motion block before
    // WorldBegin carries the patch from just left of the view onto it, column x covered for 1 - x of the
    // time.
    std::string const moving = "MotionBegin [0 1]\nTranslate -1 0 1\nTranslate 0 0 1\nMotionEnd\n";
    auto scene = [&](std::string const& shutter, std::string const& camera) {
        return "Format 16 2 1\n" + shutter + "Projection \"orthographic\"\nScreenWindow 0 1 0 1\n" + camera +
               "WorldBegin\nBxdf \"PxrConstant\" \"white\" \"color emitColor\" [1 1 1]\n"
               "Patch \"bilinear\" \"P\" [0 -1 0  1 -1 0  0 2 0  1 2 0]\nWorldEnd\n";
    };
    checkSweep(scene("Shutter 0 1\n", moving), "motion blur: the camera and 0 shapes move");
    // Also through Camera: the camera it saves moves as the one at WorldBegin would.
    checkSweep("Display \"x.exr\" \"openexr\" \"rgba\" \"string camera\" [\"main\"]\n" +
                   scene("Shutter 0 1\n", moving + "Camera \"main\"\nIdentity\n"),
               "motion blur: the camera and 0 shapes move");
    // A shutter that does not open sees the camera where it stands at time 0: the patch out of view.
    test::RenderOutcome const shut = test::renderRib(scene("", moving), test::withSpp(16));
    auto all = [](int, int) { return true; };
    CHECK(test::meanChannel(shut, 0, all) == 0.0);
    // PxrVCM joins light paths to a camera that holds still: it says so, and the patch stays out of view.
    test::RenderOutcome const held =
        test::renderRib("Integrator \"PxrVCM\" \"v\"\n" + scene("Shutter 0 1\n", moving), test::withSpp(16));
    CHECK(test::meanChannel(held, 0, all) == 0.0);
    CHECK(held.anyMessageContains(
        "joins light paths to a camera that holds still: the camera's motion is not rendered"));
}
