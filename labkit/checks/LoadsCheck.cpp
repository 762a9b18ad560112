// loads: the plugin loads, takes the exercise's parameters, builds a Bxdf,
// and declares lobes (or, for an emitter, none).
#include "checks/CheckSupport.h"

namespace bxdflab {

CheckOutcome checkLoads(CheckContext& c) {
    RixBXLobeTraits lobes = c.plugin.lobes(c.exercise.params);
    if (c.exercise.emitsOnly && lobes.HasAny())
        return CheckOutcome::fail("an emitter should declare no lobes (GetAggregateLobeTraits), but yours declares some");
    if (!c.exercise.emitsOnly && !lobes.HasAny())
        return CheckOutcome::fail(
            "your plugin declares no lobes (GetAggregateLobeTraits), so no integrator will ever ask it for light");
    return CheckOutcome::pass("the plugin loads and declares its lobes");
}

}  // namespace bxdflab
