// What the noise patterns (PxrFractal, PxrWorley, PxrVoronoise) share: a hash of
// integer lattice points, from which each lattice cell draws its own
// pseudo-random numbers, and where on the surface the noise is laid.
#pragma once

#include <cstdint>

#include "PatternHelpers.h"

namespace stockpatterns {

/// A well-mixed 32-bit hash of a lattice point.
inline uint32_t latticeHash(int x, int y, int z) {
    uint32_t h = static_cast<uint32_t>(x) * 0x8da6b343u ^ static_cast<uint32_t>(y) * 0xd8163841u ^
                 static_cast<uint32_t>(z) * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    return h ^ (h >> 16);
}

/// The next of a cell's numbers after `h`, and `h` as a number in [0, 1).
inline uint32_t nextHash(uint32_t h) { return latticeHash(static_cast<int>(h), 0x2545f491, 0x9e3779b9); }
inline float unitOf(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

/// The weighted average over `octaves` of noise(p f), f starting at `frequency` and growing `lacunarity`
/// times per octave, each octave weighing `gain` times the one before (a fractal sum); `whenNone` for no octave.
template <typename Noise>
float octaveAverage(RtPoint3 const& p, int octaves, float frequency, float lacunarity, float gain, float whenNone,
                    Noise const& noise) {
    float sum = 0.0f, norm = 0.0f, amplitude = 1.0f, f = frequency;
    for (int k = 0; k < octaves; ++k) {
        sum += amplitude * noise(RtPoint3(p.x * f, p.y * f, p.z * f));
        norm += amplitude;
        amplitude *= gain;
        f *= lacunarity;
    }
    return norm > 0.0f ? sum / norm : whenNone;
}

/// Where a noise pattern is evaluated: (s, t, 0) of its manifold (texture coordinates unless one is connected
/// at `manifoldId`; the manifold's third coordinate is a filter width, not a place), or with surfacePosition 1
/// the point's position in object space, so that the noise stays on the object as it moves.
inline RtPoint3 const* noisePositions(RixShadingContext const* sCtx, int surfacePosition, int manifoldId) {
    if (surfacePosition == 1) return objectPositions(sCtx);
    RtPoint3 const* manifold = manifoldOf(sCtx, manifoldId);
    RixShadingContext::Allocator pool(sCtx);
    RtPoint3* flat = pool.AllocFor<RtPoint3>(sCtx->numPts);
    for (int i = 0; i < sCtx->numPts; ++i) flat[i] = RtPoint3(manifold[i].x, manifold[i].y, 0.0f);
    return flat;
}

}  // namespace stockpatterns
