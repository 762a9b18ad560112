// PxrDefault: what a scene gets when it names no integrator. A light at the
// camera (a headlight, no falloff, strength pi so a white diffuse surface
// facing the camera shows radiance 1) lights whatever the camera sees, so
// scenes without lights are visible too.
#include "common/DirectLighting.h"

using namespace bxdflab;

RIX_INTEGRATORCREATE {
    PIXAR_ARGUSED(params);
    PIXAR_ARGUSED(messages);
    return new DirectLighting(1, 0, true);
}

RIX_INTEGRATORDESTROY { delete integrator; }
