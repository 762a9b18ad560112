// Each shape of the scene as Embree geometry: triangles, analytic quadrics as
// user geometry (intersected by the quadric's own exact code), curves and
// points as Embree's round curves and spheres, subdivision meshes as Embree's
// subdivision surfaces. Shapes whose exact surface only Embree knows (curves,
// subdivision limit surfaces) get an evaluator for shading.
#pragma once

#include <embree3/rtcore.h>

#include "scene/shapes/Shape.h"

namespace bxdflab {

/// Creates and commits the Embree geometry of `shape` (the caller attaches
/// and releases it).
RTCGeometry buildEmbreeGeometry(RTCDevice device, Shape const& shape);

}  // namespace bxdflab
