// The chapter 8 sampling functions: each sampler's pdf is the Jacobian of its
// mapping (checked by finite differences), matches its pdf function, and
// survives xi = 0 and xi = 1 - 2^-24.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "Sampling.h"

namespace {

using Sampler = std::function<RtVector3(RtFloat2 const&, float*)>;
using PdfFunction = std::function<float(RtVector3 const&)>;

struct Warp {
    const char* name;
    Sampler sample;
    PdfFunction pdf;
};

std::vector<Warp> warps() {
    return {
        {"uniform", sampling::sampleUniformHemisphere, sampling::uniformHemispherePdf},
        {"cosine", sampling::sampleCosineHemisphere, sampling::cosineHemispherePdf},
        {"phong n=1", [](RtFloat2 const& xi, float* pdf) { return sampling::samplePhongLobe(xi, 1.0f, pdf); },
         [](RtVector3 const& w) { return sampling::phongLobePdf(w, 1.0f); }},
        {"phong n=20", [](RtFloat2 const& xi, float* pdf) { return sampling::samplePhongLobe(xi, 20.0f, pdf); },
         [](RtVector3 const& w) { return sampling::phongLobePdf(w, 20.0f); }},
    };
}

}  // namespace

TEST_CASE("sampling: pdf = 1 / |Jacobian| of the mapping (finite differences)", "[sampling]") {
    for (Warp const& warp : warps()) {
        CAPTURE(warp.name);
        for (float u : {0.1f, 0.37f, 0.6f, 0.85f})
            for (float v : {0.05f, 0.3f, 0.7f}) {
                const double h = 1e-3;
                float pdf;
                RtVector3 w = warp.sample(RtFloat2(u, v), &pdf);
                float unused;
                RtVector3 du = (warp.sample(RtFloat2(u + h, v), &unused) - warp.sample(RtFloat2(u - h, v), &unused)) /
                               static_cast<float>(2 * h);
                RtVector3 dv = (warp.sample(RtFloat2(u, v + h), &unused) - warp.sample(RtFloat2(u, v - h), &unused)) /
                               static_cast<float>(2 * h);
                double area = du.Cross(dv).Length();  // solid angle per unit area of [0,1]^2
                CHECK(1.0 / area == Approx(pdf).epsilon(1e-2));
                CHECK(warp.pdf(w) == Approx(pdf).epsilon(1e-5));
                CHECK(w.Length() == Approx(1.0f).epsilon(1e-5));
            }
    }
}

TEST_CASE("sampling: extreme random numbers give valid directions with positive pdf", "[sampling][hard]") {
    for (Warp const& warp : warps())
        for (float u : {0.0f, 1.0f - 0x1p-24f})
            for (float v : {0.0f, 1.0f - 0x1p-24f}) {
                CAPTURE(warp.name, u, v);
                float pdf;
                RtVector3 w = warp.sample(RtFloat2(u, v), &pdf);
                CHECK(std::isfinite(w.x));
                CHECK(w.z > 0.0f);
                CHECK(pdf > 0.0f);
                CHECK(std::isfinite(pdf));
            }
}

TEST_CASE("sampling: each pdf integrates to 1 over the hemisphere", "[sampling]") {
    for (Warp const& warp : warps()) {
        CAPTURE(warp.name);
        const int n = 1024;
        double total = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < 2 * n; ++j) {
                double theta = (i + 0.5) * 0.5 * F_PI / n, phi = (j + 0.5) * F_PI / n;
                RtVector3 w(static_cast<float>(std::sin(theta) * std::cos(phi)),
                            static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
                total += warp.pdf(w) * std::sin(theta) * (0.5 * F_PI / n) * (F_PI / n);
            }
        CHECK(total == Approx(1.0).epsilon(1e-3));
    }
}
