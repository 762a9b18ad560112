// Which way lights shine, as in RenderMan: disk and rect lights emit along
// their local +z, a distant light's light travels along +z, and the classic
// light shaders (LightSource) keep the brightness their scenes were made for.
#include <catch2/catch.hpp>
#include <cmath>

#include "scene/Camera.h"
#include "scene/SceneBuilder.h"
#include "scene/lights/DayLight.h"
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

/// A white diffuse floor (y = -2, +y up) seen from above and lit by `light`; the mean red of the image.
double litFloor(std::string const& light, int spp) {
    std::string rib = "Format 16 16 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrDirectLighting\" \"d\"\n"
                      "Rotate -90 1 0 0\nTranslate 0 -6 0\n"
                      "WorldBegin\n  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n" +
                      light +
                      "  AttributeEnd\n  Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                      "  Polygon \"P\" [-4 -2 -4  4 -2 -4  4 -2 4  -4 -2 4]\nWorldEnd\n";
    return test::meanChannel(test::renderRib(rib, test::withSpp(spp)), 0, [](int, int) { return true; });
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

TEST_CASE("a portal light with no dome light is an opening onto a uniform sky: a rect light of its own colour",
          "[lights]") {
    std::string const portal = "  Translate 0 0 3\n  Light \"PxrPortalLight\" \"p\" \"float intensity\" [2]\n";
    std::string const rect = "  Translate 0 0 3\n  Light \"PxrRectLight\" \"r\" \"float intensity\" [2]\n";
    CHECK(litSquare(portal) > 0.02);
    CHECK(litSquare(portal) == litSquare(rect));
    // With a dome light the portal only guides its sampling here: the dome alone lights the square.
    std::string const dome = "  Light \"PxrDomeLight\" \"sky\" \"float intensity\" [0.5]\n";
    CHECK(litSquare(dome + portal) == litSquare(dome));
}

TEST_CASE("a rect light under a ceiling turned with Rotate 90 1 0 0 lights the floor below it", "[lights]") {
    // The light at y = 1, above the floor at y = -2.
    CHECK(litFloor("  Translate 0 1 0\n  Rotate 90 1 0 0\n  Scale 2 2 1\n"
                   "  Light \"PxrRectLight\" \"ceiling\" \"float intensity\" [4]\n",
                   16) > 0.1);
}

TEST_CASE("polygons under an area light are a light the integrators sample, as bright as a rect light of their shape",
          "[lights]") {
    // The same 2 x 2 square 3 above the floor: a PxrRectLight, then polygons.
    std::string const place = "  Translate 0 1 0\n  Rotate 90 1 0 0\n  Scale 2 2 1\n";
    double const rect = litFloor(place + "  Light \"PxrRectLight\" \"ceiling\" \"float intensity\" [4]\n", 64);
    // Counter-clockwise seen from +z (the rect light's emitting side): the front faces the floor.
    std::string const facingFloor = "  Polygon \"P\" [-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0]\n";
    std::string const facingUp = "  Polygon \"P\" [-0.5 -0.5 0  -0.5 0.5 0  0.5 0.5 0  0.5 -0.5 0]\n";
    std::string const classic = "  AreaLightSource \"PxrAreaLight\" \"ceiling\" \"float intensity\" [4]\n";
    std::string const meshLight = "  Light \"PxrMeshLight\" \"ceiling\" \"float intensity\" [4]\n";
    CHECK(rect > 0.1);
    // Two-sided (RIB's default Sides 2): either way round.
    CHECK(litFloor(place + classic + facingFloor, 64) == Approx(rect).epsilon(0.01));
    CHECK(litFloor(place + meshLight + facingUp, 64) == Approx(rect).epsilon(0.01));
    // Sides 1: the front face only.
    CHECK(litFloor(place + "  Sides 1\n" + meshLight + facingFloor, 64) == Approx(rect).epsilon(0.01));
    CHECK(litFloor(place + "  Sides 1\n" + meshLight + facingUp, 64) == 0.0);
    // A bilinear patch, as exporters write a card light, made of two triangles.
    CHECK(litFloor(place + meshLight + "  Patch \"bilinear\" \"P\" [-0.5 -0.5 0  0.5 -0.5 0  -0.5 0.5 0  0.5 0.5 0]\n",
                   64) == Approx(rect).epsilon(0.01));
    // A light hidden from every ray type still lights the scene (the openvkl smoke scene's cards).
    std::string const hidden = "  Attribute \"visibility\" \"int camera\" [0] \"int indirect\" [0] \"int transmission\" [0]\n";
    CHECK(litFloor(place + meshLight + hidden + facingFloor, 64) == Approx(rect).epsilon(0.01));
}

TEST_CASE("a light's lit face shadows what lies behind it from other lights, as it stops the Bxdf's rays",
          "[lights]") {
    // A dim two-sided panel 1 above the floor and a bright small light 2.5 above the panel:
    // the floor under the panel sees the panel's faint face, not the light beyond it. Shadow
    // rays used to pass the panel while the Bxdf's rays stopped at it, and MIS then counted
    // a part of the bright light there (350 times the panel's own light); PxrVCM's light
    // subpaths passed it too.
    std::string const hidden = "  Attribute \"visibility\" \"int camera\" [0]\n";
    std::string const panel = "  AttributeBegin\n" + hidden + "  Translate 0 -1 0\n  Rotate 90 1 0 0\n  Scale 3 3 1\n"
                              "  Light \"PxrMeshLight\" \"panel\" \"float intensity\" [0.001]\n"
                              "  Polygon \"P\" [-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0]\n  AttributeEnd\n";
    std::string const key = "  AttributeBegin\n" + hidden + "  Translate 0 1.5 0\n  Rotate 90 1 0 0\n  Scale 0.5 0.5 1\n"
                            "  Light \"PxrRectLight\" \"key\" \"float intensity\" [40]\n  AttributeEnd\n";
    std::string integrator;
    auto underPanel = [&integrator](std::string const& lights) {
        std::string rib = "Format 16 16 1\nProjection \"perspective\" \"fov\" [30]\n" + integrator +
                          "\nRotate -90 1 0 0\nTranslate 0 -6 0\nWorldBegin\n" + lights +
                          "  Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                          "  Polygon \"P\" [-4 -2 -4  4 -2 -4  4 -2 4  -4 -2 4]\nWorldEnd\n";
        return test::meanChannel(test::renderRib(rib, test::withSpp(64)), 0,
                                 [](int x, int y) { return x >= 6 && x < 10 && y >= 6 && y < 10; });
    };
    for (char const* name : {"Integrator \"PxrDirectLighting\" \"d\"", "Integrator \"PxrVCM\" \"v\" \"int maxPathLength\" [1]"}) {
        CAPTURE(name);
        integrator = name;
        double const panelAlone = underPanel(panel);
        CHECK(panelAlone > 0.0);
        CHECK(underPanel(panel + key) == Approx(panelAlone).epsilon(0.05));
    }
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
    // The Companion's shadowed lights are the same lights (their shadow maps are not needed to trace shadows).
    auto shadowed = test::renderRib(head + "LightSource \"shadowdistant\" 1 \"intensity\" [0.7] \"shadowname\" [\"l.shd\"]\n" +
                                        matte, settings);
    CHECK(test::meanChannel(shadowed, 0, [](int, int) { return true; }) == Approx(0.7).epsilon(1e-3));
    auto mean = [](test::RenderOutcome const& r) { return test::meanChannel(r, 0, [](int, int) { return true; }); };
    // Barzel's uberlight: a spotlight from its origin along +z (here 5 units from the surface); its
    // shaping parameters come untyped in old files. Its falloff is 0 by default: no distance falloff.
    auto uber = test::renderRib(head + "LightSource \"uberlight\" 1 \"intensity\" [25] \"height\" [2] \"wedge\" [0.2]\n" + matte,
                                settings);
    CHECK(mean(uber) == Approx(25.0).epsilon(1e-3));
    // falloff 2 is the inverse square, measured from falloffdist: (1 / 5)^2, (2 / 5)^2.
    auto uberSquare = test::renderRib(head + "LightSource \"uberlight\" 1 \"intensity\" [25] \"falloff\" [2]\n" + matte, settings);
    CHECK(mean(uberSquare) == Approx(1.0).epsilon(1e-3));
    auto uberFar = test::renderRib(
        head + "LightSource \"uberlight\" 1 \"intensity\" [25] \"falloff\" [1] \"falloffdist\" [2]\n" + matte, settings);
    CHECK(mean(uberFar) == Approx(10.0).epsilon(1e-3));
    // MTOR's l_uber writes falloffdist 0 beside a Maya decay rate: falloff 1 is then 1 / d.
    auto mayaDecay = test::renderRib(
        head + "LightSource \"l_uber\" 1 \"float intensity\" [25] \"float falloff\" [1] \"float falloffdist\" [0]\n" + matte,
        settings);
    CHECK(mean(mayaDecay) == Approx(5.0).epsilon(1e-3));
    // Its point light's six cube-face shadow maps (spx ... snz) mean it casts shadows; empty names do not.
    for (std::string const map : {"a.tex", ""}) {
        Diagnostics quiet(false);
        Scene withMaps = test::parseRib("WorldBegin\nLightSource \"l_uber\" 1 \"float lighttype\" [1] \"string spx\" [\"" +
                                            map + "\"]\n",
                                        quiet);
        REQUIRE(withMaps.lights.size() == 1u);
        CHECK(withMaps.lights[0]->castsShadows == !map.empty());
    }
    auto uberAway = test::renderRib(head + "TransformBegin\nRotate 180 1 0 0\nLightSource \"uberlight\" 1 \"intensity\" [25]\nTransformEnd\n" + matte,
                                    settings);
    CHECK(mean(uberAway) == 0.0);
    // MTOR's l_uber numbers its light types: 1 is omni, a point light lighting every way.
    auto omni = test::renderRib(head + "TransformBegin\nRotate 180 1 0 0\nLightSource \"l_uber\" 1 \"intensity\" [25] "
                                       "\"float lighttype\" [1]\nTransformEnd\n" + matte,
                                settings);
    CHECK(mean(omni) == Approx(25.0).epsilon(1e-3));
    // 3 is directional, and parallelrays makes any of them one: light along +z wherever the surface is
    // (here from 45 degrees, so the surface facing -z gets cos 45).
    for (std::string const kind : {"\"float lighttype\" [3]", "\"float parallelrays\" [1]"}) {
        auto parallel = test::renderRib(head + "TransformBegin\nTranslate 30 0 0\nRotate 45 0 1 0\nLightSource \"l_uber\" 1 "
                                               "\"intensity\" [2] " + kind + "\nTransformEnd\n" + matte,
                                        settings);
        CHECK(mean(parallel) == Approx(2.0 * std::cos(3.14159265 / 4)).epsilon(1e-3));
    }
    // l_uber's Maya cone: coneAngle is the full angle in degrees (10: 5 degrees off the axis), a
    // surface 4 degrees off the axis is lit, one 6 degrees off is not.
    auto tilted = [&](double degrees) {
        return mean(test::renderRib(head + "TransformBegin\nRotate " + std::to_string(degrees) +
                                        " 1 0 0\nLightSource \"l_uber\" 1 \"intensity\" [25] \"float coneAngle\" [10] "
                                        "\"float penumbraAngle\" [0]\nTransformEnd\n" + matte,
                                    settings));
    };
    CHECK(tilted(4.0) == Approx(25.0).epsilon(1e-3));
    CHECK(tilted(6.0) == 0.0);
    // A point light whose name says it has no falloff has none.
    auto noFalloff = test::renderRib(head + "LightSource \"pointnofalloff\" 1 \"intensity\" [0.5] \"from\" [0 0 -20]\n" + matte,
                                     settings);
    CHECK(mean(noFalloff) == Approx(0.5).epsilon(1e-3));
    // A distantlight whose "to" is its "from" has no direction: left out with a warning (a lecture
    // scene has one beside two good lights), the others still light the surface.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nLightSource \"distantlight\" 1 \"to\" [0 0 0]\n"
                                 "LightSource \"distantlight\" 2 \"intensity\" [0.7]\n",
                                 diagnostics, "pointless.rib");
    CHECK(scene.lights.size() == 1u);
    CHECK(test::warningsContaining(diagnostics, "pointless.rib:2:1: LightSource \"distantlight\": \"from\" and \"to\" are "
                                                "the same point, so the light has no direction; it is left out") == 1);
}

