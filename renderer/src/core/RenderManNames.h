// RenderMan's own plugins are named by family (PxrSurface, PxrDomeLight, LamaDiffuse, ...), and a
// scene that names one asks for something RenderMan ships rather than a plugin of its own. Some
// names in a scene's parameters carry a meaning of RenderMan's own too.
#pragma once

#include <string>

namespace bxdflab {

/// Whether `name` is one of RenderMan's own plugins: its Pxr and Lama families, told by their prefix.
inline bool isRenderMansOwnName(std::string const& name) {
    return name.rfind("Pxr", 0) == 0 || name.rfind("Lama", 0) == 0;
}

/// The texture name RenderMan's classic shaders give environment() and shadow() to trace rays instead
/// of reading a map ("texturename" "raytrace", "shadowname" "raytrace"): never a file.
inline constexpr char kRayTraced[] = "raytrace";

}  // namespace bxdflab
