// Which way lights shine, as in RenderMan: disk and rect lights emit along
// their local +z, a distant light's light travels along +z, and the classic
// light shaders (LightSource) keep the brightness their scenes were made for.
#include <catch2/catch.hpp>
#include <cmath>

#include "scene/Camera.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

/// A white diffuse square facing the camera at z = 5 and one light given by
/// `light` (placed at the origin of its own block); the mean red of the image.
double litSquare(std::string const& light) {
    std::string rib = "Format 16 16 1\nProjection \"perspective\" \"fov\" [20]\nIntegrator \"PxrDirectLighting\" \"d\"\n"
                      "WorldBegin\n  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n" +
                      light +
                      "  AttributeEnd\n  Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                      "  Polygon \"P\" [-4 -4 5  4 -4 5  4 4 5  -4 4 5]\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 16;
    auto r = test::renderRib(rib, settings);
    return test::meanChannel(r, 0, [](int, int) { return true; });
}

}  // namespace

TEST_CASE("area and distant lights shine along their local +z: a surface on that side is lit, one behind is not",
          "[lights]") {
    for (std::string type : {"PxrRectLight", "PxrDiskLight", "PxrDistantLight"}) {
        CAPTURE(type);
        // A distant light's intensity is the radiance of a sun-sized disk (RenderMan's default is 50000).
        std::string intensity = type == "PxrDistantLight" ? "50000" : "2";
        std::string light = "  Light \"" + type + "\" \"l\" \"float intensity\" [" + intensity + "]\n";
        // At z = 3, +z points at the square's front (the side the camera sees).
        double facing = litSquare("  Translate 0 0 3\n" + light);
        double turned = litSquare("  Translate 0 0 3\n  Rotate 180 1 0 0\n" + light);
        CHECK(facing > 0.02);
        CHECK(turned == 0.0);
    }
}

TEST_CASE("a rect light under a ceiling turned with Rotate 90 1 0 0 lights the floor below it", "[lights]") {
    // The camera looks down from above (+y is up); the floor is at y = -2, the light at y = 1.
    std::string rib = "Format 16 16 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrDirectLighting\" \"d\"\n"
                      "Rotate -90 1 0 0\nTranslate 0 -6 0\n"
                      "WorldBegin\n  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n"
                      "  Translate 0 1 0\n  Rotate 90 1 0 0\n  Scale 2 2 1\n"
                      "  Light \"PxrRectLight\" \"ceiling\" \"float intensity\" [4]\n  AttributeEnd\n"
                      "  Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                      "  Polygon \"P\" [-4 -2 -4  4 -2 -4  4 -2 4  -4 -2 4]\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 16;
    auto r = test::renderRib(rib, settings);
    CHECK(test::meanChannel(r, 0, [](int, int) { return true; }) > 0.1);
}

