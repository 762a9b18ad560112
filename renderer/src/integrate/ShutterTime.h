// When a path sees the scene: each camera path, and each light subpath, is
// given one moment of the shutter (0 as it opens, 1 as it closes), and every
// ray along the path keeps it. Over many paths the moments cover the shutter
// evenly, which is what blurs what moves.
#pragma once

#include "RixRNG.h"

namespace bxdflab {

/// The path's moment, from numbers of its own (a domain of the sample's sequence that nothing else
/// draws from), so that a scene without motion draws exactly the numbers it drew before.
inline float shutterTime(RixRNG::SampleCtx const& sample) {
    constexpr uint32_t kShutterDomain = 0x74696d65u;  // "time"
    RixRNG::SampleCtx own = sample.NewDomain(kShutterDomain);
    return RixRNG::Sample1D(own);
}

}  // namespace bxdflab
