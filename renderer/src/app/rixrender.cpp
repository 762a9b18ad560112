// rixrender: render a RIB scene with Rix Bxdf plugins.
//
//   rixrender [options] scene.rib
// Exit status: 0 on success, 1 when the scene cannot be rendered (the message
// says where and why), 2 for command-line mistakes.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "CommandLine.h"
#include "app/ImageModule.h"
#include "film/OiioImageFiles.h"
#include "core/CrashReport.h"
#include "core/Diagnostics.h"
#include "core/ImageFiles.h"
#include "film/RawImage.h"
#include "render/Renderer.h"
#include "parse/RibParser.h"
#include "scene/DisplayChannels.h"
#include "scene/SceneBuilder.h"

namespace fs = std::filesystem;
using namespace bxdflab;

namespace {

/// The image file a Display statement names. Framebuffer displays ("it")
/// have nowhere to show the image here, so it goes to a file of that name;
/// a name without an extension, or with one this renderer does not write (a
/// shadow map's ".z", a texture's ".tex"), gets the display type's.
std::string outputFor(DisplayDesc const& display) {
    fs::path name(display.name.empty() ? "rixrender" : display.name);
    if (name.has_extension() && isWritableImageName(name.string())) return name.string();
    std::string type = display.type;
    std::string extension = type == "tiff" ? ".tif" : type == "png" ? ".png" : ".exr";
    return name.string() + extension;
}

/// Where a further ("+name") display goes when -o moved the image: beside it, named after both, so that
/// nothing is written outside the folder -o chose ("out/a.exr" and "+normal.exr": "out/a.normal.exr").
std::string besideImage(std::string const& imagePath, DisplayDesc const& display) {
    fs::path image(imagePath), own(outputFor(display));
    return (image.parent_path() / (image.stem().string() + "." + own.stem().string() + own.extension().string()))
        .string();
}

/// Writes one display's image of a rendered film: RGBA for the shaded colour ("rgb", "rgba", "Ci"), else the
/// channels its mode asks for.
void writeDisplay(std::string const& path, DisplayDesc const& display, Film const& film) {
    DisplayLayout const& layout = display.layout;
    if (layout.channels.empty() || (layout.shadedOnly() && layout.channels.front().quantity == Quantity::Color)) {
        writeImage(path, film.rgba(), film.width(), film.height(), 4);
        return;
    }
    std::vector<std::string> names;
    for (DisplayChannel const& channel : layout.channels) names.push_back(channel.name);
    writeImage(path, film.channels(layout), film.width(), film.height(), static_cast<int>(names.size()), names);
}

/// "out.exr" for frame 7 is "out.0007.exr": a file of several frames writes one image each.
std::string numbered(std::string const& path, int frame) {
    if (frame < 0 || path.empty()) return path;
    fs::path p(path);
    char number[16];
    std::snprintf(number, sizeof number, ".%04d", frame);
    return (p.parent_path() / (p.stem().string() + number + p.extension().string())).string();
}

/// How many worlds (frames to render) the top-level file holds; archives are not opened.
int countWorlds(std::string const& path) {
    int worlds = 0;
    parseRibFile(path, [&worlds](RibRequest const& request) { worlds += request.name == "WorldBegin"; });
    return worlds;
}

void checkWritable(std::string const& path) {
    fs::path parent = fs::path(path).parent_path();
    if (parent.empty()) parent = ".";
    std::error_code error;  // queries that fail (a name too long, ...) count as "not there"
    if (fs::is_directory(path, error))
        throw RenderError("cannot write \"" + path + "\": it is a folder (give a file name, e.g. " +
                          (fs::path(path) / "image.exr").string() + ")");
    if (!fs::is_directory(parent, error))
        throw RenderError("cannot write image \"" + path + "\": folder \"" + parent.string() + "\" does not exist");
    if (access(parent.c_str(), W_OK) != 0)
        throw RenderError("cannot write image \"" + path + "\": folder \"" + parent.string() + "\" is not writable");
    if (fs::exists(path, error) && access(path.c_str(), W_OK) != 0)
        throw RenderError("cannot write image \"" + path + "\": the file is not writable");
}

/// A file that only makes textures (a pipeline's texture step, RenderMan's txmake as RIB) renders no
/// frame: it writes its textures, as RenderMan would. With -o they go into -o's folder, so that nothing
/// is written outside the folder -o chose.
void writeMadeTextures(std::map<std::string, MadeTexture> const& textures, std::string const& output, int rawFd) {
    if (rawFd >= 0) throw RenderError("the file only makes textures: it renders no image to write to the descriptor");
    for (auto const& [name, made] : textures) {
        fs::path const path =
            output.empty() ? fs::path(name) : fs::path(output).parent_path() / fs::path(name).filename();
        checkWritable(path.string());
        std::error_code error;
        if (fs::equivalent(path, made.picture, error))
            throw RibError(made.where, "the texture \"" + name + "\" would be written over its own picture");
        imageFiles().makeTexture(path.string(), made);
        std::fprintf(stderr, "rixrender: wrote %s (%s made from %s)\n", path.c_str(),
                     made.environment ? "a latitude-longitude environment map" : "a texture", made.picture.c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    bxdflab::crashreport::install("rixrender");
#ifdef BXDFLAB_LINK_OPENIMAGEIO
    bxdflab::useOpenImageIO();  // the sanitizer build (see renderer/CMakeLists.txt)
#else
    // The image module sits at ../lib/ from this program, in the build tree
    // and in the grader's sandbox alike.
    std::error_code noExe;
    fs::path self = fs::read_symlink("/proc/self/exe", noExe);
    bxdflab::useImageModule(((noExe ? fs::path(argv[0]) : self).parent_path() / ".." / "lib" / "rixoiio.so").string());
#endif
    CLI::App app{"rixrender: render a RIB scene with Rix Bxdf plugins"};
    std::string sceneFile, output, statsJson, variance;
    int rawFd = -1;
    RenderSettings settings;
    LoadOptions load;
    float resolutionScale = 1.0f;
    bool quiet = false;
    app.add_option("scene", sceneFile, "the RIB file to render")->required();
    app.add_option("-o", output, "write the image here (overrides Display; format from the extension: .exr .png .tif); "
                                 "a file of several frames writes NAME.0001.EXT, ... (the FrameBegin numbers)");
    app.add_option("--spp", settings.spp, "samples per pixel (overrides PixelSamples / Hider maxsamples)")
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("--pixel-variance", settings.pixelVariance,
                   "adaptive sampling: a pixel stops once its relative variance is at most this (overrides "
                   "PixelVariance; 0: every pixel takes all its samples)")
        ->check(CLI::Range(0.0f, 1e30f));
    app.add_option("--threads", settings.threads, "worker threads (default: all cores)")->check(CLI::Range(1, 1024));
    app.add_option("--seed", settings.seed, "sample-sequence seed; the same seed gives the same image");
    app.add_option("--plugin-path", settings.pluginPath, "colon-separated plugin folders, searched first");
    app.add_option("--stats-json", statsJson, "write timing, ray counts and simulated/skipped effects here");
    app.add_option("--variance", variance, "also write each pixel's variance of the mean (an EXR image)");
    app.add_option("--frame", load.frame, "render only the frame with this FrameBegin number")->check(CLI::Range(0, 1 << 30));
    app.add_option("--resolution-scale", resolutionScale, "scale the Format resolution (e.g. 0.25 for a quick look)")
        ->check(CLI::Range(0.01f, 8.0f));
    app.add_flag("--run-programs", load.runPrograms,
                 "run the programs the scene's Procedural \"RunProgram\" requests name (they are the scene's code: "
                 "use it for scenes you trust)");
    app.add_flag("--strict", load.strict, "a file the scene names that is missing (archive, texture, sky image) is an "
                                          "error instead of a warning");
    app.add_flag("--quiet", quiet, "no progress bar");
    app.add_option("--raw-out-fd", rawFd, "write the pixels and their variances to this open descriptor instead of a file "
                                          "(for programs that read them directly)")
        ->check(CLI::Range(3, 1023));
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);

    Diagnostics diagnostics;
    try {
        // Files named on the command line are checked before anything renders.
        for (std::string const& path : {output, statsJson, variance})
            if (!path.empty()) checkWritable(path);
        bool const severalFrames = load.frame < 0 && countWorlds(sceneFile) > 1;
        if (severalFrames && rawFd >= 0) throw RenderError(sceneFile + " holds several frames: choose one with --frame");
        int rendered = 0;
        auto renderFrame = [&](Scene& scene) {
            if (resolutionScale != 1.0f) {
                scene.xres = std::max(1, static_cast<int>(std::lround(scene.xres * resolutionScale)));
                scene.yres = std::max(1, static_cast<int>(std::lround(scene.yres * resolutionScale)));
            }
            int const number = severalFrames ? (scene.frame >= 0 ? scene.frame : rendered + 1) : -1;
            std::string imagePath = output.empty() && rawFd < 0 ? outputFor(scene.display) : numbered(output, number);
            // Every image the frame writes is checked before it renders.
            std::vector<std::string> morePaths;
            if (!imagePath.empty()) {
                checkWritable(imagePath);
                for (DisplayDesc const& display : scene.moreDisplays) {
                    morePaths.push_back(output.empty() ? outputFor(display) : besideImage(imagePath, display));
                    checkWritable(morePaths.back());
                }
            }
            if (number >= 0) std::fprintf(stderr, "rixrender: frame %d\n", number);

            settings.progress = !quiet && isatty(STDERR_FILENO);
            Renderer renderer(scene, settings, diagnostics);
            Film film = renderer.render();
            if (rawFd >= 0 && !writeRawImage(rawFd, film))
                throw RenderError("cannot write the raw image to descriptor " + std::to_string(rawFd));
            if (!imagePath.empty()) {
                writeDisplay(imagePath, scene.display, film);
                for (size_t k = 0; k < morePaths.size(); ++k) writeDisplay(morePaths[k], scene.moreDisplays[k], film);
            }
            if (!variance.empty())
                writeImage(numbered(variance, number), film.varianceOfMean(), film.width(), film.height(), 3);

            RenderStats const& stats = renderer.stats();
            if (!statsJson.empty()) {
                std::ofstream out(numbered(statsJson, number));
                out << stats.toJson(diagnostics).dump(2) << '\n';
                if (!out) throw RenderError("cannot write stats to \"" + numbered(statsJson, number) + "\"");
            }
            std::fprintf(stderr,
                         "rixrender: %dx%d, %d spp, %d threads: %.2f s (setup %.2f s, render %.2f s); rays: %llu camera, "
                         "%llu shadow, %llu indirect\n",
                         stats.width, stats.height, stats.spp, stats.threads, stats.setupSeconds + stats.renderSeconds,
                         stats.setupSeconds, stats.renderSeconds, static_cast<unsigned long long>(stats.cameraRays),
                         static_cast<unsigned long long>(stats.shadowRays),
                         static_cast<unsigned long long>(stats.indirectRays));
            // Which shared object each plugin came from: a forgotten --plugin-path shows here.
            std::string loaded;
            for (std::string const& plugin : stats.plugins) loaded += (loaded.empty() ? "" : ", ") + plugin;
            if (!loaded.empty()) std::fprintf(stderr, "rixrender: plugins: %s\n", loaded.c_str());
            if (imagePath.empty())
                std::fprintf(stderr, "rixrender: wrote the raw image to descriptor %d\n", rawFd);
            else if (scene.display.type == "it" || scene.display.type == "framebuffer")
                std::fprintf(stderr, "rixrender: Display \"%s\" is a framebuffer; the image was written to %s\n",
                             scene.display.name.c_str(), imagePath.c_str());
            else if (output.empty() && fs::path(scene.display.name).has_extension() &&
                     !isWritableImageName(scene.display.name))
                std::fprintf(stderr,
                             "rixrender: Display \"%s\" names a file type this renderer does not write; the image was "
                             "written to %s\n",
                             scene.display.name.c_str(), imagePath.c_str());
            else
                std::fprintf(stderr, "rixrender: wrote %s\n", imagePath.c_str());
            for (std::string const& path : morePaths) std::fprintf(stderr, "rixrender: wrote %s\n", path.c_str());
            ++rendered;
        };
        Scene scene;
        SceneBuilder builder(scene, diagnostics, load);
        builder.setFrameSink(renderFrame);
        builder.readFile(sceneFile);
        if (load.frame >= 0 && rendered == 0)
            throw RenderError(sceneFile + ": there is no frame " + std::to_string(load.frame) + " (FrameBegin " +
                              std::to_string(load.frame) + ")");
        if (rendered == 0) writeMadeTextures(scene.madeTextures, output, rawFd);
    } catch (std::exception const& error) {
        std::cerr << "rixrender: error: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
