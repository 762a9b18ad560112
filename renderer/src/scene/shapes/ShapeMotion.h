// How a shape moves while the shutter is open (transformation motion blur).
//
// A shape is built where it stands when the shutter opens. Its motion is the
// transform that carries it from there to where it stands at each of a few
// evenly spaced moments of the shutter (the first is the identity), and in
// between the transforms are blended linearly. Ray times run from 0 (shutter
// open) to 1 (shutter close).
//
// Blending matrices is what Embree does with the vertices of a moving mesh
// (each vertex moves in a straight line from step to step), so a hit Embree
// finds and the shape's own answer at that hit agree.
//
// A shape whose points change (deformation motion blur) has its points at
// each step instead, any transformation motion folded in.
#pragma once

#include <algorithm>
#include <vector>

#include "core/Math.h"

namespace bxdflab {

/// Where shutter time `time` (0..1) falls among `count` (two or more) evenly spaced steps: the
/// step before it and how far past that step it lies (0..1).
inline void shutterStep(float time, size_t count, size_t& step, float& fraction) {
    float const position = glm::clamp(time, 0.0f, 1.0f) * static_cast<float>(count - 1);
    step = std::min(static_cast<size_t>(position), count - 2);
    fraction = position - static_cast<float>(step);
}

struct ShapeMotion {
    std::vector<Mat4> steps;  ///< at times 0, 1/(n-1), ..., 1 of the shutter; at least two

    /// The transform at shutter time `time` (0..1).
    Mat4 at(float time) const {
        size_t step;
        float f;
        shutterStep(time, steps.size(), step, f);
        return (1.0f - f) * steps[step] + f * steps[step + 1];
    }
    /// How fast the transform changes at `time`, per unit of shutter time (its derivative in time).
    Mat4 rate(float time) const {
        size_t step;
        float f;
        shutterStep(time, steps.size(), step, f);
        return static_cast<float>(steps.size() - 1) * (steps[step + 1] - steps[step]);
    }
};

/// Deformation: a shape's points at evenly spaced moments of the shutter, straight lines between.
struct PointSteps {
    std::vector<std::vector<Vec3>> steps;  ///< at least two, of the same length

    Vec3 at(size_t point, float time) const {
        size_t step;
        float f;
        shutterStep(time, steps.size(), step, f);
        return (1.0f - f) * steps[step][point] + f * steps[step + 1][point];
    }
    /// How fast a point moves at `time`, per unit of shutter time.
    Vec3 rate(size_t point, float time) const {
        size_t step;
        float f;
        shutterStep(time, steps.size(), step, f);
        return static_cast<float>(steps.size() - 1) * (steps[step + 1][point] - steps[step][point]);
    }
    std::vector<Vec3> all(float time) const {
        std::vector<Vec3> points(steps.front().size());
        for (size_t i = 0; i < points.size(); ++i) points[i] = at(i, time);
        return points;
    }
};

}  // namespace bxdflab
