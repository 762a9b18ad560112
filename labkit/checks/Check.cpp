#include "checks/Check.h"

#include <map>
#include <stdexcept>

namespace bxdflab {

std::vector<std::string> const& checkNames() {
    static std::vector<std::string> const names = {"loads",       "values", "chi2",   "jacobian", "consistency",
                                                   "reciprocity", "energy", "hardcases", "smooth"};
    return names;
}

std::string const& checkHint(std::string const& check) {
    static std::map<std::string, std::string> const hints = {
        {"loads", "Does the plugin build, export its create/destroy pair, return a parameter table and declare its lobes?"},
        {"values", "Compare your W = f cos(theta_L) and pdfs with the chapter's formulas; rixlobe plots your lobe."},
        {"chi2", "Your samples do not go where your FPdf says: look at rixwarp's picture for this plugin and sampling mode."},
        {"jacobian", "At fixed random numbers, your FPdf is not the density your mapping produces: recheck its derivation."},
        {"consistency", "GenerateSample, EvaluateSample and EvaluateSamplesAtIndex should agree, and each point read "
                        "only its own entries ([i] or [index], never [0]): render ch07/validate.rib with your plugin."},
        {"reciprocity", "f(V, L) should equal f(L, V), and RPdf should be the pdf of sampling V from L."},
        {"energy", "The surface reflects more (or less) light than the reference: check the normalisation constants."},
        {"hardcases", "Guard grazing angles, directions between the shading and the geometric normal's horizons, "
                      "zero tangents, extreme parameters and xi = 0 against NaN, infinity, a negative W and negative "
                      "pdfs; mark a sample invalid instead of returning garbage."},
        {"smooth", "With roughness 0 a sample must be exactly the mirror or the refracted direction (Snell's law), from a "
                   "discrete lobe, weighted by Fresnel and by (eta_V / eta_L)^2 for the light that crosses; its RPdf is the "
                   "probability of the way back, the same choice seen from L."},
        {"renders", "Diff your render with the solution's (rixdiff --heatmap); the heatmap shows where they disagree."},
        {"noise", "Render the scene at the same spp with your plugin and the solution's and compare the noise: a "
                  "missing sampling strategy or MIS weight shows where one of them is weak."},
    };
    static std::string const none;
    auto found = hints.find(check);
    return found == hints.end() ? none : found->second;
}

std::string const& crashHint() {
    static std::string const hint =
        "Memory read or written that the plugin does not own. While checking, every array and object the shading "
        "context gives out, and the stack, hold 0xFF bytes until written, so a member or local read before it is set "
        "(a GetBuiltinVar or EvalParam that fills another variable than the one read) crashes here; so does an index "
        "past numPts, or past the end of an array RixAlloca made too small. `addr2line -f -C -e <plugin> <offsets>` "
        "names the functions and lines of a plugin built with -g.";
    return hint;
}

CheckOutcome runCheck(std::string const& check, CheckContext& context) {
    std::string const reason = context.exercise.notApplicableReason(check);
    if (!reason.empty()) return CheckOutcome::notApplicable("not applicable: " + reason);
    if (context.exercise.kind == "sampling") return checkSamplingFunctions(check, context);
    if (check == "loads") return checkLoads(context);
    if (check == "values") return checkValues(context);
    if (check == "chi2") return checkChiSquared(context);
    if (check == "jacobian") return checkJacobian(context);
    if (check == "consistency") return checkConsistency(context);
    if (check == "reciprocity") return checkReciprocity(context);
    if (check == "energy") return checkEnergy(context);
    if (check == "hardcases") return checkHardCases(context);
    if (check == "smooth") return checkSmooth(context);
    throw std::invalid_argument("no check named \"" + check + "\"");
}

}  // namespace bxdflab
