// smooth: with the boundary made smooth (the exercise's smoothParams) every
// sample goes one of two exact ways -- the mirror direction or the direction
// Snell's law refracts into -- from a lobe marked discrete, and
// EvaluateSample gives nothing (no direction chosen by anyone else can hit a
// single direction). The mean weight W / FPdf each way carries, which is all
// a renderer sees of a discrete lobe, equals the reference's within five
// standard errors (plus 0.2%), at views from outside and inside, one of them
// beyond the critical angle (total internal reflection), and again with the
// colours differing from point to point. Every sample's RPdf is the
// probability that a sample drawn from its L goes back to V, which is that
// sample's FPdf (the discrete form of reciprocity's RPdf(V, L) = FPdf(L, V)).
#include <cmath>
#include <optional>
#include <tuple>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

namespace {

/// The direction a local V refracts into through the plane z = 0 (V.z > 0 on
/// the side of index etaV; the result has z < 0). False on total internal reflection.
bool refracted(glm::dvec3 const& V, double etaV, double etaL, glm::dvec3& T) {
    double ratio = etaV / etaL;
    double sin2 = ratio * ratio * (1.0 - V.z * V.z);
    if (sin2 >= 1.0) return false;
    T = glm::dvec3(-ratio * V.x, -ratio * V.y, -std::sqrt(1.0 - sin2));
    return true;
}

/// Mean and standard error of the weight one way carries, per channel.
struct Way {
    double sum[3] = {0, 0, 0}, sumSq[3] = {0, 0, 0};
    long count = 0;
    float leastRPdf = 0.0f, greatestRPdf = 0.0f;  ///< the range of the samples' RPdf
    void add(RtColorRGB const& w, float rpdf) {
        leastRPdf = count == 0 ? rpdf : std::min(leastRPdf, rpdf);
        greatestRPdf = count == 0 ? rpdf : std::max(greatestRPdf, rpdf);
        ++count;
        for (int k = 0; k < 3; ++k) {
            sum[k] += w[k];
            sumSq[k] += static_cast<double>(w[k]) * w[k];
        }
    }
    double mean(int k, double n) const { return sum[k] / n; }
    double variance(int k, double n) const { return std::max(0.0, sumSq[k] / n - mean(k, n) * mean(k, n)) / n; }
    std::string describe(double n) const {
        return "(" + number(mean(0, n)) + ", " + number(mean(1, n)) + ", " + number(mean(2, n)) + ")";
    }
};

struct Sorted {
    Way mirror, refraction;
    std::string problem;  ///< the first sample that goes neither way, or is not discrete
};

Sorted sortSamples(std::vector<ProbeResult> const& drawn, Frame const& f, glm::dvec3 const& M, bool canRefract,
                   glm::dvec3 const& T) {
    Sorted s;
    long valid = 0;
    for (ProbeResult const& g : drawn) {
        if (!g.valid) continue;
        ++valid;
        glm::dvec3 L = glm::normalize(glm::dvec3(f.toLocal(g.L)));
        double weightScale = g.FPdf > 0.0f ? 1.0 / g.FPdf : 0.0;
        RtColorRGB w = g.W * static_cast<float>(weightScale);
        bool toMirror = glm::length(L - M) < 1e-3, toRefraction = canRefract && glm::length(L - T) < 1e-3;
        if (s.problem.empty() && !toMirror && !toRefraction)
            s.problem = "a sample goes toward " + describeDirection(Vec3(L)) + ", which is neither the mirror direction (" +
                        describeDirection(Vec3(M)) + ")" +
                        (canRefract ? " nor the refracted direction (" + describeDirection(Vec3(T)) + ")"
                                    : " nor a refracted one (this view is beyond the critical angle)");
        else if (s.problem.empty() && !g.discrete)
            s.problem = "a sample toward " + describeDirection(Vec3(L)) +
                        " comes from a lobe not marked discrete; an integrator would then weight it against light "
                        "samples (MIS) that can never find a single direction";
        if (toMirror) s.mirror.add(w, g.RPdf);
        if (toRefraction) s.refraction.add(w, g.RPdf);
    }
    if (valid == 0)
        s.problem = "none of " + std::to_string(drawn.size()) +
                    " samples was valid: a smooth boundary always sends light one way or the other";
    return s;
}

/// The FPdf of the samples drawn with the viewer at local `from` that go back
/// to local `to`: the probability of that way. Nothing when none of them does.
std::optional<float> probabilityOfWayBack(CheckContext& c, std::string const& params, Frame const& f,
                                          glm::dvec3 const& from, Vec3 const& to, uint32_t seed) {
    size_t const n = 4000;
    ProbePoint const point = f.point(Vec3(from));
    for (ProbeResult const& g : c.plugin.generate(params, std::vector<ProbePoint>(n, point), stratifiedSamples(n, seed)))
        if (g.valid && glm::length(glm::dvec3(f.toLocal(g.L)) - glm::dvec3(to)) < 1e-3) return g.FPdf;
    return std::nullopt;
}

/// Why the RPdf of `way`'s samples (toward local `L`, viewed from local V) is
/// wrong, or nothing: it must be the probability that a sample drawn from L
/// goes back to V.
std::string wrongReversePdf(CheckContext& c, std::string const& params, Frame const& f, Vec3 const& V,
                            glm::dvec3 const& L, Way const& way, std::string const& name, uint32_t seed) {
    if (way.count == 0) return "";
    std::optional<float> back = probabilityOfWayBack(c, params, f, L, V, seed);
    float const expected = back.value_or(0.0f);
    for (float rpdf : {way.leastRPdf, way.greatestRPdf})
        if (!close(rpdf, expected, 1e-3, 1e-6))
            return "the samples toward " + name + " have RPdf " +
                   (way.leastRPdf == way.greatestRPdf
                        ? number(way.leastRPdf)
                        : "from " + number(way.leastRPdf) + " to " + number(way.greatestRPdf)) +
                   ", but " +
                   (back ? "a sample drawn with the viewer there goes back with probability (FPdf) " + number(expected)
                         : std::string("no sample drawn with the viewer there goes back (RPdf 0)")) +
                   "; RPdf is the probability of sampling V from L, for every sample";
    return "";
}

}  // namespace