TEST_CASE("a classic metal's highlight is as narrow as PRMan's: Blinn's exponent 8 / roughness", "[lights][classic]") {
    // A surface facing the camera, a distant light at alpha from its normal: the half vector is alpha / 2
    // from the normal and the mirror direction alpha from the viewer. PRMan's specular() (which BMRT and
    // Aqsis emulate as max(0, N.H)^(8 / roughness)) is half its peak where cos(alpha / 2)^80 = 1/2 at
    // roughness 0.1; the stock Phong lobe of exponent 2 / roughness is cos(alpha)^20 there, times cos(alpha).
    double const roughness = 0.1, Ks = 0.8;
    double const alpha = 2.0 * std::acos(std::pow(0.5, roughness / 8.0));
    std::string const rib =
        "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\nWorldBegin\n"
        "LightSource \"distantlight\" 1 \"to\" [" + std::to_string(std::sin(alpha)) + " 0 " +
        std::to_string(std::cos(alpha)) + "]\nColor [1 1 1]\nSurface \"metal\" \"Ka\" [0] \"Ks\" [" +
        std::to_string(Ks) + "] \"roughness\" [" + std::to_string(roughness) +
        "]\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 4;
    double const highlight = test::meanChannel(test::renderRib(rib, settings), 0, [](int, int) { return true; });
    double const stockLobe = Ks * std::cos(alpha) * std::pow(std::cos(alpha), 2.0 / roughness);
    CHECK(highlight == Approx(stockLobe).epsilon(2e-3));
    // Within 5% of PRMan's half peak (less its cosine); the specification's 1 / roughness would give 0.91.
    CHECK(highlight / (Ks * std::cos(alpha)) == Approx(0.5).epsilon(0.05));
}

