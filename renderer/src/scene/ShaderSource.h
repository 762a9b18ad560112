// The parameter defaults a classic shader's source declares. A scene's own
// surface shader (wood.sl beside the RIB) is rendered as the standard shader it
// most resembles; the defaults it declares for the standard parameters (its Kd
// of 0.04, say) are what the scene was lit for, where the RIB does not give them.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace bxdflab {

/// A shader's parameter defaults by name: one value for a float, three for a colour.
using ShaderDefaults = std::map<std::string, std::vector<float>>;

/// A shader source a scene brings, and the defaults it declares (none when there is no file).
struct DeclaredDefaults {
    std::string file;  ///< the source file read, empty when none was found
    ShaderDefaults values;
    /// The colour parameter a shader that never reads Cs colours its surface with (brick.sl's
    /// brickcolor, LGbrushedmetal.sl's basecolor); empty when it reads Cs or has no such parameter.
    std::string ownColour;
};

/// The defaults of the surface shader `shader` declared in RenderMan Shading
/// Language source `text`, for parameters whose default is a plain number (a
/// float, or a grey colour) or a colour of three numbers ("color (1, 0.5, 0)",
/// "color \"rgb\" (1, 0.5, 0)").
/// Defaults written as expressions or of other types are left out; a source
/// without that shader gives none.
ShaderDefaults surfaceShaderDefaults(std::string const& text, std::string const& shader);

/// For a surface shader `shader` in `text` whose code never reads the surface colour Cs: its first
/// input colour parameter that is not a specular, highlight, reflection, environment, shadow or
/// opacity colour, which is then what colours it. Empty when the shader reads Cs or has none.
std::string ownSurfaceColour(std::string const& text, std::string const& shader);

}  // namespace bxdflab
