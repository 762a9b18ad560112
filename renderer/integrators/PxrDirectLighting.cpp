// PxrDirectLighting: direct lighting with light and Bxdf sampling combined
// by multiple importance sampling (see common/DirectLighting.cpp).
//   int numLightSamples [1]  samples per light per camera sample
//   int numBxdfSamples  [1]  Bxdf samples per camera sample
#include "common/DirectLighting.h"
#include "common/Params.h"

using namespace bxdflab;

RIX_INTEGRATORCREATE {
    int lightSamples, bxdfSamples;
    if (!ReadInt(params, messages, "numLightSamples", 1, 0, 4096, lightSamples) ||
        !ReadInt(params, messages, "numBxdfSamples", 1, 0, 4096, bxdfSamples))
        return nullptr;
    return new DirectLighting(lightSamples, bxdfSamples, false);
}

RIX_INTEGRATORDESTROY { delete integrator; }
