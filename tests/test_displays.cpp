// Displays: what a Display's mode asks for, and the images of the surface the camera saw (z, P, N, s, t).
#include <catch2/catch.hpp>

#include <limits>

#include "render/Renderer.h"
#include "scene/DisplayChannels.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

std::vector<std::string> channelNames(std::string const& mode) {
    std::vector<std::string> names;
    for (DisplayChannel const& channel : displayLayout(mode).channels) names.push_back(channel.name);
    return names;
}

using Names = std::vector<std::string>;

}  // namespace

TEST_CASE("Display modes name the channels of an image", "[rib]") {
    CHECK(channelNames("rgba") == Names{"R", "G", "B", "A"});
    CHECK(channelNames("rgbaz") == Names{"R", "G", "B", "A", "Z"});
    CHECK(channelNames("az") == Names{"A", "Z"});
    CHECK(channelNames("Ci, a,z") == Names{"R", "G", "B", "A", "Z"});
    CHECK(channelNames("normal N") == Names{"N.x", "N.y", "N.z"});
    CHECK(channelNames("P,s,t") == Names{"P.x", "P.y", "P.z", "s", "t"});
    CHECK(displayLayout("rgb").shadedOnly());
    CHECK(displayLayout("z").needsSurface());
    CHECK(!displayLayout("Ci,a").needsSurface());
    // Names this renderer cannot make: the layout is empty and says which.
    CHECK(displayLayout("rgb,myval").unknown == "myval");
    CHECK(displayLayout("rgb,myval").channels.empty());
    CHECK(displayLayout("zrgb").unknown == "zrgb");
    CHECK(displayLayout(" ").unknown == "(nothing)");
    // What the camera must record at each sample for a set of displays, each quantity once.
    SurfaceRecord const record({displayLayout("rgba"), displayLayout("N,z"), displayLayout("s,N")});
    CHECK(record.needsDepth());
    CHECK(record.width() == 4);
    CHECK(record.offset(Quantity::N) == 0);
    CHECK(record.offset(Quantity::S) == 3);
    CHECK(record.offset(Quantity::P) == -1);
    CHECK(!SurfaceRecord({displayLayout("rgba")}).any());
}

TEST_CASE("Displays of the surface: depth, position and normals in camera space", "[render]") {
    // A camera scaled 2x: a wall at world z = 1.5 lies at camera z = 3. It fills the left half of the
    // view; the right half sees nothing. Rays away from the centre travel further than 3 to reach the
    // wall, so depth must be camera-space z, not the distance along the ray.
    std::string const rib =
        "Format 8 4 1\nProjection \"perspective\" \"fov\" [40]\nDisplay \"beauty.exr\" \"file\" \"rgba\"\n"
        "Display \"+surface.exr\" \"file\" \"z,P,N,s\"\nIntegrator \"PxrDirectLighting\" \"d\"\nScale 2 2 2\n"
        "WorldBegin\nBxdf \"PxrConstant\" \"wall\" \"color emitColor\" [1 0 0]\n"
        "Patch \"bilinear\" \"P\" [-10 -10 1.5  0 -10 1.5  -10 10 1.5  0 10 1.5]\nWorldEnd\n";
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(rib, diagnostics);
    REQUIRE(scene.moreDisplays.size() == 1);
    RenderSettings settings = test::withSpp(4);
    settings.pluginPath = TEST_PLUGIN_DIR;
    Renderer renderer(scene, settings, diagnostics);
    Film film = renderer.render();
    DisplayLayout const layout = displayLayout(scene.moreDisplays[0].mode);
    std::vector<float> const values = film.channels(layout);
    REQUIRE(values.size() == 8u * 4u * 8u);
    auto at = [&](int x, int y, int channel) {
        return values[8 * static_cast<size_t>(y * 8 + x) + static_cast<size_t>(channel)];
    };
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            INFO("pixel " << x << ", " << y);
            CHECK(at(x, y, 0) == Approx(3.0f).epsilon(1e-5));  // depth
            CHECK(at(x, y, 3) == Approx(3.0f).epsilon(1e-5));  // P.z
            CHECK(at(x, y, 1) < 0.0f);                         // P.x: left of the centre
            // The wall faces along z; its normal is unit length in camera space despite the scale.
            CHECK(std::abs(at(x, y, 6)) == Approx(1.0f).epsilon(1e-5));
            CHECK(at(x, y, 4) == Approx(0.0f).margin(1e-6));
            CHECK(at(x, y, 7) > 0.0f);  // s runs along the patch's first edge
        }
        for (int x = 4; x < 8; ++x) {
            INFO("pixel " << x << ", " << y);
            CHECK(at(x, y, 0) == std::numeric_limits<float>::max());  // nothing seen
            CHECK(at(x, y, 3) == 0.0f);
            CHECK(at(x, y, 6) == 0.0f);
        }
    }
    // The image itself is what it is without the further display.
    Scene plain = test::parseRib(rib.substr(0, rib.find("Display \"+")) + rib.substr(rib.find("Integrator")), diagnostics);
    Renderer plainRenderer(plain, settings, diagnostics);
    CHECK(plainRenderer.render().rgba() == film.rgba());
}
