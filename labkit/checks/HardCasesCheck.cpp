// hardcases: grazing, exactly tangent and back-facing views and lights,
// degenerate tangents (zero, along N, not unit), random numbers 0 and
// 1 - 2^-24, and the exercise's extreme parameters, in every sampling mode:
// W finite, pdfs finite and never negative, and a sample marked valid has
// FPdf > 0 and a finite unit direction (otherwise it must be marked invalid).
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

namespace {

struct Named {
    Vec3 v;
    char const* name;
};

}  // namespace

CheckOutcome checkHardCases(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
    const float tiny = 1e-7f;
    std::vector<Named> const views = {{Vec3(0, 0, 1), "along the normal"},
                                      {glm::normalize(Vec3(1, 0, tiny)), "grazing, 1e-7 above the horizon"},
                                      {Vec3(1, 0, 0), "exactly on the horizon"},
                                      {glm::normalize(Vec3(1, 0, -tiny)), "grazing, 1e-7 below the horizon"},
                                      {glm::normalize(Vec3(0.3f, 0.2f, -0.9f)), "from below the surface"}};
    std::vector<Named> const tangents = {{Vec3(2.5f, 0, 0.8f), "an ordinary tangent"},
                                         {Vec3(0), "a zero tangent (dPdu = 0, as at a sphere's pole)"},
                                         {Vec3(0, 0, 1), "a tangent along the normal"},
                                         {Vec3(0, 3, 0.5f), "a long tangent"}};
    std::vector<Named> const lights = {{Vec3(0, 0, 1), "along the normal"},
                                       {glm::normalize(Vec3(0, 1, tiny)), "grazing above"},
                                       {Vec3(0, 1, 0), "on the horizon"},
                                       {glm::normalize(Vec3(0, 1, -tiny)), "grazing below"},
                                       {glm::normalize(Vec3(-0.5f, 0.1f, 0.8f)), "ordinary"}};
    std::vector<std::string> paramSets = {e.params};
    for (auto const& p : e.hardCaseParams) paramSets.push_back(e.params.empty() ? p : e.params + " " + p);
    int cases = 0;
    for (std::string const& base : paramSets)
        for (SamplingMode const& mode : e.samplingModes) {
            std::string const params = e.withMode(base, mode);
            for (Named const& V : views)
                for (Named const& T : tangents) {
                    ProbePoint point = f.point(V.v, T.v);
                    std::string where = withParams(params) + ", the viewer " + V.name + " and " + T.name;
                    for (float xi : {-1.0f, 0.0f, 1.0f - 0x1p-24f}) {
                        size_t n = xi < 0 ? 32 : 1;
                        auto samples = xi < 0 ? stratifiedSamples(n, c.seed + 5u) : fixedSamples(n, RtFloat2(xi, xi));
                        std::string draw = xi < 0 ? "" : " (every random number " + number(xi) + ")";
                        for (auto const& g : c.plugin.generate(params, std::vector<ProbePoint>(n, point), samples)) {
                            ++cases;
                            bool finite = std::isfinite(g.W.r) && std::isfinite(g.W.g) && std::isfinite(g.W.b) &&
                                          std::isfinite(g.FPdf) && std::isfinite(g.RPdf);
                            if (!finite)
                                return CheckOutcome::fail(where + draw + ": GenerateSample gave W " + describe(g.W) +
                                                          ", FPdf " + number(g.FPdf) + ", RPdf " + number(g.RPdf));
                            if (g.FPdf < 0 || g.RPdf < 0)
                                return CheckOutcome::fail(where + draw + ": GenerateSample gave a negative pdf (FPdf " +
                                                          number(g.FPdf) + ", RPdf " + number(g.RPdf) + ")");
                            if (!g.valid) continue;
                            if (!(g.FPdf > 0))
                                return CheckOutcome::fail(where + draw +
                                                          ": a sample marked valid has FPdf 0; mark it invalid instead");
                            float length = glm::length(g.L);
                            if (!isFinite(g.L) || !(std::fabs(length - 1.0f) < 1e-3f))
                                return CheckOutcome::fail(where + draw + ": a sample marked valid has the direction (" +
                                                          number(g.L.x) + ", " + number(g.L.y) + ", " + number(g.L.z) +
                                                          "), which is not a finite unit vector");
                        }
                    }
                    std::vector<Vec3> L;
                    for (auto const& l : lights) L.push_back(f.toWorld(l.v));
                    auto evaluated = c.plugin.evaluate(params, std::vector<ProbePoint>(L.size(), point), L);
                    for (size_t k = 0; k < evaluated.size(); ++k) {
                        ++cases;
                        auto const& r = evaluated[k];
                        std::string at = where + ", the light " + lights[k].name;
                        if (!(std::isfinite(r.W.r) && std::isfinite(r.W.g) && std::isfinite(r.W.b)) ||
                            !std::isfinite(r.FPdf) || !std::isfinite(r.RPdf))
                            return CheckOutcome::fail(at + ": EvaluateSample gave W " + describe(r.W) + ", FPdf " +
                                                      number(r.FPdf) + ", RPdf " + number(r.RPdf));
                        if (r.FPdf < 0 || r.RPdf < 0)
                            return CheckOutcome::fail(at + ": EvaluateSample gave a negative pdf (FPdf " +
                                                      number(r.FPdf) + ", RPdf " + number(r.RPdf) + ")");
                    }
                    for (auto const& emitted : c.plugin.emission(params, {point}))
                        if (!(std::isfinite(emitted.r) && std::isfinite(emitted.g) && std::isfinite(emitted.b)))
                            return CheckOutcome::fail(where + ": EmitLocal gave " + describe(emitted));
                }
        }
    return CheckOutcome::pass("all " + std::to_string(cases) + " hard cases stay finite with valid pdfs",
                              std::to_string(paramSets.size()) + " parameter sets x " +
                                  std::to_string(e.samplingModes.size()) + " sampling modes x " +
                                  std::to_string(views.size()) + " views x " + std::to_string(tangents.size()) +
                                  " tangents");
}

}  // namespace bxdflab
