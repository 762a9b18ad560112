// Motion blocks read into motion: a transform that changes over time, and the
// evenly spaced moments of the shutter at which shapes are given to the ray
// tracer (see shapes/ShapeMotion.h).
#pragma once

#include <memory>
#include <vector>

#include "core/Math.h"
#include "scene/shapes/ShapeMotion.h"

namespace bxdflab {

/// Where `time` falls among increasing `times`: the two around it and how far from the first to the
/// second it lies (the first or last twice, and 0, before the first or after the last).
void bracket(std::vector<float> const& times, float time, size_t& earlier, size_t& later, float& fraction);

/// The current transform of a motion block: its value at each of the block's times (increasing),
/// straight lines between, the first and last values before and after.
struct TransformPath {
    std::vector<float> times;
    std::vector<Mat4> transforms;
    Mat4 at(float time) const;
};

/// The moments of the shutter [open, close] at which something whose motion is known at `times`
/// is given to the ray tracer: evenly spaced, as Embree wants them, and close enough together to
/// follow the nearest two of `times` (at least two moments, at most 33).
std::vector<float> shutterSteps(std::vector<float> const& times, float open, float close);

/// How a shape built where `path` places it at shutter open moves while the shutter is open; null
/// when it does not (a shutter that opens and closes at once, or a path that stays put).
std::shared_ptr<ShapeMotion const> shapeMotion(TransformPath const& path, float open, float close);

}  // namespace bxdflab
