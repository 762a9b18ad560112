// A procedural board of figured wood, in one function a student can read in
// one sitting. The WoodGrain pattern evaluates it at every shade point; the
// texture baker (tools/rixwoodtextures) writes it into the images the
// chapter-8 scene reads through PxrTexture, so both show the same board.
//
// The board is a plane cut from a log. The growth rings are cylinders around
// the log's axis, which runs along the board (along s) but dips slightly into
// it, so the plane cuts the rings in long stretched arcs ("cathedrals").
// "Figure" -- the ripples of curly maple -- is fibers that tilt in and out of
// the surface in bands across the board: where they tilt toward you the fiber
// highlight lights up, and the bands seem to move as you walk past.
#pragma once

#include <cmath>
#include <cstdint>

namespace woodgrain {

struct Params {
    float ringsPerUnit = 14.0f;     ///< growth rings per unit distance from the pith (in s, t units)
    float pithDepth = 0.6f;         ///< how far below the surface the log's axis runs
    float axisDip = 0.08f;          ///< radians the axis dips into the board along s
    float ringNoise = 0.35f;        ///< how irregular the rings are (in ring widths)
    float figureStrength = 0.2f;    ///< radians the fibers tilt out of the surface in the figure
    float figureFrequency = 12.0f;  ///< figure bands per unit of s
    float grainAngle = 0.0f;        ///< radians between the fibers and s, in the surface
    float earlyColor[3] = {0.62f, 0.40f, 0.20f};  ///< light, fast-grown spring wood
    float lateColor[3] = {0.36f, 0.18f, 0.07f};   ///< dark, dense summer wood
    float fiberTint[3] = {1.0f, 0.80f, 0.55f};    ///< fiber highlight colour relative to the diffuse colour
    float beta = 0.10f;             ///< highlight width (radians) in early wood; late wood is 40% narrower
};

struct Sample {
    float diffuse[3];     ///< diffuse colour
    float fiberColor[3];  ///< colour of the fiber highlight
    float fiberAxis[3];   ///< unit fiber direction in the tangent frame (x along s, z out of the surface)
    float beta;           ///< width of the fiber highlight
};

/// Smooth value noise in [-1, 1]: random values on the integer lattice, blended smoothly between them.
inline float valueNoise(float x, float y) {
    auto lattice = [](int32_t i, int32_t j) {
        uint32_t h = static_cast<uint32_t>(i) * 0x8da6b343u ^ static_cast<uint32_t>(j) * 0xd8163841u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        return static_cast<float>(h & 0xffffu) / 32767.5f - 1.0f;
    };
    float fx = std::floor(x), fy = std::floor(y);
    int32_t i = static_cast<int32_t>(fx), j = static_cast<int32_t>(fy);
    float a = x - fx, b = y - fy;
    a = a * a * (3.0f - 2.0f * a);  // smoothstep: no creases at lattice lines
    b = b * b * (3.0f - 2.0f * b);
    float bottom = lattice(i, j) + a * (lattice(i + 1, j) - lattice(i, j));
    float top = lattice(i, j + 1) + a * (lattice(i + 1, j + 1) - lattice(i, j + 1));
    return bottom + b * (top - bottom);
}

inline float smoothstep(float edge0, float edge1, float x) {
    float t = std::fmin(std::fmax((x - edge0) / (edge1 - edge0), 0.0f), 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

/// The wood at texture coordinates (s, t) of the board.
inline Sample evaluate(Params const& p, float s, float t) {
    // 1. Distance from the log's axis: the axis runs along s at depth pithDepth
    //    below the centre line t = 0.5, dipping by axisDip.
    float depth = p.pithDepth + s * std::sin(p.axisDip);
    float across = t - 0.5f;
    float radius = std::sqrt(depth * depth + across * across);

    // 2. Rings: the phase within a year's growth, made irregular by noise that
    //    varies slowly along the fibers and quickly across them.
    float phase = radius * p.ringsPerUnit + p.ringNoise * valueNoise(s * 3.0f, t * 9.0f);
    float year = phase - std::floor(phase);
    float late = smoothstep(0.55f, 0.8f, year) * (1.0f - smoothstep(0.92f, 1.0f, year));

    // 3. Colour: early wood to late wood, with fine streaks along the fibers.
    float streaks = 1.0f + 0.08f * valueNoise(s * 4.0f, t * 160.0f);
    Sample out;
    for (int c = 0; c < 3; ++c) {
        out.diffuse[c] = (p.earlyColor[c] + late * (p.lateColor[c] - p.earlyColor[c])) * streaks;
        out.fiberColor[c] = out.diffuse[c] * p.fiberTint[c];
    }

    // 4. Fibers: along s (turned by grainAngle and a slight wander), tilting out
    //    of the surface in bands across the board -- the figure.
    float wander = p.grainAngle + 0.05f * valueNoise(s * 2.0f, t * 5.0f);
    float bands = std::sin(6.2831853f * p.figureFrequency * s + 2.5f * valueNoise(s * 2.0f, t * 4.0f));
    float tilt = p.figureStrength * bands;
    out.fiberAxis[0] = std::cos(tilt) * std::cos(wander);
    out.fiberAxis[1] = std::cos(tilt) * std::sin(wander);
    out.fiberAxis[2] = std::sin(tilt);
    out.beta = p.beta * (1.0f - 0.4f * late);
    return out;
}

}  // namespace woodgrain
