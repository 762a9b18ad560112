// Each shape of the scene as Embree geometry: triangles, analytic quadrics as
// user geometry (intersected by the quadric's own exact code; a whole sphere,
// when asked, by Embree's own sphere primitive), curves and points as Embree's
// round curves and spheres, subdivision meshes as Embree's
// subdivision surfaces. Shapes whose exact surface only Embree knows (curves,
// subdivision limit surfaces) get an evaluator for shading.
#pragma once

#include <embree3/rtcore.h>

#include "scene/shapes/Shape.h"

namespace bxdflab {

/// Creates and commits the Embree geometry of `shape` (the caller attaches
/// and releases it). embreeSpheres: whole spheres as Embree's sphere primitive.
RTCGeometry buildEmbreeGeometry(RTCDevice device, Shape const& shape, bool embreeSpheres);

}  // namespace bxdflab
