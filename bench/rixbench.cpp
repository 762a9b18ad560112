// rixbench: what the renderer costs, measured in one process.
//
//   rixbench [scene.rib]   (default: scenes/ch06/diffuse.rib)
//
// 1. Shading overhead: the render's own camera and shadow rays are recorded,
//    then traced again by Embree alone; the ratio render / raw tracing is the
//    price of everything that is not ray tracing (target: at most 1.5, stretch 1.3).
// 2. Thread scaling: 2 threads against 1 (target: at least 1.85); whole
//    spheres by the exact quadric code against Embree's sphere primitive.
// 3. Cost against samples per pixel, resolution and triangle count.
// 4. A textured colour against a uniform one; 5. start-up of rixrender and rixcheck,
//    and what writing an image adds; 6. peak memory at 4 and 64 spp.
// Times are the best of three to five runs; the two sides of a ratio are timed
// in turn, so that a slow spell of a shared machine does not fall on one side
// only. It prints ratios; it asserts nothing.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "CommandLine.h"
#include "RayRecording.h"
#include "film/OiioImageFiles.h"
#include "parse/RibText.h"
#include "render/Renderer.h"
#include "scene/SceneBuilder.h"

using namespace bxdflab;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double bestOf(int runs, std::function<void()> const& work) {
    double best = 1e30;
    for (int r = 0; r < runs; ++r) {
        auto start = Clock::now();
        work();
        best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return best;
}

/// The best time of each piece of work over `rounds` rounds, each round
/// running every piece once in turn: a slow spell of a shared machine then
/// falls on all sides of a ratio alike instead of on one of them.
std::vector<double> bestOfInterleaved(int rounds, std::vector<std::function<void()>> const& works) {
    std::vector<double> best(works.size(), 1e30);
    for (int r = 0; r < rounds; ++r)
        for (size_t w = 0; w < works.size(); ++w) best[w] = std::min(best[w], bestOf(1, works[w]));
    return best;
}

double renderSeconds(Scene& scene, int spp, int threads, Diagnostics& diagnostics) {
    RenderSettings settings;
    settings.spp = spp;
    settings.threads = threads;
    Renderer renderer(scene, settings, diagnostics);
    return bestOf(3, [&] { renderer.render(); });
}

/// A sphere of about `triangles` triangles in front of the camera, lit by a disk light.
std::string meshScene(int triangles) {
    int n = std::max(4, static_cast<int>(std::sqrt(triangles / 2.0)));
    std::ostringstream rib;
    rib << "Format 200 175 1\nProjection \"perspective\" \"fov\" [15]\nIntegrator \"PxrDirectLighting\" \"d\"\n"
           "WorldBegin\n AttributeBegin\n Translate -2 2 0\n Rotate 14.04 0 1 0\n Rotate 13.63 1 0 0\n"
           " Light \"PxrDiskLight\" \"l\" \"float intensity\" [150]\n AttributeEnd\n Translate 0 0 8\n"
           " Bxdf \"diffuse\" \"d\"\n PointsPolygons ";
    writeQuadGridFaces(rib, n, n);
    rib << " \"P\" [";
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            double theta = M_PI * i / n, phi = 2 * M_PI * j / n;
            rib << 0.8 * std::sin(theta) * std::cos(phi) << ' ' << 0.8 * std::sin(theta) * std::sin(phi) << ' '
                << 0.8 * std::cos(theta) << ' ';
        }
    rib << "]\nWorldEnd\n";
    return rib.str();
}

std::string readFile(std::string const& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// A mip-mapped checkerboard of size x size pixels in the temporary folder; returns its path.
std::string writeCheckerTexture(int size) {
    OIIO::ImageBuf image(OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::HALF));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float value = ((x / 64 + y / 64) % 2) ? 0.9f : 0.3f;
            float rgb[3] = {value, value * 0.8f, value * 0.6f};
            image.setpixel(x, y, rgb);
        }
    std::string path = (std::filesystem::temp_directory_path() / "rixbench_checker.tx").string();
    OIIO::ImageSpec config;
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, image, path, config))
        throw RenderError("cannot write " + path + ": " + OIIO::geterror());
    return path;
}

void runQuietly(std::string const& command) {
    if (std::system((command + " > /dev/null 2>&1").c_str()) != 0) std::fprintf(stderr, "rixbench: %s failed\n", command.c_str());
}