CheckOutcome checkSmooth(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (!e.transmits || e.smoothParams.empty())
        return CheckOutcome::notApplicable("not applicable: this model has no smooth (discrete) limit to check");
    // (No "not attempted" test on the rough parameters: the smooth part is an
    // exercise of its own, and this check must pass as soon as it is done.)
    Frame const& f = frame();
    size_t const n = 20000;
    double const dn = static_cast<double>(n);
    std::string details;
    int views = 0;
    // The colour set also with its colours differing from point to point, as a texture makes them (a
    // sample weighted by another point's colour shows only then); the index stays, so the directions
    // are known.
    for (auto const& [base, coloursVary] : {std::pair<std::string, bool>{e.params, false}, {e.colorParams, false},
                                            {e.colorParams, true}}) {
        std::string const smooth = base + " " + e.smoothParams;
        std::string const params = coloursVary ? varyingColours(smooth) : smooth;
        double const ior = e.ior(smooth);
        for (double theta : {0.0, 40.0, 75.0, 89.0, 150.0, 130.0}) {
            ++views;
            Vec3 const localV = direction(theta, 20);
            ProbePoint const point = f.point(localV);
            // The viewer's side: flip z so that V is above, as the formulas want.
            double const flip = localV.z < 0 ? -1.0 : 1.0;
            double const etaV = indexOfSide(ior, localV), etaL = localV.z < 0 ? 1.0 : ior;
            glm::dvec3 Vs(localV.x, localV.y, flip * localV.z), Ts(0.0);
            bool const canRefract = refracted(Vs, etaV, etaL, Ts);
            glm::dvec3 const M(-localV.x, -localV.y, localV.z), T(Ts.x, Ts.y, flip * Ts.z);
            std::string const where = "with the viewer at " + describeDirection(localV) + " (" +
                                      (localV.z < 0 ? "inside" : "outside") + "), " + withParams(base) +
                                      " made smooth by " + e.smoothParams +
                                      (coloursVary ? " (its colours varying from point to point, as a texture makes "
                                                     "them)"
                                                   : "");

            auto samples = stratifiedSamples(n, c.seed + 17u + static_cast<uint32_t>(views));
            Sorted mine = sortSamples(c.plugin.generate(params, std::vector<ProbePoint>(n, point), samples), f, M,
                                      canRefract, T);
            Sorted theirs = sortSamples(c.reference.generate(params, std::vector<ProbePoint>(n, point), samples), f, M,
                                        canRefract, T);
            if (!mine.problem.empty()) return CheckOutcome::fail(where + ": " + mine.problem, details);

            details += where + ": mirror " + mine.mirror.describe(dn) + " (the reference's " +
                       theirs.mirror.describe(dn) + "), refraction " + mine.refraction.describe(dn) +
                       " (the reference's " + theirs.refraction.describe(dn) + ")\n";
            for (auto const& [name, a, b] : {std::tuple<char const*, Way const*, Way const*>{"the mirror direction",
                                                                                            &mine.mirror, &theirs.mirror},
                                             {"the refracted direction", &mine.refraction, &theirs.refraction}})
                for (int k = 0; k < 3; ++k) {
                    double ma = a->mean(k, dn), mb = b->mean(k, dn);
                    double allowed = 5.0 * std::sqrt(a->variance(k, dn) + b->variance(k, dn)) +
                                     2e-3 * std::max(std::fabs(ma), std::fabs(mb)) + 1e-4;
                    if (!(std::fabs(ma - mb) <= allowed))
                        return CheckOutcome::fail(where + ": the light your samples carry toward " + name +
                                                      " (the mean of W / FPdf over all samples) is " + a->describe(dn) +
                                                      ", the reference's " + b->describe(dn) +
                                                      " (channel " + std::to_string(k) + " differs by " +
                                                      number(std::fabs(ma - mb)) + ", " + number(allowed) + " allowed)",
                                                  details);
                }

            for (auto const& [name, way, L] :
                 {std::tuple<char const*, Way const*, glm::dvec3>{"the mirror direction", &mine.mirror, M},
                  {"the refracted direction", &mine.refraction, T}}) {
                std::string wrong = wrongReversePdf(c, params, f, localV, L, *way, name,
                                                    c.seed + 101u + static_cast<uint32_t>(views));
                if (!wrong.empty()) return CheckOutcome::fail(where + ": " + wrong, details);
            }

            // A discrete lobe has no value at any given direction, not even its own.
            std::vector<Vec3> exact = {f.toWorld(Vec3(M))};
            if (canRefract) exact.push_back(f.toWorld(Vec3(T)));
            auto evaluated = c.plugin.evaluate(params, std::vector<ProbePoint>(exact.size(), point), exact);
            for (size_t k = 0; k < evaluated.size(); ++k)
                if (!evaluated[k].W.IsBlack() || evaluated[k].FPdf != 0.0f)
                    return CheckOutcome::fail(where + ": EvaluateSample toward the " +
                                                  (k == 0 ? "mirror" : "refracted") + " direction gives W " +
                                                  describe(evaluated[k].W) + " and FPdf " + number(evaluated[k].FPdf) +
                                                  "; a discrete lobe evaluates to nothing (light sampling cannot hit "
                                                  "a single direction; the integrator follows it through GenerateSample)",
                                              details);
        }
    }
    return CheckOutcome::pass("smooth glass: every sample goes the mirror or the refracted way, with the reference's "
                              "weights, at " + std::to_string(views) + " views",
                              details);
}

}  // namespace bxdflab