TEST_CASE("classic light shaders: pointlight, spotlight and distantlight light what they face, ambientlight adds Ka",
          "[lights]") {
    // pointlight: intensity I at distance d gives a matte (Kd = 1) surface facing it the radiance I / d^2,
    // as the classic diffuse() did: the pi of the physically based Bxdf is in the light.
    std::string const head = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                             "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n";
    std::string const matte = "Surface \"matte\"\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 4;
    auto point = test::renderRib(head + "LightSource \"pointlight\" 1 \"intensity\" [8] \"from\" [0 0 3]\n" + matte, settings);
    CHECK(test::meanChannel(point, 0, [](int, int) { return true; }) == Approx(8.0 / 4.0).epsilon(1e-3));
    // distantlight from its default direction (0 0 0) -> (0 0 1): straight at the surface.
    auto distant = test::renderRib(head + "LightSource \"distantlight\" 1 \"intensity\" [0.7]\n" + matte, settings);
    CHECK(test::meanChannel(distant, 0, [](int, int) { return true; }) == Approx(0.7).epsilon(1e-3));
    // ...and aimed away, nothing.
    auto away = test::renderRib(head + "LightSource \"distantlight\" 1 \"intensity\" [0.7] \"to\" [0 0 -1]\n" + matte, settings);
    CHECK(test::meanChannel(away, 0, [](int, int) { return true; }) == 0.0);
    // A spotlight pointing at the surface lights it; pointing away it does not.
    auto spot = test::renderRib(head + "LightSource \"spotlight\" 1 \"intensity\" [8] \"from\" [0 0 3] \"to\" [0 0 5]\n" + matte,
                                settings);
    CHECK(test::meanChannel(spot, 0, [](int, int) { return true; }) == Approx(2.0).epsilon(1e-3));
    auto spotAway = test::renderRib(
        head + "LightSource \"spotlight\" 1 \"intensity\" [8] \"from\" [0 0 3] \"to\" [0 0 1]\n" + matte, settings);
    CHECK(test::meanChannel(spotAway, 0, [](int, int) { return true; }) == 0.0);
    // ambientlight: Ka * ambient, whatever the geometry (Ka = 1 for matte).
    auto ambient = test::renderRib(head + "LightSource \"ambientlight\" 1 \"intensity\" [0.25]\n" + matte, settings);
    CHECK(test::meanChannel(ambient, 0, [](int, int) { return true; }) == Approx(0.25).epsilon(1e-3));
    // Illuminate 1 0 turns the light off.
    auto off = test::renderRib(
        head + "LightSource \"distantlight\" 1 \"intensity\" [0.7]\nIlluminate 1 0\n" + matte, settings);
    CHECK(test::meanChannel(off, 0, [](int, int) { return true; }) == 0.0);
    // A distantlight whose "to" is its "from" has no direction: left out with a warning (a lecture
    // scene has one beside two good lights), the others still light the surface.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nLightSource \"distantlight\" 1 \"to\" [0 0 0]\n"
                                 "LightSource \"distantlight\" 2 \"intensity\" [0.7]\n",
                                 diagnostics, "pointless.rib");
    CHECK(scene.lights.size() == 1u);
    bool warned = false;
    for (auto const& entry : diagnostics.entries())
        warned = warned || entry.text.find("pointless.rib:2:1: LightSource \"distantlight\": \"from\" and \"to\" are the same "
                                           "point, so the light has no direction; it is left out") != std::string::npos;
    CHECK(warned);
}

TEST_CASE("a light given before WorldBegin is placed in camera space", "[lights]") {
    // A headlight-like pointlight at the camera, then the camera moves back by 3: the light moves with it.
    std::string rib = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                      "Integrator \"PxrDirectLighting\" \"d\"\n"
                      "LightSource \"pointlight\" 1 \"intensity\" [8]\nTranslate 0 0 3\nWorldBegin\n"
                      "Surface \"matte\"\nPolygon \"P\" [-10 -10 2  10 -10 2  10 10 2  -10 10 2]\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 4;
    auto r = test::renderRib(rib, settings);
    // The surface is at camera z = 5: 8 / 25.
    CHECK(test::meanChannel(r, 0, [](int, int) { return true; }) == Approx(8.0 / 25.0).epsilon(1e-3));
}

