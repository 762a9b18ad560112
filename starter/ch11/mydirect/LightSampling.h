// Next-event estimation for a batch of shade points: sample every light,
// ask the Bxdf how much of that light it reflects toward the viewer, trace a
// shadow ray, and weight the sample against Bxdf sampling (MIS). Written in
// exercise 1 for mydirect; mypath (exercise 2) calls it at every vertex.
#pragma once

#include "IntegratorHelpers.h"
#include "RixBxdfScratch.h"

/// Adds to radiance[i] the light reflected toward the viewer straight from the
/// lights, from numLightSamples samples per light, MIS-weighted (power
/// heuristic) against the numBxdfSamples Bxdf samples the caller takes, and
/// multiplied by throughput[i] (the path's weight so far; 1 for mydirect).
void sampleLights(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                  int numLightSamples, int numBxdfSamples, RtColorRGB const* throughput, RtColorRGB* radiance);
