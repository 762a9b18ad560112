// hardcases: grazing, exactly tangent and back-facing views and lights
// (tangent to the bit in an unturned frame, as at a silhouette), degenerate
// tangents (zero, along N, not unit), random numbers 0 and 1 - 2^-24, views
// and lights between the horizons of a shading normal bent away from the
// geometric one, and the exercise's extreme parameters, in every sampling
// mode: W finite and never negative, pdfs finite and never negative (from
// EvaluateSample and EvaluateSamplesAtIndex alike), and a sample marked valid
// has FPdf > 0 and a finite unit direction (otherwise it must be marked
// invalid).
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

namespace {

struct Named {
    Vec3 v;
    char const* name;
};

bool isFiniteColor(RtColorRGB const& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }
bool isNegative(RtColorRGB const& c) { return c.r < 0 || c.g < 0 || c.b < 0; }

/// What is wrong with the W and pdfs a Bxdf's `call` gave, or "" when nothing is.
std::string valueProblem(ProbeResult const& r, std::string const& call) {
    if (!isFiniteColor(r.W) || !std::isfinite(r.FPdf) || !std::isfinite(r.RPdf))
        return call + " gave W " + describe(r.W) + ", FPdf " + number(r.FPdf) + ", RPdf " + number(r.RPdf);
    if (isNegative(r.W)) return call + " gave a negative W " + describe(r.W);
    if (r.FPdf < 0 || r.RPdf < 0)
        return call + " gave a negative pdf (FPdf " + number(r.FPdf) + ", RPdf " + number(r.RPdf) + ")";
    return "";
}

/// What is wrong with what GenerateSample gave, or "" when nothing is.
std::string generatedProblem(ProbeResult const& g) {
    if (std::string problem = valueProblem(g, "GenerateSample"); !problem.empty()) return problem;
    if (!g.valid) return "";
    if (!(g.FPdf > 0)) return "a sample marked valid has FPdf 0; mark it invalid instead";
    float length = glm::length(g.L);
    if (!isFinite(g.L) || !(std::fabs(length - 1.0f) < 1e-3f))
        return "a sample marked valid has the direction (" + number(g.L.x) + ", " + number(g.L.y) + ", " +
               number(g.L.z) + "), which is not a finite unit vector";
    return "";
}

}  // namespace

