#include "probe/SamplingHistogram.h"

#include <cmath>

namespace bxdflab {

SamplingHistogram sampleHistogram(BxdfProbe& probe, ProbePoint const& point, int samples, int cosCells, int phiCells,
                                  int sub, uint32_t seed) {
    SamplingHistogram h;
    h.cosCells = cosCells;
    h.phiCells = phiCells;
    h.samples = samples;
    size_t cells = static_cast<size_t>(cosCells) * static_cast<size_t>(phiCells);
    h.observed.assign(cells, 0.0);
    h.expected.assign(cells, 0.0);

    auto generated = probe.generate(std::vector<ProbePoint>(static_cast<size_t>(samples), point), 0, seed, -1.0f,
                                    BxdfProbe::Sequence::Independent);
    for (ProbeResult const& g : generated) {
        if (!g.valid) continue;  // rejected samples are accounted for by the pdf's integral
        if (!isFinite(g.L) || !std::isfinite(g.FPdf) || glm::length(g.L) == 0.0f) {
            ++h.nonFiniteSamples;
            continue;
        }
        ++h.validSamples;
        Vec3 L = glm::normalize(g.L);
        int c = std::min(cosCells - 1, static_cast<int>(std::max(0.0f, L.z) * static_cast<float>(cosCells)));
        float phi = std::atan2(L.y, L.x);
        if (phi < 0) phi += 2 * kPi;
        int p = std::min(phiCells - 1, static_cast<int>(phi / (2 * kPi) * static_cast<float>(phiCells)));
        h.observed[static_cast<size_t>(c * phiCells + p)] += 1;
    }

    // FPdf over each cell, supersampled (cells are equal area: 2 pi / cells each).
    std::vector<Vec3> L;
    for (int c = 0; c < cosCells; ++c)
        for (int p = 0; p < phiCells; ++p)
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    float z = (static_cast<float>(c) + (a + 0.5f) / sub) / static_cast<float>(cosCells);
                    float phi = 2 * kPi * (static_cast<float>(p) + (b + 0.5f) / sub) / static_cast<float>(phiCells);
                    float s = std::sqrt(std::max(0.0f, 1 - z * z));
                    L.emplace_back(s * std::cos(phi), s * std::sin(phi), z);
                }
    auto pdfs = probe.evaluate(std::vector<ProbePoint>(L.size(), point), L);
    double cellArea = 2 * kPi / static_cast<double>(cells);
    size_t perCell = static_cast<size_t>(sub) * static_cast<size_t>(sub);
    for (size_t k = 0; k < pdfs.size(); ++k) {
        double mass = std::isfinite(pdfs[k].FPdf) ? pdfs[k].FPdf * cellArea / static_cast<double>(perCell) : 0.0;
        h.expected[k / perCell] += mass;
        h.pdfIntegral += mass;
    }
    // Compare shapes: expected counts scaled to the valid samples (the
    // supersampling error of a sharp lobe cancels out of the scale).
    if (h.pdfIntegral > 0.0)
        for (double& e : h.expected) e *= static_cast<double>(h.validSamples) / h.pdfIntegral;
    return h;
}

}  // namespace bxdflab
