#pragma once

#include <memory>
#include <string>

#include "parse/ParamList.h"
#include "scene/lights/Light.h"

namespace bxdflab {

/// The light a `Light "<type>" ...` statement describes, or nullptr when the
/// type is not one this renderer knows. `baseDir` resolves relative image paths;
/// problems with the light's image that do not stop the render are warned about.
std::unique_ptr<Light> makeLight(std::string const& type, ParamList const& params, Mat4 const& lightToWorld,
                                 std::string const& baseDir, SourceLocation const& where, Diagnostics& diagnostics);

}  // namespace bxdflab