/// Peak resident memory of a whole rixrender process, from its stats JSON.
double peakMemoryMB(fs::path const& rixrender, std::string const& scene, int spp) {
    fs::path const stats = fs::temp_directory_path() / "rixbench_memory.json";
    runQuietly(rixrender.string() + " --quiet --resolution-scale 0.5 --spp " + std::to_string(spp) + " --stats-json " +
               stats.string() + " " + scene + " -o " + (fs::temp_directory_path() / "rixbench_memory.exr").string());
    std::ifstream in(stats);
    return nlohmann::json::parse(in, nullptr, false).value("peak_memory_mb", 0.0);
}

/// How the render's shade points were grouped into batches (one shading
/// context each): large batches amortise every per-batch cost.
void printBatchStatistics(RenderStats const& stats) {
    double const batches = static_cast<double>(std::max<uint64_t>(1, stats.batches));
    auto percentOfSurface = [&](uint64_t points) {
        return stats.surfacePoints ? 100.0 * static_cast<double>(points) / static_cast<double>(stats.surfacePoints) : 0.0;
    };
    std::printf("shading: %llu points in %llu batches, %.0f points per batch; %.0f%% of the points asked for (u, v, s, t), "
                "%.0f%% for tangents\n",
                static_cast<unsigned long long>(stats.shadePoints), static_cast<unsigned long long>(stats.batches),
                static_cast<double>(stats.shadePoints) / batches, percentOfSurface(stats.parameterPoints),
                percentOfSurface(stats.tangentPoints));
}

/// Whole spheres through the quadric's exact code (the default) against
/// Embree's own sphere primitive: one thread each, timed in turn, and how far
/// apart the two images are.
void printWholeSpheres(Scene& scene, int spp, Diagnostics& diagnostics) {
    RenderSettings settings;
    settings.spp = spp;
    settings.threads = 1;
    Renderer exact(scene, settings, diagnostics);
    settings.wholeSpheres = WholeSpheres::EmbreePrimitive;
    Renderer embree(scene, settings, diagnostics);
    std::vector<float> exactImage, embreeImage;
    std::vector<double> best = bestOfInterleaved(
        3, {[&] { exactImage = exact.render().rgba(); }, [&] { embreeImage = embree.render().rgba(); }});
    double largest = 0.0;
    for (size_t i = 0; i < exactImage.size(); ++i)
        largest = std::max(largest, static_cast<double>(std::abs(exactImage[i] - embreeImage[i])));
    std::printf("whole spheres: exact (double, user geometry) %.3f s   Embree's sphere primitive %.3f s   ratio: %.2f; "
                "largest pixel difference %.1e\n",
                best[0], best[1], best[1] / best[0], largest);
}

}  // namespace

