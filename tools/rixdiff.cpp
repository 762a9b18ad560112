// rixdiff: compare two renders (yours and the solution's).
//
//   rixdiff A.exr B.exr [--heatmap diff.png] [--max-rmse X] [--max-relmse X] [--min-psnr X] [--json FILE]
//
// Prints mean (of A and of B), RMSE, relMSE = mean((a - b)^2 / (b^2 + 0.01)),
// the largest difference and PSNR over the colour channels, and writes a
// heatmap of |A - B| (black = equal). Exit status: 0 when every given
// threshold holds, 1 when one fails, 2 for bad input (unreadable images,
// different sizes).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "CommandLine.h"
#include "image/RenderComparison.h"

namespace {

OIIO::ImageBuf readRgb(std::string const& path) {
    OIIO::ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT))
        throw std::runtime_error("cannot read \"" + path + "\": " + image.geterror());
    int channels = std::min(3, image.nchannels());
    OIIO::ImageBuf rgb = OIIO::ImageBufAlgo::channels(image, channels, {});
    if (rgb.has_error()) throw std::runtime_error("cannot use \"" + path + "\": " + rgb.geterror());
    return rgb;
}

std::vector<float> pixels(OIIO::ImageBuf const& image) {
    std::vector<float> values(image.spec().image_pixels() * static_cast<size_t>(image.nchannels()));
    image.get_pixels(image.roi(), OIIO::TypeDesc::FLOAT, values.data());
    return values;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rixdiff: statistics and a heatmap of the difference of two renders"};
    std::string pathA, pathB, heatmap, jsonPath;
    double maxRmse = -1, maxRelMse = -1, minPsnr = -1;
    app.add_option("A", pathA, "your image")->required();
    app.add_option("B", pathB, "the reference image")->required();
    app.add_option("--heatmap", heatmap, "write |A - B| as a colour-mapped image here");
    app.add_option("--max-rmse", maxRmse, "fail when RMSE is larger");
    app.add_option("--max-relmse", maxRelMse, "fail when relMSE is larger");
    app.add_option("--min-psnr", minPsnr, "fail when PSNR (dB) is smaller");
    app.add_option("--json", jsonPath, "also write the statistics as JSON");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);

    try {
        OIIO::ImageBuf a = readRgb(pathA), b = readRgb(pathB);
        if (a.spec().width != b.spec().width || a.spec().height != b.spec().height ||
            a.nchannels() != b.nchannels()) {
            std::cerr << "rixdiff: the images differ in size or channels (" << a.spec().width << "x" << a.spec().height
                      << " vs " << b.spec().width << "x" << b.spec().height << ")\n";
            return 2;
        }
        OIIO::ImageBufAlgo::CompareResults compared = OIIO::ImageBufAlgo::compare(a, b, 0.0f, 0.0f);
        OIIO::ImageBuf difference = OIIO::ImageBufAlgo::absdiff(a, b);
        auto statsA = OIIO::ImageBufAlgo::computePixelStats(a);
        auto statsB = OIIO::ImageBufAlgo::computePixelStats(b);
        auto average = [](std::vector<float> const& v) {
            double s = 0;
            for (float x : v) s += x;
            return v.empty() ? 0.0 : s / static_cast<double>(v.size());
        };
        double relMse = bxdflab::relativeMse(pixels(a), pixels(b));  // the grader's metric (labkit)
        nlohmann::json result = {
            {"mean_a", average(statsA.avg)}, {"mean_b", average(statsB.avg)}, {"rmse", compared.rms_error},
            {"relmse", relMse},              {"max", compared.maxerror},       {"psnr", compared.PSNR},
        };
        std::cout << "mean A  " << result["mean_a"] << "\nmean B  " << result["mean_b"] << "\nRMSE    "
                  << compared.rms_error << "\nrelMSE  " << relMse << "\nmax     " << compared.maxerror << "\nPSNR    "
                  << compared.PSNR << " dB\n";

        if (!heatmap.empty()) {
            // Average the channels, scale so the largest difference is the top of the map.
            OIIO::ImageBuf grey = OIIO::ImageBufAlgo::channel_sum(difference, {1.0f / 3, 1.0f / 3, 1.0f / 3});
            float scale = compared.maxerror > 0 ? static_cast<float>(1.0 / compared.maxerror) : 1.0f;
            OIIO::ImageBuf mapped = OIIO::ImageBufAlgo::color_map(OIIO::ImageBufAlgo::mul(grey, scale), 0, "inferno");
            mapped.set_write_format(OIIO::TypeDesc::UINT8);
            if (!mapped.write(heatmap)) {
                std::cerr << "rixdiff: cannot write \"" << heatmap << "\": " << mapped.geterror() << '\n';
                return 2;
            }
        }
        if (!jsonPath.empty()) std::ofstream(jsonPath) << result.dump(2) << '\n';

        bool pass = true;
        auto check = [&](bool ok, std::string const& what) {
            if (!ok) {
                std::cout << "FAIL: " << what << '\n';
                pass = false;
            }
        };
        if (maxRmse >= 0) check(compared.rms_error <= maxRmse, "RMSE above " + std::to_string(maxRmse));
        if (maxRelMse >= 0) check(relMse <= maxRelMse, "relMSE above " + std::to_string(maxRelMse));
        if (minPsnr >= 0) check(compared.PSNR >= minPsnr, "PSNR below " + std::to_string(minPsnr));
        return pass ? 0 : 1;
    } catch (std::exception const& e) {
        std::cerr << "rixdiff: " << e.what() << '\n';
        return 2;
    }
}
