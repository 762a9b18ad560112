// RixRNG.h — random numbers for a batch of shade points.
//
// Monte Carlo estimates converge faster when the random numbers are spread
// evenly (stratified) rather than clumped. RixRNG therefore hands out
// low-discrepancy numbers: for each pixel, the samples 0..N-1 of one "draw"
// cover [0,1)^2 evenly (a scrambled Sobol' sequence, Owen-scrambled per pixel
// and per draw after Burley, "Practical Hash-based Owen Scrambling", 2020).
//
// Every shade point carries its own sample context (pixel, sample index, and
// how many draws it has made), so the numbers a point receives do not depend
// on which batch it is in or on the thread count: renders are deterministic.
//
// Each call to DrawSamples1D/2D consumes one "draw" for every point of the
// batch; DrawSample1D(i)/DrawSample2D(i) do the same for point i only, and
// give exactly the value the batch call would have given that point.
#pragma once

#include <cstdint>

#include "RiTypesHelper.h"

class RixRNG {
public:
    /// Where in its sequence one shade point is.
    /// The first two fields are RenderMan's: `patternid` picks the sample
    /// pattern (here a hash of the pixel and the render seed, which decorrelates
    /// pixels) and `sampleid` the sample within it (the pixel's sample number).
    struct SampleCtx {
        uint32_t patternid = 0;  ///< which pattern: hash of pixel and render seed
        uint32_t sampleid = 0;   ///< which of the pattern's samples this is
        uint32_t draw = 0;       ///< how many draws this point has made so far (this renderer's)
        /// Testing hook: when >= 0, every draw returns this value in every
        /// dimension (how the test suite feeds a Bxdf xi = 0 or xi = 1 - 2^-24).
        float fixedValue = -1.0f;
        /// With fixedValue: when >= 0, the second coordinate of 2-D draws (else fixedValue).
        float fixedValue2 = -1.0f;
        /// With fixedValue: when >= 0, what 1-D draws return (else fixedValue), so
        /// a test can choose a lobe with one number and a direction with another.
        float fixedValue1D = -1.0f;

        /// The same sample in a new, independent pattern (RenderMan's way to give
        /// a sub-computation numbers of its own): `scramble` tells domains apart.
        SampleCtx NewDomain(uint32_t scramble) const {
            SampleCtx c = *this;
            c.patternid = Hash(patternid ^ Hash(scramble + 0x2545f491u));
            c.draw = 0;
            return c;
        }
    };

    RixRNG(SampleCtx* contexts, int numPoints) : numPts(numPoints), sampleCtxArray(contexts) {}

    int numPts;
    SampleCtx* sampleCtxArray;

    /// One number in [0,1) per shade point: xi[0..numPts-1].
    void DrawSamples1D(float* xi) {
        for (int i = 0; i < numPts; ++i) xi[i] = DrawSample1D(i);
    }
    /// One 2-D sample in [0,1)^2 per shade point: xi[0..numPts-1].
    void DrawSamples2D(RtFloat2* xi) {
        for (int i = 0; i < numPts; ++i) xi[i] = DrawSample2D(i);
    }
    float DrawSample1D(int i) { return Sample1D(sampleCtxArray[i]); }
    RtFloat2 DrawSample2D(int i) { return Sample2D(sampleCtxArray[i]); }

    /// The next 2-D sample of a context (advances its draw counter).
    static RtFloat2 Sample2D(SampleCtx& ctx) {
        if (ctx.fixedValue >= 0.0f)
            return RtFloat2(ctx.fixedValue, ctx.fixedValue2 >= 0.0f ? ctx.fixedValue2 : ctx.fixedValue);
        uint32_t seed = Hash(ctx.patternid ^ Hash(ctx.draw++ * 0x9e3779b9u + 0x632be5abu));
        uint32_t index = NestedUniformScramble(ctx.sampleid, seed);
        // Sobol's first dimension is the index with its bits reversed, and the
        // scramble reverses them again: the two reversals cancel.
        uint32_t x = ReverseBits(LaineKarrasPermutation(index, Hash(seed ^ 0xa511e9b3u)));
        uint32_t y = ReverseBits(LaineKarrasPermutation(SobolSecondDimensionReversed(index), Hash(seed ^ 0x63d83595u)));
        return RtFloat2(ToUnitFloat(x), ToUnitFloat(y));
    }
    /// The next 1-D sample of a context (advances its draw counter).
    static float Sample1D(SampleCtx& ctx) {
        if (ctx.fixedValue >= 0.0f) return ctx.fixedValue1D >= 0.0f ? ctx.fixedValue1D : ctx.fixedValue;
        uint32_t seed = Hash(ctx.patternid ^ Hash(ctx.draw++ * 0x9e3779b9u + 0x1b873593u));
        uint32_t index = NestedUniformScramble(ctx.sampleid, seed);
        return ToUnitFloat(ReverseBits(LaineKarrasPermutation(index, Hash(seed ^ 0x85ebca6bu))));
    }

    /// A well-mixed 32-bit hash (lowbias32 by C. Wellons).
    static uint32_t Hash(uint32_t x) {
        x ^= x >> 16; x *= 0x7feb352du;
        x ^= x >> 15; x *= 0x846ca68bu;
        x ^= x >> 16;
        return x;
    }

private:
    static uint32_t ReverseBits(uint32_t v) {
        v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
        v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
        v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
        v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
        return (v >> 16) | (v << 16);
    }
    // The second dimension of Sobol's sequence, with its bits reversed (bit k
    // of the result is the k-th binary digit after the point). Its direction
    // numbers are the rows of Pascal's triangle mod 2 (1, 11, 101, 1111, ...),
    // and C(j, k) is odd exactly when the bits of k are a subset of those of j
    // (Lucas): so bit k is the XOR of the index bits j that contain k. Five
    // shift-and-XOR steps sum over those supersets, one bit position at a time,
    // with no loop over the index's bits and no branch.
    static uint32_t SobolSecondDimensionReversed(uint32_t index) {
        index ^= (index >> 1) & 0x55555555u;
        index ^= (index >> 2) & 0x33333333u;
        index ^= (index >> 4) & 0x0f0f0f0fu;
        index ^= (index >> 8) & 0x00ff00ffu;
        index ^= (index >> 16) & 0x0000ffffu;
        return index;
    }
    // Laine-Karras style permutation: an Owen scramble of a bit-reversed value.
    static uint32_t LaineKarrasPermutation(uint32_t x, uint32_t seed) {
        x += seed;
        x ^= x * 0x6c50b47cu;
        x ^= x * 0xb82f1e52u;
        x ^= x * 0xc7afe638u;
        x ^= x * 0x8d22f6e6u;
        return x;
    }
    static uint32_t NestedUniformScramble(uint32_t x, uint32_t seed) {
        return ReverseBits(LaineKarrasPermutation(ReverseBits(x), seed));
    }
    // Keeps the top 24 bits so the result is exactly representable and < 1.
    static float ToUnitFloat(uint32_t bits) { return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f); }
};