TEST_CASE("a LightSource without its handle is read as Aqsis and Pixie read it: the string after the shader is a "
          "parameter's name", "[lights]") {
    // A hand-written teaching file: LightSource "ambientlight" "intensity" [1], no sequence number.
    std::string const head = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                             "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n";
    std::string const matte = "Surface \"matte\"\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 4;
    auto mean = [](test::RenderOutcome const& r) { return test::meanChannel(r, 0, [](int, int) { return true; }); };
    auto point = test::renderRib(head + "LightSource \"pointlight\" \"intensity\" [8] \"from\" [0 0 3]\n" + matte, settings);
    CHECK(mean(point) == Approx(8.0 / 4.0).epsilon(1e-3));
    CHECK(point.anyMessageContains("test.rib:6:1: LightSource has no handle"));
    auto ambient = test::renderRib(head + "LightSource \"ambientlight\" \"intensity\" [0.25]\n" + matte, settings);
    CHECK(mean(ambient) == Approx(0.25).epsilon(1e-3));

    // With no parameters at all, and twice: two lights, one warning.
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib("WorldBegin\nLightSource \"distantlight\"\nLightSource \"distantlight\" "
                                 "\"from\" [0 1 0] \"to\" [0 0 0]\nLightSource \"spotlight\" \"key\" \"intensity\" [2]\n"
                                 "Illuminate \"key\" 0\n",
                                 diagnostics);
    CHECK(scene.lights.size() == 2u);  // the spotlight with its handle is named, and turned off by it
    CHECK(test::warningsContaining(diagnostics, "has no handle") == 1);
    // A handle followed by a string-valued parameter is still a handle.
    Diagnostics named(false);
    Scene withHandle = test::parseRib("WorldBegin\nLightSource \"shadowspot\" \"key\" \"shadowname\" \"raytrace\"\n"
                                      "Illuminate \"key\" 0\n",
                                      named);
    CHECK(withHandle.lights.empty());
    CHECK(test::warningsContaining(named, "has no handle") == 0);
}

TEST_CASE("a classic light is on the light list of the shapes after it in its attribute block", "[lights]") {
    // RenderMan's light list is an attribute: a LightSource lights the shapes that follow it until its
    // block ends, and not the shapes before it; one that no shape has lights nothing, with a warning.
    std::string const head = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                             "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n";
    std::string const light = "LightSource \"distantlight\" \"key\" \"intensity\" [0.7]\n";
    std::string const wall = "Surface \"matte\"\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\n";
    std::string const ball = "AttributeBegin\nTranslate 50 0 0\nSphere 0.1 -0.1 0.1 360\nAttributeEnd\n";  // out of view
    RenderSettings settings;
    settings.spp = 4;
    auto mean = [](test::RenderOutcome const& r) { return test::meanChannel(r, 0, [](int, int) { return true; }); };

    auto before = test::renderRib(head + light + wall + "WorldEnd\n", settings);
    CHECK(mean(before) == Approx(0.7).epsilon(1e-3));
    CHECK_FALSE(before.anyMessageContains("light list"));

    // Given inside a block that holds no shape: off for the wall after the block, and so for every shape.
    auto scoped = test::renderRib(head + "AttributeBegin\n" + light + "AttributeEnd\n" + wall + "WorldEnd\n", settings);
    CHECK(mean(scoped) == 0.0);
    CHECK(scoped.anyMessageContains("test.rib:7:1: light \"key\" is not on the light list of every shape"));

    // Given after the wall, for a ball: the ball is lit and the wall is not (Houdini's shadow-map passes
    // write their lights this way).
    auto after = test::renderRib(head + wall + light + ball + "WorldEnd\n", settings);
    CHECK(mean(after) == 0.0);
    CHECK_FALSE(after.anyMessageContains("light list"));

    // Illuminate puts a light back on the list.
    auto back = test::renderRib(head + "AttributeBegin\n" + light + "AttributeEnd\nIlluminate \"key\" 1\n" + wall + "WorldEnd\n",
                                settings);
    CHECK(mean(back) == Approx(0.7).epsilon(1e-3));
    CHECK_FALSE(back.anyMessageContains("light list"));

    // A RenderMan light (Light) is not on any list: it lights every shape wherever it is given.
    auto ris = test::renderRib(head + "AttributeBegin\nLight \"PxrDistantLight\" \"sun\" \"float intensity\" [50000] "
                                      "\"float angleExtent\" [0]\nAttributeEnd\n" + wall + "WorldEnd\n",
                               settings);
    CHECK(mean(ris) > 0.1);
    CHECK_FALSE(ris.anyMessageContains("light list"));
}

TEST_CASE("Illuminate links lights to shapes: a light turned off for a shape lights the other shapes alone",
          "[lights]") {
    // A rect light facing two halves of a wall; the left half turns it off. Every integrator that samples
    // lights and Bxdfs (MIS) must leave the left half black and light the right half as if nothing were off.
    auto render = [](std::string const& integrator, std::string const& leftAttributes) {
        std::string rib = "Format 16 16 1\nProjection \"perspective\" \"fov\" [20]\nIntegrator \"" + integrator +
                          "\" \"i\"\nWorldBegin\n  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n"
                          "  Translate 0 0 3\n  Light \"PxrRectLight\" \"panel\" \"float intensity\" [2]\n"
                          "  AttributeEnd\n"
                          "  Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n  AttributeBegin\n" +
                          leftAttributes +
                          "  Polygon \"P\" [-4 -4 5  0 -4 5  0 4 5  -4 4 5]\n  AttributeEnd\n"
                          "  Polygon \"P\" [0 -4 5  4 -4 5  4 4 5  0 4 5]\nWorldEnd\n";
        return test::renderRib(rib, test::withSpp(16));
    };
    auto left = [](int x, int) { return x < 8; };
    auto right = [](int x, int) { return x >= 8; };
    for (std::string integrator : {"PxrDirectLighting", "PxrPathTracer", "PxrVCM"}) {
        CAPTURE(integrator);
        auto linked = render(integrator, "  Illuminate \"panel\" 0\n");
        auto unlinked = render(integrator, "");
        CHECK(test::meanChannel(unlinked, 0, left) > 0.02);
        CHECK(test::meanChannel(linked, 0, left) == 0.0);
        CHECK(test::meanChannel(linked, 0, right) == Approx(test::meanChannel(unlinked, 0, right)).epsilon(1e-4));
    }
}

