// rixlobe: draw a plugin's reflection lobe, the figures the course text makes
// with a BRDF explorer.
//
//   rixlobe PLUGIN [--params "..."] [--theta 45] [--phi 0] [--polar polar.png] [--sphere sphere.png]
//
// The polar plot is a slice through the plane of incidence (the plane of N
// and V): the distance from the centre in direction L is W = f(V, L) cos(theta_L)
// (luminance), with the normal pointing up, V drawn in blue and the mirror
// direction in grey. The sphere plot is the same quantity over the whole
// hemisphere, as a surface rendered by rixrender's own renderer.
#include <OpenImageIO/imagebufalgo.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <iostream>
#include <sstream>

#include "film/OiioImageFiles.h"
#include "parse/RibText.h"
#include "CommandLine.h"
#include "ToolSupport.h"
#include "render/Film.h"
#include "render/Renderer.h"
#include "scene/SceneBuilder.h"

using namespace bxdflab;

namespace {

/// W's luminance for each direction in L.
std::vector<float> lobe(BxdfProbe& probe, ProbePoint const& point, std::vector<Vec3> const& L) {
    std::vector<float> values;
    for (ProbeResult const& r : probe.evaluate(std::vector<ProbePoint>(L.size(), point), L))
        values.push_back(std::isfinite(r.W.Luminance()) ? std::max(0.0f, r.W.Luminance()) : 0.0f);
    return values;
}

void drawPolar(BxdfProbe& probe, float theta, float phi, std::string const& path) {
    const int width = 640, height = 360, cx = width / 2, cy = height - 20;
    ProbePoint point = tools::viewFrom(theta, phi);
    // Angles in the plane of incidence, from -90 (the viewer's side) to +90 degrees.
    std::vector<Vec3> L;
    std::vector<float> angles;
    for (int k = 0; k <= 720; ++k) {
        float a = -90.0f + 0.25f * static_cast<float>(k);
        angles.push_back(a);
        L.push_back(a < 0 ? tools::direction(-a, phi) : tools::direction(a, phi + 180.0f));
    }
    std::vector<float> r = lobe(probe, point, L);
    float top = *std::max_element(r.begin(), r.end());
    float scale = top > 0 ? 0.9f * static_cast<float>(height - 64) / top : 1.0f;

    OIIO::ImageBuf canvas(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::fill(canvas, {1.0f, 1.0f, 1.0f});
    auto at = [&](float angleDegrees, float radius) {
        float a = glm::radians(angleDegrees);
        return std::pair<int, int>(cx + static_cast<int>(radius * std::sin(a)), cy - static_cast<int>(radius * std::cos(a)));
    };
    float reach = static_cast<float>(height - 64);
    OIIO::ImageBufAlgo::render_line(canvas, 10, cy, width - 10, cy, {0.6f, 0.6f, 0.6f});  // the surface
    OIIO::ImageBufAlgo::render_line(canvas, cx, cy, cx, cy - static_cast<int>(reach), {0.6f, 0.6f, 0.6f});  // N
    auto [vx, vy] = at(-theta, reach);
    OIIO::ImageBufAlgo::render_line(canvas, cx, cy, vx, vy, {0.2f, 0.4f, 1.0f});  // V
    auto [mx, my] = at(theta, reach);
    OIIO::ImageBufAlgo::render_line(canvas, cx, cy, mx, my, {0.8f, 0.8f, 0.8f});  // mirror direction
    for (size_t k = 1; k < r.size(); ++k) {
        auto [x0, y0] = at(angles[k - 1], r[k - 1] * scale);
        auto [x1, y1] = at(angles[k], r[k] * scale);
        OIIO::ImageBufAlgo::render_line(canvas, x0, y0, x1, y1, {0.9f, 0.35f, 0.05f});
    }
    tools::label(canvas, cx + 6, cy - static_cast<int>(reach) + 14, "N");
    tools::label(canvas, vx - 10, vy - 6, "V", {0.2f, 0.4f, 1.0f});
    tools::label(canvas, mx - 30, my - 6, "mirror", {0.55f, 0.55f, 0.55f});
    // (OpenImageIO draws ASCII only: the Greek letters are spelled out.)
    tools::label(canvas, 12, cy - 6, "-90 deg");
    tools::label(canvas, width - 72, cy - 6, "+90 deg");
    tools::label(canvas, 12, 22, "W(V, L) for L in the plane of incidence, V at theta " + tools::number(theta) +
                                     " deg; radius W / " + tools::number(top),
                 {0.9f, 0.35f, 0.05f});
    tools::writeDisplayImage(canvas, path);
    std::cout << "polar slice: largest W = " << top << " -> " << path << '\n';
}

void drawSphere(BxdfProbe& probe, float theta, float phi, std::string const& path) {
    // The lobe as a surface: the point at distance W(L) / max W along each direction L.
    const int thetaSteps = 64, phiSteps = 128;
    std::vector<Vec3> L;
    for (int i = 0; i <= thetaSteps; ++i)
        for (int j = 0; j <= phiSteps; ++j)
            L.push_back(tools::direction(90.0f * static_cast<float>(i) / thetaSteps, 360.0f * static_cast<float>(j) / phiSteps));
    std::vector<float> r = lobe(probe, tools::viewFrom(theta, phi), L);
    float top = std::max(1e-12f, *std::max_element(r.begin(), r.end()));

    std::ostringstream rib;
    // A camera above and in front of the lobe, looking at its middle (left-handed, +z forward).
    Mat4 view = glm::lookAtLH(Vec3(2.2f, -2.6f, 2.0f), Vec3(0.0f, 0.0f, 0.35f), Vec3(0.0f, 0.0f, 1.0f));
    float const* m = glm::value_ptr(view);
    rib << "Format 480 480 1\nProjection \"perspective\" \"fov\" [30]\nHider \"raytrace\" \"int maxsamples\" [16]\n"
           "Integrator \"PxrDirectLighting\" \"d\"\nTransform [";
    for (int k = 0; k < 16; ++k) rib << m[k] << ' ';
    rib << "]\nWorldBegin\n"
           "  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n"
           "  Light \"PxrDomeLight\" \"sky\" \"float intensity\" [0.6]\n"
           "  Translate 2 -3 4\n  Light \"PxrSphereLight\" \"key\" \"float intensity\" [20]\n  AttributeEnd\n"
           "  Bxdf \"diffuse\" \"lobe\" \"color diffuseColor\" [0.9 0.45 0.1]\n  PointsPolygons ";
    writeQuadGridFaces(rib, thetaSteps, phiSteps);
    rib << " \"P\" [";
    for (size_t k = 0; k < L.size(); ++k) {
        Vec3 p = L[k] * (r[k] / top);
        rib << p.x << ' ' << p.y << ' ' << p.z << ' ';
    }
    rib << "]\n  Bxdf \"diffuse\" \"surface\" \"color diffuseColor\" [0.5 0.5 0.5]\n  Disk -0.001 1.2 360\nWorldEnd\n";

    Diagnostics diagnostics(false);
    Scene scene;
    SceneBuilder(scene, diagnostics).readText(rib.str(), "<lobe>");
    RenderSettings settings;
    Renderer renderer(scene, settings, diagnostics);
    Film film = renderer.render();
    writeImage(path, film.rgba(), film.width(), film.height(), 4);
    std::cout << "spherical lobe -> " << path << '\n';
}

}  // namespace

int main(int argc, char** argv) {
    bxdflab::useOpenImageIO();
    CLI::App app{"rixlobe: plot a Bxdf plugin's lobe (a polar slice and a 3-D surface)"};
    std::string plugin, params, polar = "lobe-polar.png", sphere = "lobe-sphere.png", pluginPath;
    float theta = 45.0f, phi = 0.0f;
    app.add_option("plugin", plugin, "the Bxdf plugin's name (e.g. specular)")->required();
    app.add_option("--params", params, "parameters as on a RIB Bxdf line");
    app.add_option("--theta", theta, "viewer's angle from the normal, degrees")->check(CLI::Range(0.0f, 90.0f));
    app.add_option("--phi", phi, "viewer's azimuth, degrees (0: along dPdu)");
    app.add_option("--polar", polar, "the polar plot (empty: skip)");
    app.add_option("--sphere", sphere, "the 3-D plot (empty: skip)");
    app.add_option("--plugin-path", pluginPath, "colon-separated folders searched first");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);
    try {
        Diagnostics diagnostics;
        BxdfProbe probe(plugin, params, splitSearchPath(pluginPath), diagnostics);
        if (!polar.empty()) drawPolar(probe, theta, phi, polar);
        if (!sphere.empty()) drawSphere(probe, theta, phi, sphere);
        return 0;
    } catch (std::exception const& e) {
        std::cerr << "rixlobe: " << e.what() << '\n';
        return 1;
    }
}
