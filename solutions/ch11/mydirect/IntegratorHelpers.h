// Small helpers both of chapter 11's integrators use.
#pragma once

#include <cmath>

#include "RixIntegrator.h"

/// Adds a contribution to a pixel, unless it is NaN or infinite (a Bxdf bug,
/// which the render stats then count instead).
inline void addContribution(RixIntegratorContext& ictx, RtColorRGB& radiance, RtColorRGB const& contribution) {
    if (std::isfinite(contribution.r) && std::isfinite(contribution.g) && std::isfinite(contribution.b))
        radiance += contribution;
    else
        ictx.CountNonFinite();
}

/// The integer parameter `name` of the Integrator's RIB line, or `fallback` when it is not set.
inline int readInt(RixParameterList const* params, const char* name, int fallback) {
    int id, value = fallback;
    if (params->GetParamId(RtUString(name), &id) == 0) params->EvalParam(id, -1, &value);
    return value;
}