TEST_CASE("Attribute lighting subset and excludesubset link lights by handle or by grouping membership",
          "[lights]") {
    // Which of two lights (key, in the groups "keys" and "rims", and fill) light a sphere given after them.
    auto litBy = [](std::string const& sphereAttributes) {
        Diagnostics diagnostics(false);
        Scene scene = test::parseRib("WorldBegin\nAttributeBegin\nAttribute \"grouping\" \"string membership\" "
                                     "[\"keys rims\"]\nLight \"PxrDistantLight\" \"key\"\nAttributeEnd\n"
                                     "Light \"PxrDistantLight\" \"fill\"\n" + sphereAttributes +
                                         "Sphere 1 -1 1 360\n",
                                     diagnostics);
        CHECK(test::warningsContaining(diagnostics, "not used") == 0);
        REQUIRE(scene.lights.size() == 2u);
        REQUIRE(scene.shapes.size() == 1u);
        int const link = scene.shapes[0]->lightLink;
        std::string lit;
        for (size_t l = 0; l < scene.lights.size(); ++l)
            if (link < 0 || scene.lightLinks[static_cast<size_t>(link)][l]) lit += " " + scene.lights[l]->handle;
        return lit;
    };
    CHECK(litBy("") == " key fill");
    CHECK(litBy("Attribute \"lighting\" \"string excludesubset\" [\"fill\"]\n") == " key");
    CHECK(litBy("Attribute \"lighting\" \"string subset\" [\"rims\"]\n") == " key");
    CHECK(litBy("Attribute \"lighting\" \"string subset\" [\"fill,keys\"]\n") == " key fill");
    CHECK(litBy("Attribute \"lighting\" \"string subset\" [\"keys\"] \"string excludesubset\" [\"key\"]\n") == "");
    // What exporters write when nothing is linked.
    CHECK(litBy("Attribute \"lighting\" \"int mute\" [0] \"string subset\" [\"\"] \"string excludesubset\" [\"\"]\n") ==
          " key fill");

    // A muted light emits nothing: it is left out.
    Diagnostics diagnostics(false);
    Scene muted = test::parseRib("WorldBegin\nAttributeBegin\nAttribute \"lighting\" \"int mute\" [1]\n"
                                 "Light \"PxrDistantLight\" \"key\"\nAttributeEnd\n"
                                 "Light \"PxrDistantLight\" \"fill\"\n",
                                 diagnostics);
    REQUIRE(muted.lights.size() == 1u);
    CHECK(muted.lights[0]->handle == "fill");
}

