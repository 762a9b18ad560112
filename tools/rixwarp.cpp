// rixwarp: does a plugin sample the directions its pdf promises?
//
//   rixwarp PLUGIN [--params "..."] [--theta 45] [--phi 0] [--samples 200000] [--out warp.png] [--sphere]
//
// Draws GenerateSample directions at one shade point (N = +z, the viewer at
// theta, phi), bins them over equal-area cells (cos(theta) up, phi across),
// and puts the histogram beside the same cells filled by integrating FPdf.
// The two pictures must look alike; the chi-squared test says whether they
// do (p-value above 0.01: pass, exit status 0; otherwise 1). --sphere maps
// the whole sphere of directions, for a model that transmits (chapter 10),
// and lets the viewer look from below (theta up to 180). Samples from
// discrete lobes (a mirror, a smooth refraction) have no density to compare:
// they are counted and the verdict is skipped, which the output says.
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "film/OiioImageFiles.h"
#include "CommandLine.h"
#include "ToolSupport.h"
#include "measure/BxdfMeasurer.h"
#include "stats/DirectionTest.h"

using namespace bxdflab;

int main(int argc, char** argv) {
    bxdflab::useOpenImageIO();
    CLI::App app{"rixwarp: a plugin's sampled directions beside its declared pdf, with a chi-squared verdict"};
    std::string plugin, params, out = "warp.png", pluginPath;
    float theta = 45.0f, phi = 0.0f;
    int samples = 200000;
    bool sphere = false;
    app.add_option("plugin", plugin, "the Bxdf plugin's name (e.g. diffuse)")->required();
    app.add_option("--params", params, "parameters as on a RIB Bxdf line, e.g. '\"float gloss\" [50]'");
    app.add_option("--theta", theta, "viewer's angle from the normal, degrees (up to 180 with --sphere)")
        ->check(CLI::Range(0.0f, 180.0f));
    app.add_option("--phi", phi, "viewer's azimuth, degrees");
    app.add_option("--samples", samples, "number of sampled directions")->check(CLI::Range(1000, 50000000));
    app.add_option("--out", out, "the side-by-side image");
    app.add_option("--plugin-path", pluginPath, "colon-separated folders searched first");
    app.add_flag("--sphere", sphere, "map the whole sphere of directions (a model that transmits)");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);
    if (theta > 90.0f && !sphere) {
        std::cerr << "rixwarp: a view from below the surface (--theta above 90) needs --sphere\n";
        return 1;
    }

    try {
        Diagnostics diagnostics;
        BxdfProbe probe(plugin, params, splitSearchPath(pluginPath), diagnostics);
        ProbePoint point = tools::viewFrom(theta, phi);
        DirectionCells cells;
        cells.cosCells = 32;
        cells.phiCells = 64;
        cells.fullSphere = sphere;
        long discrete = 0;
        DirectionCounts counts(cells);
        // What each valid sample contributes to an estimate, W / FPdf (averaged
        // over r, g, b): a good sampler keeps it close to constant and small.
        double weightSum = 0.0, weightLargest = 0.0;
        for (auto const& g : probe.generate(std::vector<ProbePoint>(static_cast<size_t>(samples), point),
                                            independentSamples(static_cast<size_t>(samples), 7u))) {
            counts.add(g.valid, g.L, g.FPdf);
            discrete += g.valid && g.discrete;
            if (g.valid && g.FPdf > 0.0f) {
                double weight = (g.W.r + g.W.g + g.W.b) / (3.0 * g.FPdf);
                weightSum += weight;
                weightLargest = std::max(weightLargest, weight);
            }
        }
        BatchPdf const pdf = [&](std::vector<Vec3> const& L) {
            std::vector<double> values;
            for (auto const& r : probe.evaluate(std::vector<ProbePoint>(L.size(), point), L)) values.push_back(r.FPdf);
            return values;
        };
        auto mass = integrateCells(cells, pdf, toleranceForSamples(samples));
        integrateEmptyCellsFinely(cells, counts.observed, pdf, mass, 64, &counts.example);
        DirectionTestResult t = testDirections(counts, mass);
        ChiSquaredResult const& chi = t.chi;
        std::vector<double> observed = counts.observed, expected;
        for (double m : mass) expected.push_back(m * samples);
        long valid = counts.total - counts.invalid - counts.nonFinite;

        double top = 0.0;
        for (size_t i = 0; i < observed.size(); ++i) top = std::max({top, observed[i], expected[i]});
        // Two maps of the hemisphere (cos theta up, phi across) under their
        // titles, with the axes labelled once on the left and below.
        const int cell = 6, gap = 24, marginLeft = 40, marginTop = 26, marginBottom = 40;
        OIIO::ImageBuf left = tools::heatmap(observed, cells.phiCells, cells.cosCells, top, cell);
        OIIO::ImageBuf right = tools::heatmap(expected, cells.phiCells, cells.cosCells, top, cell);
        int w = cells.phiCells * cell, ht = cells.cosCells * cell;
        OIIO::ImageBuf canvas(
            OIIO::ImageSpec(marginLeft + 2 * w + gap + 10, marginTop + ht + marginBottom, 3, OIIO::TypeDesc::FLOAT));
        OIIO::ImageBufAlgo::fill(canvas, {1.0f, 1.0f, 1.0f});
        int const rightX = marginLeft + w + gap;
        OIIO::ImageBufAlgo::paste(canvas, marginLeft, marginTop, 0, 0, left);
        OIIO::ImageBufAlgo::paste(canvas, rightX, marginTop, 0, 0, right);
        tools::label(canvas, marginLeft, marginTop - 8, "sampled directions (GenerateSample)");
        tools::label(canvas, rightX, marginTop - 8, "expected from FPdf");
        // (OpenImageIO draws ASCII only: the Greek letters are spelled out.)
        tools::label(canvas, 8, marginTop + 12, "1");
        tools::label(canvas, 8, marginTop + ht, sphere ? "-1" : "0");
        for (int x : {marginLeft, rightX}) {
            tools::label(canvas, x, marginTop + ht + 16, "0");
            tools::label(canvas, x + w - 28, marginTop + ht + 16, "360");
        }
        tools::label(canvas, marginLeft, marginTop + ht + 34,
                     std::string("up: cos(theta) ") + (sphere ? "-1" : "0") + "..1, across: phi 0..360 deg; viewer at theta " + tools::number(theta) +
                         " deg, phi " + tools::number(phi) + " deg; one colour scale");
        tools::writeDisplayImage(canvas, out);

        // No valid sample at all proves nothing: that is a failure, not a pass.
        bool pass = valid > 0 && chi.pValue > 0.01 && t.impossible == 0 && counts.nonFinite == 0;
        std::printf("%s at theta %.1f phi %.1f: %ld of %ld samples valid, FPdf integrates to %.4f over the %s\n",
                    plugin.c_str(), theta, phi, valid, counts.total, t.pdfMass, sphere ? "sphere" : "hemisphere");
        if (valid == 0)
            std::printf("no sample was valid: GenerateSample marked none valid (SetValid(true), or assigning a "
                        "lobe from RixBXLookupLobeByName)\n");
        else std::printf("sample weight W/FPdf: mean %.4g, largest %.4g\n", weightSum / valid, weightLargest);
        if (counts.nonFinite) std::printf("%ld valid samples had a NaN or infinite direction or pdf\n", counts.nonFinite);
        if (discrete > 0) {
            std::printf("%ld of the valid samples came from discrete lobes (one exact direction each, no density): "
                        "chi-squared skipped; rixcheck's \"smooth\" check tests such lobes\n", discrete);
            std::printf("left: sampled directions, right: FPdf (cos(theta) upward, phi across) -> %s\n", out.c_str());
            return 0;
        }
        std::printf("chi-squared %.2f with %d degrees of freedom: p = %.4g -> %s\n", chi.statistic,
                    chi.degreesOfFreedom, chi.pValue, pass ? "PASS" : "FAIL");
        if (t.impossible) std::printf("%ld samples fell where the pdf is zero (or below the surface)\n", t.impossible);
        if (counts.outside > 0)
            std::printf("%ld samples went below the surface: for a model that transmits, add --sphere\n", counts.outside);
        std::printf("left: sampled directions, right: FPdf (cos(theta) upward, phi across) -> %s\n", out.c_str());
        return pass ? 0 : 1;
    } catch (std::exception const& e) {
        std::cerr << "rixwarp: " << e.what() << '\n';
        return 2;
    }
}
