// rixwarp: does a plugin sample the directions its pdf promises?
//
//   rixwarp PLUGIN [--params "..."] [--theta 45] [--phi 0] [--samples 200000] [--out warp.png]
//
// Draws GenerateSample directions at one shade point (N = +z, the viewer at
// theta, phi), bins them over equal-area cells (cos(theta) up, phi across),
// and puts the histogram beside the same cells filled by integrating FPdf.
// The two pictures must look alike; the chi-squared test says whether they
// do (p-value above 0.01: pass, exit status 0; otherwise 1).
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "CommandLine.h"
#include "ToolSupport.h"
#include "probe/SamplingHistogram.h"

using namespace bxdflab;

int main(int argc, char** argv) {
    CLI::App app{"rixwarp: a plugin's sampled directions beside its declared pdf, with a chi-squared verdict"};
    std::string plugin, params, out = "warp.png", pluginPath;
    float theta = 45.0f, phi = 0.0f;
    int samples = 200000;
    app.add_option("plugin", plugin, "the Bxdf plugin's name (e.g. diffuse)")->required();
    app.add_option("--params", params, "parameters as on a RIB Bxdf line, e.g. '\"float gloss\" [50]'");
    app.add_option("--theta", theta, "viewer's angle from the normal, degrees")->check(CLI::Range(0.0f, 90.0f));
    app.add_option("--phi", phi, "viewer's azimuth, degrees");
    app.add_option("--samples", samples, "number of sampled directions")->check(CLI::Range(1000, 50000000));
    app.add_option("--out", out, "the side-by-side image");
    app.add_option("--plugin-path", pluginPath, "colon-separated folders searched first");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);

    try {
        Diagnostics diagnostics;
        BxdfProbe probe(plugin, params, splitSearchPath(pluginPath), diagnostics);
        SamplingHistogram h = sampleHistogram(probe, tools::viewPoint(theta, phi), samples, 32, 64, 8);
        ChiSquaredResult chi = h.test();

        double top = 0.0;
        for (size_t i = 0; i < h.observed.size(); ++i) top = std::max({top, h.observed[i], h.expected[i]});
        const int cell = 6, gap = 12;
        OIIO::ImageBuf left = tools::heatmap(h.observed, h.phiCells, h.cosCells, top, cell);
        OIIO::ImageBuf right = tools::heatmap(h.expected, h.phiCells, h.cosCells, top, cell);
        int w = h.phiCells * cell, ht = h.cosCells * cell;
        OIIO::ImageBuf canvas(OIIO::ImageSpec(2 * w + gap, ht, 3, OIIO::TypeDesc::FLOAT));
        OIIO::ImageBufAlgo::fill(canvas, {1.0f, 1.0f, 1.0f});
        OIIO::ImageBufAlgo::paste(canvas, 0, 0, 0, 0, left);
        OIIO::ImageBufAlgo::paste(canvas, w + gap, 0, 0, 0, right);
        tools::writeDisplayImage(canvas, out);

        bool pass = chi.pValue > 0.01 && chi.impossibleSamples == 0 && h.nonFiniteSamples == 0;
        std::printf("%s at theta %.1f phi %.1f: %ld of %ld samples valid, pdf integral %.4f\n", plugin.c_str(), theta,
                    phi, h.validSamples, h.samples, h.pdfIntegral);
        std::printf("chi-squared %.2f with %d degrees of freedom: p = %.4g -> %s\n", chi.statistic,
                    chi.degreesOfFreedom, chi.pValue, pass ? "PASS" : "FAIL");
        if (chi.impossibleSamples) std::printf("%ld samples fell where the pdf is zero\n", chi.impossibleSamples);
        std::printf("left: sampled directions, right: FPdf (cos(theta) upward, phi across) -> %s\n", out.c_str());
        return pass ? 0 : 1;
    } catch (std::exception const& e) {
        std::cerr << "rixwarp: " << e.what() << '\n';
        return 2;
    }
}