CheckOutcome checkHardCases(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
    const float tiny = 1e-7f;
    std::vector<Named> const views = {{Vec3(0, 0, 1), "along the normal"},
                                      {glm::normalize(Vec3(1, 0, tiny)), "grazing, 1e-7 above the horizon"},
                                      {Vec3(1, 0, 0), "on the horizon (to float precision)"},
                                      {glm::normalize(Vec3(1, 0, -tiny)), "grazing, 1e-7 below the horizon"},
                                      {glm::normalize(Vec3(0.3f, 0.2f, -0.9f)), "from below the surface"}};
    std::vector<Named> const tangents = {{Vec3(2.5f, 0, 0.8f), "an ordinary tangent"},
                                         {Vec3(0), "a zero tangent (dPdu = 0, as at a sphere's pole)"},
                                         {Vec3(0, 0, 1), "a tangent along the normal"},
                                         {Vec3(0, 3, 0.5f), "a long tangent"}};
    // Turned 40 degrees, "on the horizon" is so only to float precision (N.V
    // comes out as 3e-8). In the unturned frame N.V and N.L are exactly 0, as where a ray grazes a
    // silhouette: a division by the cosine there gives infinity.
    Frame const unturned(0.0f);
    std::vector<Named> const exactViews = {
        {Vec3(1, 0, 0), "exactly on the horizon (N.V = 0 to the bit)"},
        {Vec3(0, 0, 1), "along the normal (frame unturned: a light on the horizon has N.L = 0 to the bit)"}};
    std::vector<Named> const lights = {{Vec3(0, 0, 1), "along the normal"},
                                       {glm::normalize(Vec3(0, 1, tiny)), "grazing above"},
                                       {Vec3(0, 1, 0), "on the horizon"},
                                       {glm::normalize(Vec3(0, 1, -tiny)), "grazing below"},
                                       {glm::normalize(Vec3(-0.5f, 0.1f, 0.8f)), "ordinary"}};
    // A smooth-shaded mesh bends the shading normal N away from the geometric
    // normal Ng (20 degrees at azimuth 250 here): a direction can then lie above
    // one horizon and below the other. What a model does there is its writer's
    // choice, within the rules above.
    std::vector<Named> const between = {
        {direction(0, 0), "along the shading normal (the geometric normal bent 20 deg)"},
        {direction(80, 70), "above the shading normal's horizon and below the geometric normal's"},
        {direction(100, 250), "below the shading normal's horizon and above the geometric normal's"}};
    std::vector<std::string> paramSets = {e.params};
    for (auto const& p : e.hardCaseParams) paramSets.push_back(e.params.empty() ? p : e.params + " " + p);
    int cases = 0;
    // Generates from `point` (32 stratified draws, then every random number 0 and 1 - 2^-24) and
    // evaluates `toward` (local directions) there: the first problem found, or "".
    auto probe = [&](std::string const& params, Frame const& frameOf, ProbePoint const& point,
                     std::string const& where, std::vector<Named> const& toward) -> std::string {
        for (float xi : {-1.0f, 0.0f, 1.0f - 0x1p-24f}) {
            size_t n = xi < 0 ? 32 : 1;
            auto samples = xi < 0 ? stratifiedSamples(n, c.seed + 5u) : fixedSamples(n, RtFloat2(xi, xi));
            std::string draw = xi < 0 ? "" : " (every random number " + number(xi) + ")";
            for (auto const& g : c.plugin.generate(params, std::vector<ProbePoint>(n, point), samples)) {
                ++cases;
                if (std::string problem = generatedProblem(g); !problem.empty()) return where + draw + ": " + problem;
            }
        }
        std::vector<Vec3> L;
        for (auto const& l : toward) L.push_back(frameOf.toWorld(l.v));
        // EvaluateSamplesAtIndex too: the consistency check, which compares it with EvaluateSample
        // at ordinary directions, is not run for an emitter, whose three sampling functions
        // must still answer "nothing here" within the arrays they are given.
        auto evaluated = c.plugin.evaluate(params, std::vector<ProbePoint>(L.size(), point), L);
        auto atIndex = c.plugin.evaluateAtIndex(params, point, L);
        for (auto const& [results, call] :
             {std::pair{&evaluated, "EvaluateSample"}, std::pair{&atIndex, "EvaluateSamplesAtIndex"}})
            for (size_t k = 0; k < results->size(); ++k) {
                ++cases;
                if (std::string problem = valueProblem((*results)[k], call); !problem.empty())
                    return where + ", the light " + toward[k].name + ": " + problem;
            }
        for (auto const& emitted : c.plugin.emission(params, {point}))
            if (!isFiniteColor(emitted)) return where + ": EmitLocal gave " + describe(emitted);
        return "";
    };
    for (std::string const& base : paramSets)
        for (SamplingMode const& mode : e.samplingModes) {
            std::string const params = e.withMode(base, mode);
            for (auto const& [frameOf, viewsThere] : {std::pair{&f, &views}, std::pair{&unturned, &exactViews}})
                for (Named const& V : *viewsThere)
                    for (Named const& T : tangents) {
                        std::string const where =
                            withParams(params) + ", the viewer " + V.name + " and " + T.name;
                        ProbePoint const point = frameOf->point(V.v, T.v);
                        if (std::string problem = probe(params, *frameOf, point, where, lights); !problem.empty())
                            return CheckOutcome::fail(problem);
                    }
            for (Named const& V : between) {
                std::string const where = withParams(params) + ", the viewer " + V.name;
                if (std::string problem = probe(params, f, f.bentPoint(V.v), where, between); !problem.empty())
                    return CheckOutcome::fail(problem);
            }
        }
    return CheckOutcome::pass("all " + std::to_string(cases) + " hard cases stay finite, with W never negative and valid pdfs",
                              std::to_string(paramSets.size()) + " parameter sets x " +
                                  std::to_string(e.samplingModes.size()) + " sampling modes x (" +
                                  std::to_string(views.size() + exactViews.size()) + " views x " +
                                  std::to_string(tangents.size()) +
                                  " tangents + " + std::to_string(between.size()) +
                                  " views about a bent shading normal)");
}

}  // namespace bxdflab
