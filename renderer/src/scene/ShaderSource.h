// What a classic shader's source tells about it. A scene's own surface shader
// (wood.sl beside the RIB) is rendered as the standard shader it most resembles;
// the defaults it declares for the standard parameters (its Kd of 0.04, say) are
// what the scene was lit for, where the RIB does not give them; a source that never
// reads Cs names the colour it shows instead, and one that reads no light shows its
// colour unlit.
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
    /// The colour parameters a shader that never reads Cs colours its surface with, to be averaged
    /// (brick.sl's brickcolor; a checker's color1 and color2); none when it reads Cs or has no such one.
    std::vector<std::string> ownColours;
    /// Whether the source is known to read no light (no diffuse(), illuminance, Cl, ... and no #include
    /// that could hide one): with a colour of its own, its surface shows it whatever lights it.
    bool unlit = false;
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
/// opacity colour, which is then what colours it; when that one is one of a numbered or lettered
/// set (color1, color2; colorA, colorB), the whole set, whose average colours it. Empty when the
/// shader reads Cs or has none.
std::vector<std::string> ownSurfaceColours(std::string const& text, std::string const& shader);

/// Whether shading language source `text` reads no light: it calls none of the functions that gather
/// light (diffuse, specular, phong, ambient, illuminance, trace, ...) nor reads the light colour Cl, and
/// includes no other file, and it sets a colour Ci. False when it might read light or sets none.
bool readsNoLight(std::string const& text);

}  // namespace bxdflab