int main(int argc, char** argv) {
    std::string const defaultScene = std::string(BXDFLAB_SOURCE_DIR) + "/scenes/ch06/diffuse.rib";
    std::string sceneFile = defaultScene;
    CLI::App app{"rixbench: the renderer's own costs, as ratios measured in one run (prints; asserts nothing)"};
    app.add_option("scene", sceneFile, "the RIB scene to measure (default: the chapter-6 diffuse sphere)");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);
    bxdflab::useOpenImageIO();
    Diagnostics diagnostics(false);
    Scene scene;
    try {
        scene = loadScene(sceneFile, diagnostics);
    } catch (std::exception const& error) {
        std::fprintf(stderr, "rixbench: %s\n", error.what());
        return 1;
    }
    const int spp = 16;

    // 1. Shading overhead against raw Embree, one thread each, and (2.) the
    //    same render on two threads, timed in turn.
    RayRecording rays;
    double render1 = 0.0, raw = 0.0, render2 = 0.0;
    RenderStats batches;
    {
        RenderSettings settings;
        settings.spp = spp;
        settings.threads = 1;
        Renderer renderer(scene, settings, diagnostics);
        renderer.tracer().observe(&rays);
        renderer.render();
        renderer.tracer().observe(nullptr);
        settings.threads = 2;
        Renderer twoThreads(scene, settings, diagnostics);
        std::vector<double> best = bestOfInterleaved(
            5, {[&] { renderer.render(); }, [&] { rays.replay(renderer.tracer()); }, [&] { twoThreads.render(); }});
        render1 = best[0];
        raw = best[1];
        render2 = best[2];
        batches = renderer.stats();
    }
    size_t shadow = rays.occlusionRays();
    std::printf("scene %s, %dx%d, %d spp\n", sceneFile.c_str(), scene.xres, scene.yres, spp);
    std::printf("rays recorded: %zu camera + %zu shadow\n", rays.rays().size() - shadow, shadow);
    std::printf("raw Embree: %.3f s   full render: %.3f s   overhead ratio: %.2f (target <= 1.5, stretch 1.3)\n", raw, render1,
                render1 / raw);
    printBatchStatistics(batches);

    std::printf("1 thread: %.3f s   2 threads: %.3f s   scaling: %.2fx (target >= 1.85)\n", render1, render2,
                render1 / render2);
    printWholeSpheres(scene, spp, diagnostics);

    // 3. Cost scaling (2 threads).
    std::printf("\nspp      seconds\n");
    for (int s : {1, 4, 16, 64}) std::printf("%-8d %.3f\n", s, renderSeconds(scene, s, 2, diagnostics));
    std::printf("\nresolution  seconds (%d spp)\n", spp);
    int xres = scene.xres, yres = scene.yres;
    for (int div : {4, 2, 1}) {
        scene.xres = xres / div;
        scene.yres = yres / div;
        std::printf("%4dx%-6d %.3f\n", scene.xres, scene.yres, renderSeconds(scene, spp, 2, diagnostics));
    }
    // 4. A texture on the diffuse colour: the chapter-6 sphere with its colour
    //    from a 2048 x 2048 mip-mapped texture, against the uniform colour.
    if (sceneFile == defaultScene) {
        scene.xres = xres;
        scene.yres = yres;
        std::string const texture = writeCheckerTexture(2048);
        std::string rib = readFile(sceneFile);
        std::string const uniform = "\"color diffuseColor\" [1 1 1]";
        rib.replace(rib.find(uniform), uniform.size(), "\"reference color diffuseColor\" [\"tex:resultRGB\"]");
        rib.insert(rib.find("    Bxdf \"diffuse\""), "    Pattern \"PxrTexture\" \"tex\" \"string filename\" [\"" + texture + "\"]\n");
        Scene textured;
        SceneBuilder(textured, diagnostics).readText(rib, sceneFile);
        RenderSettings settings;
        settings.spp = spp;
        settings.threads = 2;
        Renderer uniformRenderer(scene, settings, diagnostics), textureRenderer(textured, settings, diagnostics);
        std::vector<double> best =
            bestOfInterleaved(3, {[&] { uniformRenderer.render(); }, [&] { textureRenderer.render(); }});
        double plain = best[0], mapped = best[1];
        std::printf("\ntexture     uniform colour: %.3f s   2048^2 texture: %.3f s   ratio: %.2f (target <= 1.50)\n", plain,
                    mapped, mapped / plain);
    }

    std::printf("\ntriangles   seconds (200x175, %d spp)\n", spp);
    for (int triangles : {1000, 10000, 100000, 1000000}) {
        Scene mesh;
        SceneBuilder(mesh, diagnostics).readText(meshScene(triangles), "<mesh>");
        std::printf("%-11d %.3f\n", triangles, renderSeconds(mesh, spp, 2, diagnostics));
    }

    // 5. Start-up: what a process costs before it reads a byte (best of 10),
    //    for the programs the grader starts once per check or render.
    std::printf("\nstart-up (best of 10)\n");
    fs::path const bin = fs::read_symlink("/proc/self/exe").parent_path();
    for (char const* program : {"rixrender", "rixcheck"}) {
        double seconds = bestOf(10, [&] { runQuietly((bin / program).string() + " --help"); });
        std::printf("%-11s %.1f ms (target <= 30 ms)\n", program, 1000.0 * seconds);
    }
    // What writing an image adds: the same 8 x 7 render with and without an
    // image file (only programs that write images load OpenImageIO).
    std::string const tiny = (bin / "rixrender").string() + " --quiet --spp 1 --threads 1 --resolution-scale 0.01 " +
                             defaultScene;
    double const noImage = bestOf(10, [&] { runQuietly(tiny + " --raw-out-fd 9 9>/dev/null"); });
    double const exr = bestOf(10, [&] { runQuietly(tiny + " -o " + (fs::temp_directory_path() / "rixbench_tiny.exr").string()); });
    std::printf("rixrender, an 8x7 render: %.1f ms; written as EXR: %.1f ms (+%.1f ms: loading OpenImageIO)\n",
                1000.0 * noImage, 1000.0 * exr, 1000.0 * (exr - noImage));

    // 6. Memory: peak resident memory of whole renders at 4 and 64 spp (half
    //    resolution, separate processes); it must not grow with samples.
    if (sceneFile == defaultScene) {
        std::printf("\npeak memory (rixrender, half resolution)\n");
        double peak4 = peakMemoryMB(bin / "rixrender", sceneFile, 4), peak64 = peakMemoryMB(bin / "rixrender", sceneFile, 64);
        std::printf("4 spp: %.1f MiB   64 spp: %.1f MiB   ratio: %.3f (target <= 1.10)\n", peak4, peak64, peak64 / peak4);
    }
    return 0;
}