TEST_CASE("a light shader this renderer does not have is placed by its name, then by its parameters", "[lights]") {
    auto kindOf = [](std::string const& lightSource, bool known = false) {
        Diagnostics diagnostics(false);
        Scene scene = test::parseRib("WorldBegin\n" + lightSource + "\n", diagnostics);
        CHECK(test::warningsContaining(diagnostics, "is a shader this renderer does not have; it is rendered as the") ==
              (known ? 0 : 1));
        return scene.lights.size() == 1u ? std::string(scene.lights[0]->kind()) : std::string("none");
    };
    std::string const fromTo = " 1 \"from\" [0 0 0] \"to\" [0 0 1]";
    std::string const distant = kindOf("LightSource \"distantlight\"" + fromTo, true);
    std::string const spot = kindOf("LightSource \"spotlight\"" + fromTo, true);
    std::string const point = kindOf("LightSource \"pointlight\" 1 \"from\" [0 0 0]", true);
    CHECK(distant != spot);
    CHECK(spot != point);
    CHECK(kindOf("LightSource \"RMsoftDistant\"" + fromTo) == distant);  // MayaMan's soft-shadowed distant light
    CHECK(kindOf("LightSource \"mySpot\"" + fromTo) == spot);
    CHECK(kindOf("LightSource \"sunlight\"" + fromTo) == distant);
    CHECK(kindOf("LightSource \"omniLight\"" + fromTo) == point);
    CHECK(kindOf("LightSource \"key\"" + fromTo + " \"coneangle\" [0.5]") == spot);
    CHECK(kindOf("LightSource \"key\"" + fromTo) == distant);  // a "to" and no cone: a direction
    CHECK(kindOf("LightSource \"key\" 1 \"from\" [0 0 0]") == point);
    // A shader of its own named for its shadows traces them (it names no map); another casts none,
    // as the standard pointlight does.
    auto shadowsOf = [](std::string const& shader) {
        Diagnostics diagnostics(false);
        Scene scene = test::parseRib("WorldBegin\nLightSource \"" + shader + "\" 1 \"from\" [0 0 0]\n", diagnostics);
        REQUIRE(scene.lights.size() == 1u);
        return scene.lights[0]->castsShadows;
    };
    CHECK(shadowsOf("pointlight_shadows"));
    CHECK(shadowsOf("shaders/shadowlight"));
    CHECK_FALSE(shadowsOf("mypointlight"));
    CHECK_FALSE(shadowsOf("pointlight"));
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

TEST_CASE("areaNormalize keeps a light's power whatever its size, without it power grows with area", "[lights]") {
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

TEST_CASE("PxrEnvDayLight: the sun and Preetham's sky light a floor as much as they shine on it", "[lights][daylight]") {
    // A white Lambertian floor (+y up, as the day light's zenith) under an open sky reflects
    // (E_sun cos(theta_sun) + E_sky) / pi; E_sky integrates the model's radiance over the
    // hemisphere. Sun and sky are sampled as one light: this checks their mixture's pdf too.
    Vec3 const sun = glm::normalize(Vec3(0.3f, 0.8f, 0.2f));
    float const turbidity = 3.0f;
    double skyIrradiance = 0.0;
    int const n = 400;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 4 * n; ++j) {
            double const theta = 0.5 * kPi * (i + 0.5) / n, phi = 2.0 * kPi * (j + 0.5) / (4 * n);
            Vec3 const dir(static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                           static_cast<float>(std::sin(theta) * std::sin(phi)));
            skyIrradiance += skyRadiance(dir, sun, turbidity).x * std::cos(theta) * std::sin(theta) *
                             (0.5 * kPi / n) * (2.0 * kPi / (4 * n));
        }
    double const expected = (sunIrradiance(sun, turbidity).x * sun.y + skyIrradiance) / kPi;
    double const red =
        litFloor("  Light \"PxrEnvDayLight\" \"day\" \"vector sunDirection\" [0.3 0.8 0.2] \"float haziness\" [3]\n", 64);
    CHECK(red == Approx(expected).epsilon(0.01));
    // RenderMan's scale: daylight near noon gives an irradiance near 1, the sun most of it.
    CHECK(expected * kPi > 0.7);
    CHECK(expected * kPi < 1.5);
    CHECK(sunIrradiance(sun, turbidity).x * sun.y > 2.0 * skyIrradiance);
}

TEST_CASE("PxrEnvDayLight: the sun's place by date, time and place, a bluer zenith, a redder low sun", "[lights][daylight]") {
    // 21 June at 47.6 degrees north, local noon on the zone's own meridian: the sun stands
    // 90 - 47.6 + 23.44 = 65.8 degrees high, due south (-z); at 8 in the morning it is east (+x).
    DaylightParams p;
    p.month = 6;
    p.day = 21;
    p.latitude = 47.6f;
    p.longitude = -120.0f;
    p.zone = -8.0f;
    p.hour = 12.0f;
    Vec3 noon = sunDirectionAt(p);
    CHECK(glm::degrees(std::asin(noon.y)) == Approx(65.8).margin(0.6));
    CHECK(noon.z < 0.0f);
    CHECK(std::fabs(noon.x) < 0.05f);
    p.hour = 8.0f;
    Vec3 morning = sunDirectionAt(p);
    CHECK(morning.x > 0.5f);
    CHECK(morning.y > 0.0f);
    p.hour = 23.0f;
    CHECK(sunDirectionAt(p).y < 0.0f);  // night: the sun is down
    p.month = 12;  // winter noon: 90 - 47.6 - 23.44 = 19 degrees
    p.hour = 12.0f;
    CHECK(glm::degrees(std::asin(sunDirectionAt(p).y)) == Approx(19.0).margin(0.6));

    // Rayleigh scattering: the zenith of a high sun's sky is bluer than its horizon is, and a sun
    // near the horizon, through more air, is redder (and weaker) than a high one.
    Vec3 const high = glm::normalize(Vec3(0.0f, 1.0f, -0.5f)), low = glm::normalize(Vec3(0.0f, 0.08f, -1.0f));
    Vec3 const zenith = skyRadiance(Vec3(0, 1, 0), high, 2.0f), horizon = skyRadiance(glm::normalize(Vec3(1, 0.05f, 0)), high, 2.0f);
    CHECK(zenith.z / zenith.x > horizon.z / horizon.x);
    Vec3 const highSun = sunIrradiance(high, 2.0f), lowSun = sunIrradiance(low, 2.0f);
    CHECK(lowSun.x / lowSun.z > 1.5f * (highSun.x / highSun.z));
    CHECK(lowSun.y < highSun.y);
    CHECK(sunIrradiance(Vec3(0.0f, -0.1f, 1.0f), 2.0f) == Vec3(0.0f));
    CHECK(skyRadiance(Vec3(0.0f, -0.5f, 0.866f), high, 2.0f) == Vec3(0.0f));  // no ground: black below the horizon
}

TEST_CASE("a rect or disk light's shaping: coneAngle cuts it off, coneSoftness fades its edge, emissionFocus "
          "narrows it and emissionFocusTint gives back what focus takes",
          "[lights][shaping]") {
    // A row of pixels across a white plane 1 unit in front of a tiny light that faces it: a point
    // at x sees the light at theta = atan(|x|), so shaped / unshaped at a pixel is a weighted mean
    // of the shaping factor over the pixel's span of theta (the same samples in both images).
    int const width = 256;
    auto row = [&](std::string const& light, std::string const& shaping) {
        std::string rib = "Format " + std::to_string(width) + " 1 1\nProjection \"orthographic\"\n"
                          "ScreenWindow -4 4 -0.015625 0.015625\nIntegrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n"
                          "  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n  Translate 0 0 4\n"
                          "  Scale 0.002 0.002 0.002\n  Light \"" + light + "\" \"l\" \"float intensity\" [1e6] " +
                          shaping + "\n  AttributeEnd\n  Bxdf \"PxrDiffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                          "  Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
        return test::renderRib(rib, test::withSpp(4));
    };
    auto thetaAt = [](double x) { return std::atan(std::fabs(x)); };
    double const degree = 3.14159265358979 / 180.0;
    // The factors as RenderMan's shaping (UsdLux's cone) defines them, written out here.
    auto cone = [&](double t, double angle, double softness) {
        double cut = angle * degree, start = cut * (1.0 - softness);
        if (t >= cut) return 0.0;
        if (t <= start) return 1.0;
        double x = (t - start) / (cut - start);
        return 1.0 - x * x * (3.0 - 2.0 * x);
    };
    for (char const* light : {"PxrRectLight", "PxrDiskLight"}) {
        INFO(light);
        auto plain = row(light, "");
        auto compare = [&](std::string const& shaping, auto factor, int channel) {
            INFO(shaping);
            auto shaped = row(light, shaping);
            int narrow = 0;
            for (int i = 0; i < width; ++i) {
                double x0 = -4.0 + 8.0 * i / width, x1 = -4.0 + 8.0 * (i + 1) / width;
                // Each factor is monotone in theta, and theta in |x| on either side of 0.
                double lo = 1e9, hi = -1e9;
                for (double x : {x0, 0.5 * (x0 + x1), x1}) {
                    lo = std::min(lo, factor(thetaAt(x)));
                    hi = std::max(hi, factor(thetaAt(x)));
                }
                if (x0 < 0.0 && x1 > 0.0) hi = std::max(hi, factor(0.0));
                INFO("pixel " << i << ", theta " << thetaAt(0.5 * (x0 + x1)) / degree << " degrees");
                REQUIRE(plain.channel(i, 0, channel) > 0.0f);
                double ratio = shaped.channel(i, 0, channel) / plain.channel(i, 0, channel);
                CHECK(ratio >= lo - 2e-3);
                CHECK(ratio <= hi + 2e-3);
                if (hi - lo < 0.02) ++narrow;
            }
            CHECK(narrow > width * 3 / 4);  // most pixels pin the factor down to 0.02
        };
        compare("\"float coneAngle\" [40]", [&](double t) { return cone(t, 40, 0); }, 0);
        compare("\"float coneAngle\" [50] \"float coneSoftness\" [0.6]", [&](double t) { return cone(t, 50, 0.6); }, 0);
        compare("\"float emissionFocus\" [3]", [](double t) { return std::pow(std::cos(t), 3.0); }, 0);
        // A tint fills in what focus takes away, channel by channel: red 0.5, blue 0.
        compare("\"float emissionFocus\" [3] \"color emissionFocusTint\" [0.5 0 0]",
                [](double t) { return 0.5 + 0.5 * std::pow(std::cos(t), 3.0); }, 0);
        compare("\"float emissionFocus\" [3] \"color emissionFocusTint\" [0.5 0 0]",
                [](double t) { return std::pow(std::cos(t), 3.0); }, 2);
        // Written without a type, as RenderMan types them from the light.
        compare("\"coneAngle\" [40]", [&](double t) { return cone(t, 40, 0); }, 0);
        // Out of range: an angle over 90 degrees is the whole hemisphere, softness is clamped to 1.
        compare("\"float coneAngle\" [120]", [](double) { return 1.0; }, 0);
        compare("\"float coneAngle\" [60] \"float coneSoftness\" [3]", [&](double t) { return cone(t, 60, 1); }, 0);
    }
}

TEST_CASE("a file lit by classic light shaders and naming no integrator renders with its lights as RenderMan "
          "before RIS did and a RIS file without one keeps PxrDefault's headlight",
          "[lights][classic]") {
    std::string const head = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\nWorldBegin\n";
    std::string const matte = "Surface \"matte\"\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
    auto mean = [](test::RenderOutcome const& r) { return test::meanChannel(r, 0, [](int, int) { return true; }); };
    RenderSettings settings;
    settings.spp = 4;
    auto toward = test::renderRib(head + "LightSource \"distantlight\" 1 \"intensity\" [0.7]\n" + matte, settings);
    CHECK(toward.stats.integrator == "PxrDirectLighting");
    CHECK(mean(toward) == Approx(0.7).epsilon(1e-3));
    CHECK(toward.anyMessageContains("test.rib:5:1: the scene names no Integrator and is lit by classic light shaders, so "
                                    "it renders with PxrDirectLighting and its lights"));
    // Its light aimed away: black, as then (the headlight would have lit it).
    auto away = test::renderRib(head + "LightSource \"distantlight\" 1 \"intensity\" [0.7] \"to\" [0 0 -1]\n" + matte, settings);
    CHECK(mean(away) == 0.0);
    // Named, the integrator is the file's.
    auto named = test::renderRib("Integrator \"PxrDefault\" \"d\"\n" + head +
                                     "LightSource \"distantlight\" 1 \"intensity\" [0.7] \"to\" [0 0 -1]\n" + matte,
                                 settings);
    CHECK(named.stats.integrator == "PxrDefault");
    CHECK(mean(named) > 0.5);
    // Only an ambientlight (no light to sample): the headlight, as before.
    auto ambientOnly = test::renderRib(head + "LightSource \"ambientlight\" 1 \"intensity\" [0.2]\n" + matte, settings);
    CHECK(ambientOnly.stats.integrator == "PxrDefault");
    // RIS lights: RenderMan's RIS default.
    auto ris = test::renderRib(head + "Light \"PxrDistantLight\" \"l\"\n" + matte, settings);
    CHECK(ris.stats.integrator == "PxrDefault");
    // A file of frames is told once, by its first: its frames are lit alike.
    Diagnostics diagnostics(false);
    Scene scene;
    SceneBuilder builder(scene, diagnostics);
    std::vector<std::string> integrators;
    builder.setFrameSink([&](Scene& frame) { integrators.push_back(frame.integrator.name); });
    std::string const frame = head + "LightSource \"distantlight\" 1\n" + matte;
    builder.readText("FrameBegin 1\n" + frame + "FrameEnd\nFrameBegin 2\n" + frame + "FrameEnd\n", "frames.rib");
    CHECK(integrators == std::vector<std::string>{"PxrDirectLighting", "PxrDirectLighting"});
    int notes = 0;
    for (auto const& entry : diagnostics.entries())
        if (entry.text.find("names no Integrator and is lit by classic light shaders") != std::string::npos) ++notes;
    CHECK(notes == 1);
}

TEST_CASE("in a file lit by classic light shaders a surface given no shader is PRMan's defaultsurface",
          "[lights][classic]") {
    // defaultsurface: Cs (Ka + Kd (I.N)^2) with Ka 0.2 and Kd 0.8, lit by no light. A wall facing the
    // camera shows its Color whether or not the file's light reaches it; the same wall seen at 60
    // degrees shows 0.2 + 0.8 / 4 of it.
    std::string const head = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\nWorldBegin\n";
    std::string const wall = "Color [0.3 0.6 0.9]\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\n";
    std::string const light = "LightSource \"distantlight\" 1 \"intensity\" [0.7]\n";
    auto mean = [](test::RenderOutcome const& r, int c) {
        return test::meanChannel(r, c, [](int, int) { return true; });
    };
    RenderSettings settings;
    settings.spp = 4;
    // Before its light, off the wall's light list: with RIS's PxrDiffuse it was black.
    auto before = test::renderRib(head + wall + light + "WorldEnd\n", settings);
    CHECK(before.stats.integrator == "PxrDirectLighting");
    CHECK(mean(before, 0) == Approx(0.3).epsilon(1e-3));
    CHECK(mean(before, 1) == Approx(0.6).epsilon(1e-3));
    CHECK(mean(before, 2) == Approx(0.9).epsilon(1e-3));
    // After it, lit by it: still only its Color, the light adds nothing.
    auto after = test::renderRib(head + light + wall + "WorldEnd\n", settings);
    CHECK(mean(after, 1) == Approx(0.6).epsilon(1e-3));
    // Turned 60 degrees about y: (I.N)^2 = 1/4.
    auto turned = test::renderRib(head + light + "Translate 0 0 5\nRotate 60 0 1 0\nTranslate 0 0 -5\n" + wall +
                                      "WorldEnd\n",
                                  settings);
    CHECK(mean(turned, 1) == Approx(0.6 * (0.2 + 0.8 * 0.25)).epsilon(1e-3));
    // A shape's own Cs takes the Color's place.
    auto own = test::renderRib(head + light +
                                   "Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5] \"Cs\" [1 0 0  1 0 0  1 0 0  1 0 0]\n"
                                   "WorldEnd\n",
                               settings);
    CHECK(mean(own, 0) == Approx(1.0).epsilon(1e-3));
    CHECK(mean(own, 1) == 0.0);
    // A file without classic lights keeps RenderMan's RIS default: PxrDiffuse under PxrDefault's headlight.
    auto ris = test::renderRib(head + wall + "WorldEnd\n", settings);
    CHECK(ris.stats.integrator == "PxrDefault");
    CHECK(mean(ris, 1) == Approx(0.6).epsilon(0.02));
    CHECK(mean(ris, 0) / mean(ris, 1) == Approx(0.5).epsilon(1e-3));
}

TEST_CASE("a classic arealight gives what a point light of its intensity would, whatever its size", "[lights][classic]") {
    // BMRT's arealight sends intensity / d^2 from each point it samples: a small square 5 units from a
    // matte surface gives it intensity / 25 at any size.
    auto litBy = [](double side) {
        std::string const half = std::to_string(side / 2);
        std::string rib = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                          "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\nAttributeBegin\n"
                          "Attribute \"visibility\" \"int camera\" [0]\n"
                          "AreaLightSource \"arealight\" 1 \"intensity\" [50]\n"
                          "Polygon \"P\" [-" + half + " -" + half + " 0  " + half + " -" + half + " 0  " + half + " " +
                          half + " 0  -" + half + " " + half + " 0]\nAttributeEnd\n"
                          "Surface \"matte\"\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(64));
        return test::meanChannel(r, 0, [](int, int) { return true; });
    };
    CHECK(litBy(0.1) == Approx(2.0).epsilon(0.01));
    CHECK(litBy(0.4) == Approx(2.0).epsilon(0.01));
    // Given as a LightSource, with no shape, it is its unit square (here scaled to 0.1), and gives the same.
    std::string const unshaped = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                                 "WorldBegin\nTransformBegin\nScale 0.1 0.1 0.1\n"
                                 "LightSource \"arealight\" 1 \"intensity\" [50]\nTransformEnd\n"
                                 "Surface \"matte\"\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
    auto r = test::renderRib(unshaped, test::withSpp(64));
    CHECK(test::meanChannel(r, 0, [](int, int) { return true; }) == Approx(2.0).epsilon(0.01));
}

TEST_CASE("classic lights cast shadows only when asked: a shadow map, a traced shadow or BMRT's shadows attribute",
          "[lights][classic]") {
    // A square between a distant light and a matte surface.
    auto behindBlocker = [](std::string const& before, std::string const& light) {
        std::string rib = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\nWorldBegin\n" +
                          before + "LightSource " + light + "\nSurface \"matte\"\n"
                          "AttributeBegin\nAttribute \"visibility\" \"int camera\" [0]\n"
                          "Polygon \"P\" [-1 -1 3  1 -1 3  1 1 3  -1 1 3]\nAttributeEnd\n"
                          "Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(4));
        return test::meanChannel(r, 0, [](int, int) { return true; });
    };
    std::string const distant = "\"distantlight\" 1 \"intensity\" [0.7]";
    CHECK(behindBlocker("", distant) == Approx(0.7).epsilon(1e-3));
    CHECK(behindBlocker("", "\"shadowdistant\" 1 \"intensity\" [0.7] \"string shadowname\" [\"\"]") ==
          Approx(0.7).epsilon(1e-3));
    CHECK(behindBlocker("", "\"shadowdistant\" 1 \"intensity\" [0.7] \"string shadowname\" [\"raytrace\"]") == 0.0);
    CHECK(behindBlocker("", "\"shadowspot\" 1 \"intensity\" [8] \"from\" [0 0 1] \"to\" [0 0 5] \"shadowname\" [\"key.shd\"]") ==
          0.0);
    CHECK(behindBlocker("", "\"uberlight\" 1 \"intensity\" [1] \"raytraceshadow\" [1]") == 0.0);
    CHECK(behindBlocker("Attribute \"light\" \"shadows\" \"on\"\n", distant) == 0.0);
    CHECK(behindBlocker("Attribute \"light\" \"string shadows\" [\"off\"]\n", distant) == Approx(0.7).epsilon(1e-3));
}

TEST_CASE("RIS lights' shadow controls: enableShadows 0 lights what lies behind a blocker, controls at values that "
          "change nothing are read quietly, and one that would change the image is said to be unused",
          "[lights]") {
    // A square between a sun (no angular extent) and a white diffuse floor that fills the view.
    auto behindBlocker = [](std::string const& light, Diagnostics* diagnostics = nullptr, bool blocked = true) {
        std::string rib = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
                          "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n"
                          "Light \"PxrDistantLight\" \"sun\" \"float angleExtent\" [0] " + light + "\n"
                          "Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
                          "AttributeBegin\nAttribute \"visibility\" \"int camera\" [0]\n" +
                          (blocked ? "Polygon \"P\" [-1 -1 3  1 -1 3  1 1 3  -1 1 3]\n" : "") + "AttributeEnd\n"
                          "Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
        if (diagnostics) {
            test::parseRib(rib, *diagnostics);
            return 0.0;
        }
        return test::meanChannel(test::renderRib(rib, test::withSpp(4)), 0, [](int, int) { return true; });
    };
    CHECK(behindBlocker("") == 0.0);
    CHECK(behindBlocker("\"int enableShadows\" [1]") == 0.0);
    double const unshadowed = behindBlocker("\"int enableShadows\" [0]");
    CHECK(unshadowed > 0.0);
    CHECK(unshadowed == Approx(behindBlocker("", nullptr, false)).epsilon(1e-6));  // as if the blocker were not there
    CHECK(behindBlocker("\"enableShadows\" [0]") == unshadowed);  // untyped, as older exporters write it

    // RenderMan 20's area light takes its shape from the geometry that follows, and its controls with it.
    for (char const* enable : {"0", "1"}) {
        Diagnostics diagnostics(false);
        Scene area = test::parseRib(std::string("WorldBegin\nAttributeBegin\nAreaLightSource \"PxrStdAreaLight\" \"a\" "
                                                "\"float enableShadows\" [") + enable + "]\nSphere 1 -1 1 360\nAttributeEnd\n"
                                                "WorldEnd\n", diagnostics);
        REQUIRE(area.lights.size() == 1u);
        CHECK(area.lights[0]->castsShadows == (enable[0] == '1'));
    }

    // What RenderMan for Maya and Houdini write for every light: no warning, no change.
    std::string const defaults = "\"color shadowColor\" [0 0 0] \"float shadowDistance\" [-1] \"float shadowFalloff\" [-1] "
                                 "\"float shadowFalloffGamma\" [1] \"string shadowSubset\" [\"\"] \"string shadowExcludeSubset\" "
                                 "[\"\"] \"int thinShadow\" [1] \"int traceLightPaths\" [0] \"int fixedSampleCount\" [0] "
                                 "\"float diffuse\" [1] \"float specular\" [1] \"float importanceMultiplier\" [1] "
                                 "\"string lightGroup\" [\"keys\"] \"int enableTemperature\" [0] "
                                 "\"float temperature\" [3000] \"float intensityNearDist\" [0] \"string iesProfile\" [\"\"] "
                                 "\"float iesProfileScale\" [0] \"string lightColorMap\" [\"\"]";
    Diagnostics quiet(false);
    behindBlocker(defaults, &quiet);
    CHECK(test::warningTexts(quiet).empty());
    CHECK(behindBlocker(defaults) == 0.0);

    // A grey shadow would change the image: not modelled, so said (a light kept out of the diffuse
    // lobe is modelled: see the multipliers' test).
    Diagnostics told(false);
    behindBlocker("\"color shadowColor\" [0.5 0.5 0.5] \"float diffuse\" [0]", &told);
    std::vector<std::string> const warnings = test::warningTexts(told);
    REQUIRE(warnings.size() == 1u);
    CHECK_THAT(warnings[0], Catch::Matchers::EndsWith("parameter \"shadowColor\" is not used; ignored"));
}

TEST_CASE("a light's diffuse and specular multipliers scale what diffuse and specular lobes take straight from it "
          "in every integrator",
          "[lights]") {
    // A rect light the camera does not see, over a square of `bxdf`; the mean red of the image.
    auto lit = [](std::string const& integrator, std::string const& bxdf, std::string const& multipliers) {
        std::string rib = "Format 16 16 1\nProjection \"perspective\" \"fov\" [20]\nIntegrator \"" + integrator +
                          "\" \"i\"\nWorldBegin\nAttributeBegin\nAttribute \"visibility\" \"int camera\" [0]\n"
                          "Translate 0 0 3\nLight \"PxrRectLight\" \"key\" \"float intensity\" [4] " + multipliers +
                          "\nAttributeEnd\n" + bxdf + "\nPolygon \"P\" [-4 -4 5  4 -4 5  4 4 5  -4 4 5]\nWorldEnd\n";
        return test::meanChannel(test::renderRib(rib, test::withSpp(16)), 0, [](int, int) { return true; });
    };
    auto multipliers = [](char const* diffuse, char const* specular) {
        return std::string("\"float diffuse\" [") + diffuse + "] \"float specular\" [" + specular + "]";
    };
    std::string const plastic = "Bxdf \"plastic\" \"p\" \"color diffuseColor\" [0.5 0.5 0.5] "
                                "\"color specularColor\" [0.3 0.3 0.3] \"float gloss\" [0.5]";
    std::string const matte = "Bxdf \"diffuse\" \"d\" \"color diffuseColor\" [0.8 0.8 0.8]";
    for (std::string integrator : {"PxrDirectLighting", "PxrPathTracer", "PxrVCM"}) {
        CAPTURE(integrator);
        double const full = lit(integrator, plastic, multipliers("1", "1"));
        double const diffuseOnly = lit(integrator, plastic, multipliers("1", "0"));
        double const specularOnly = lit(integrator, plastic, multipliers("0", "1"));
        REQUIRE(full > 0.01);
        CHECK(full == lit(integrator, plastic, ""));  // 1 and 1 are RenderMan's defaults
        CHECK(lit(integrator, plastic, multipliers("0", "0")) == 0.0);
        CHECK(lit(integrator, plastic, multipliers("0.5", "0.5")) == Approx(full / 2).epsilon(1e-5));
        // Each lobe's share is its own: the two shares make up the whole.
        CHECK(diffuseOnly > 0.05 * full);
        CHECK(specularOnly > 0.05 * full);
        CHECK(diffuseOnly + specularOnly == Approx(full).epsilon(1e-4));
        CHECK(lit(integrator, plastic, multipliers("2", "1")) == Approx(full + diffuseOnly).epsilon(1e-4));
        // A diffuse surface takes only the diffuse multiplier.
        double const matteFull = lit(integrator, matte, "");
        CHECK(lit(integrator, matte, multipliers("1", "0")) == matteFull);
        CHECK(lit(integrator, matte, multipliers("0", "3")) == 0.0);
    }

    // A classic light shader's "__nondiffuse" and "__nonspecular" 1 leave it out of diffuse() and specular().
    auto classic = [](std::string const& surface, std::string const& switches) {
        std::string rib = "Format 16 16 1\nProjection \"perspective\" \"fov\" [20]\nWorldBegin\n"
                          "LightSource \"pointlight\" 1 \"intensity\" [20] \"from\" [0 1 2] " + switches + "\n" +
                          surface + "\nPolygon \"P\" [-4 -4 5  4 -4 5  4 4 5  -4 4 5]\nWorldEnd\n";
        return test::meanChannel(test::renderRib(rib, test::withSpp(4)), 0, [](int, int) { return true; });
    };
    double const plasticLit = classic("Surface \"plastic\"", "");
    REQUIRE(plasticLit > 0.01);
    CHECK(classic("Surface \"matte\"", "\"float __nondiffuse\" [1]") == 0.0);
    CHECK(classic("Surface \"matte\"", "\"__nonspecular\" [1]") == classic("Surface \"matte\"", ""));
    double const diffusePart = classic("Surface \"plastic\"", "\"float __nonspecular\" [1]");
    double const specularPart = classic("Surface \"plastic\"", "\"float __nondiffuse\" [1]");
    CHECK(diffusePart > 0.0);
    CHECK(specularPart > 0.0);
    CHECK(diffusePart + specularPart == Approx(plasticLit).epsilon(1e-4));
    CHECK(classic("Surface \"plastic\"", "\"float __nondiffuse\" [0] \"float __nonspecular\" [0]") == plasticLit);

    // Read quietly, and a negative or non-finite multiplier is a located error.
    Diagnostics quiet(false);
    test::parseRib("WorldBegin\nLight \"PxrRectLight\" \"key\" \"float diffuse\" [0.5] \"float specular\" [2]\nWorldEnd\n",
                   quiet);
    CHECK(test::warningTexts(quiet).empty());
    for (char const* bad : {"\"float diffuse\" [-1]", "\"specular\" [-0.5]"}) {
        CAPTURE(bad);
        Diagnostics diagnostics(false);
        CHECK_THROWS_WITH(test::parseRib(std::string("WorldBegin\nLight \"PxrDiskLight\" \"key\" ") + bad + "\nWorldEnd\n",
                                         diagnostics),
                          Catch::Matchers::Contains("test.rib:2:") &&
                              Catch::Matchers::Contains("diffuse and specular multipliers must be finite and not negative"));
    }
}

TEST_CASE("an area light shader without geometry (plausibleArealight) is a light of its shape, radiance intensity x "
          "lightcolor, unseen by the camera",
          "[lights][classic]") {
    // A matte surface at z = 5 under a small light at the origin: a source of area A and radiance L
    // gives the surface about L A / (pi d^2) (1e-3 for a 0.1 square at 5 units). The orthographic
    // camera looks straight through the light, so the pixels would show L were the light visible.
    auto litBy = [](std::string const& placement, std::string const& parameters, std::string const& blocker = "") {
        std::string rib = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\nWorldBegin\n"
                          "TransformBegin\n" + placement + "LightSource \"plausibleArealight\" \"key\" " + parameters +
                          "\nTransformEnd\nSurface \"matte\"\n" + blocker +
                          "Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(64));
        CHECK(r.anyMessageContains("plausibleArealight\" is a shader this renderer does not have; it is rendered as a"));
        return test::meanChannel(r, 0, [](int, int) { return true; });
    };
    double const pi = 3.14159265358979;
    double const square = 1000.0 * 0.01 / (pi * 25.0);
    std::string const small = "Scale 0.1 0.1 0.1\n";
    // One-sided ("sides" 1, its default): it sends light along its +z only.
    CHECK(litBy(small, "\"intensity\" [1000]") == Approx(square).epsilon(2e-3));
    CHECK(litBy("Rotate 180 1 0 0\n" + small, "\"intensity\" [1000]") == 0.0);
    // Two-sided: turned away, it lights the surface all the same.
    CHECK(litBy("Rotate 180 1 0 0\n" + small, "\"intensity\" [1000] \"float sides\" [2]") ==
          Approx(square).epsilon(2e-3));
    // lightcolor tints it; areanormalize divides by the area (0.01 here).
    CHECK(litBy(small, "\"intensity\" [500] \"lightcolor\" [2 2 2]") == Approx(square).epsilon(2e-3));
    CHECK(litBy(small, "\"intensity\" [10] \"float areanormalize\" [1]") == Approx(square).epsilon(2e-3));
    // A disk of diameter 0.1 (area pi 0.05^2) and a sphere of that diameter (seen as a disk that size).
    double const disk = 1000.0 * 0.0025 / 25.0;
    CHECK(litBy(small, "\"intensity\" [1000] \"string shape\" [\"disk\"]") == Approx(disk).epsilon(2e-3));
    CHECK(litBy(small, "\"intensity\" [1000] \"string shape\" [\"disk\"] \"float sides\" [2]") ==
          Approx(disk).epsilon(5e-3));  // the two-sided disk is a polygon of 64 sides
    CHECK(litBy(small, "\"intensity\" [1000] \"string shape\" [\"sphere\"]") == Approx(disk).epsilon(2e-3));
    // It traces its shadows: a square between it and the surface blocks it.
    CHECK(litBy(small, "\"intensity\" [1000]",
                "AttributeBegin\nAttribute \"visibility\" \"int camera\" [0]\n"
                "Polygon \"P\" [-1 -1 3  1 -1 3  1 1 3  -1 1 3]\nAttributeEnd\n") == 0.0);
    // Given a shape as an AreaLightSource, its intensity is a radiance all the same (where BMRT's
    // arealight gives what a point light would).
    auto shaped = [](std::string const& parameters) {
        std::string rib = "Format 8 8 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\nWorldBegin\n"
                          "AttributeBegin\nAttribute \"visibility\" \"int camera\" [0]\n"
                          "AreaLightSource \"plausibleArealight\" \"key\" " + parameters +
                          "\nPolygon \"P\" [-0.05 -0.05 0  0.05 -0.05 0  0.05 0.05 0  -0.05 0.05 0]\nAttributeEnd\n"
                          "Surface \"matte\"\nPolygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\nWorldEnd\n";
        return test::meanChannel(test::renderRib(rib, test::withSpp(64)), 0, [](int, int) { return true; });
    };
    CHECK(shaped("\"intensity\" [1000]") == Approx(square).epsilon(2e-3));
    CHECK(shaped("\"intensity\" [10] \"float areanormalize\" [1]") == Approx(square).epsilon(2e-3));
}