TEST_CASE("areaNormalize keeps a light's power whatever its size; without it power grows with area", "[lights]") {
    // A tiny patch of a white plane 20 units in front of a rect light of side 1 or 2.
    auto irradiance = [](float side, bool normalize) {
        std::string rib = "Format 4 4 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                          "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n  AttributeBegin\n"
                          "  Attribute \"visibility\" \"int camera\" [0]\n  Scale " +
                          std::to_string(side) + " " + std::to_string(side) +
                          " 1\n  Light \"PxrRectLight\" \"l\" \"float intensity\" [100] \"int areaNormalize\" [" +
                          (normalize ? "1" : "0") +
                          "]\n  AttributeEnd\n  Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                          "  Polygon \"P\" [-10 -10 20  10 -10 20  10 10 20  -10 10 20]\nWorldEnd\n";
        RenderSettings settings;
        settings.spp = 64;
        auto r = test::renderRib(rib, settings);
        return test::meanChannel(r, 0, [](int, int) { return true; });
    };
    CHECK(irradiance(2.0f, false) / irradiance(1.0f, false) == Approx(4.0).epsilon(0.02));
    CHECK(irradiance(2.0f, true) / irradiance(1.0f, true) == Approx(1.0).epsilon(0.02));
    // Normalized, a light of area A has radiance intensity / A: side 1 gives the same as without.
    CHECK(irradiance(1.0f, true) == Approx(irradiance(1.0f, false)).epsilon(1e-4));
}

TEST_CASE("the camera sees the nearest light: a rect light in front of the sky hides it, whatever the order",
          "[lights]") {
    for (bool skyFirst : {false, true}) {
        std::string const sky = "Light \"PxrDomeLight\" \"sky\" \"float intensity\" [0.1]\n";
        std::string const panel = "AttributeBegin\nTranslate 0 0 5\nRotate 180 0 1 0\n"
                                  "Light \"PxrRectLight\" \"panel\" \"float intensity\" [3]\nAttributeEnd\n";
        RenderSettings settings;
        settings.spp = 1;
        auto r = test::renderRib("Format 8 8 1\nProjection \"perspective\" \"fov\" [5]\nIntegrator \"PxrDirectLighting\" \"d\"\n"
                                 "WorldBegin\n" + (skyFirst ? sky + panel : panel + sky) + "WorldEnd\n",
                                 settings);
        CHECK(r.channel(4, 4, 0) == Approx(3.0f).epsilon(1e-4));
    }
}

TEST_CASE("camera rays skip lights out of view, and still see a light that is only partly in view", "[lights]") {
    // The chapter-6 key light sits beside the camera, outside its 15-degree view.
    CameraDesc desc;
    desc.projection = "perspective";
    desc.fov = 15.0f;
    Camera camera(desc, 800, 700, 1.0f);
    CHECK_FALSE(camera.mightSee(Vec3(-2.0f, 2.0f, 0.0f), 1.0f));
    CHECK_FALSE(camera.mightSee(Vec3(0.0f, 0.0f, -3.0f), 1.0f));  // behind
    CHECK(camera.mightSee(Vec3(0.0f, 0.0f, 8.0f), 0.5f));
    CHECK(camera.mightSee(Vec3(0.0f, 0.0f, 0.0f), 0.1f));  // around the eye

    // A disk light whose centre lies outside the frame but whose edge reaches
    // into the last column of pixels: those pixels see it (1 spp, radiance 3).
    for (char const* projection : {"\"perspective\" \"fov\" [40]", "\"orthographic\""}) {
        bool const perspective = std::string(projection).find("perspective") != std::string::npos;
        // Half the view at z = 5 is 5 tan 20 = 1.82 (perspective) or 1 (orthographic).
        std::string const x = perspective ? "1.95" : "1.13";
        RenderSettings settings;
        settings.spp = 1;
        auto r = test::renderRib("Format 16 16 1\nProjection " + std::string(projection) +
                                     "\nIntegrator \"PxrDirectLighting\" \"d\"\nWorldBegin\nTranslate " + x +
                                     " 0 5\nRotate 180 0 1 0\nLight \"PxrDiskLight\" \"edge\" \"float intensity\" [3]\n"
                                     "WorldEnd\n",
                                 settings);
        INFO(projection);
        CHECK(r.channel(15, 7, 0) == Approx(3.0f).epsilon(1e-4));
        CHECK(r.channel(15, 8, 0) == Approx(3.0f).epsilon(1e-4));
        CHECK(r.channel(0, 7, 0) == 0.0f);
    }
}
