// Typed parameter lists, as written after a RIB request:
//   "float intensity" [150]  "color lightColor" [1 0.9 0.8]  "string name" "x"
// Each parameter keeps its declaration (type, storage class, array length),
// its values and where it was written, so that errors and warnings point at it.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostics.h"
#include "core/Error.h"
#include "core/Math.h"

namespace bxdflab {

/// A whole number an int can hold (converting any other value to int is undefined behaviour).
inline bool isWholeInt(double d) { return d == std::floor(d) && d >= -2147483648.0 && d <= 2147483647.0; }

/// Unknown: a name written without a type that is not a standard one (its
/// values are kept as they were written; using it is an error, skipping it a
/// warning), or a type this renderer does not model ("struct").
enum class ParamType { Float, Int, Color, Point, Vector, Normal, HPoint, String, Matrix, Unknown };

/// How many floats one element of a type takes (1 for float/int/string).
int componentsOf(ParamType type);
const char* paramTypeName(ParamType type);

/// A parsed declaration such as "uniform float[2] st".
struct ParamDecl {
    std::string name;
    ParamType type = ParamType::Float;
    std::string storageClass;  ///< constant, uniform, varying, vertex, facevarying (or empty)
    int arraySize = 1;         ///< elements per item, e.g. 2 for float[2]
    bool reference = false;    ///< "reference color x" ["node:output"]: connected to a pattern's output
    bool untyped = false;      ///< written without a type (and not a standard name)
    bool standard = false;     ///< typed by the built-in table of standard names, not by the RIB
};

/// How many numbers a colour is written with and how they become RGB, as
/// ColorSamples sets it (RGB itself until it does).
struct ColorSamples {
    size_t count = 3;
    /// `count` rows of 3 (RI's nRGB): RGB is the sum of number i times row i. Empty: the numbers are RGB.
    std::vector<float> toRGB;
    /// The RGB of one colour written as `count` numbers.
    Vec3 rgb(float const* numbers) const;
};

/// Declarations known without a Declare request (parse/StandardDeclarations),
/// plus whatever the RIB declared. Parses "class type name" strings. Holds the
/// ColorSamples in force too: like a declaration, it says how values are read.
class Declarations {
public:
    Declarations();
    void declare(std::string const& name, std::string const& declaration, SourceLocation const& where);
    /// Parses a parameter token like "float fov" or "fov". A name that is
    /// neither typed, declared nor standard comes back untyped (type Unknown);
    /// a malformed declaration throws.
    ParamDecl resolve(std::string const& token, SourceLocation const& where) const;
    void setColorSamples(ColorSamples samples) { m_colorSamples = std::move(samples); }
    ColorSamples const& colorSamples() const { return m_colorSamples; }

private:
    static bool parseDeclaration(std::string const& text, ParamDecl& out, std::string& error);
    std::map<std::string, ParamDecl> m_known;
    ColorSamples m_colorSamples;
};

struct Param {
    ParamDecl decl;
    std::vector<float> floats;  ///< Float, Int (as floats too), Color, Point, Vector, Normal
    std::vector<int> ints;      ///< Int
    std::vector<std::string> strings;
    /// A reference's value where its pattern cannot be loaded (a stand-in material
    /// sets it to what the original would have had); empty: the plugin's default.
    std::vector<float> fallback;
    SourceLocation location;
    mutable bool used = false;

    std::string const& name() const { return decl.name; }
    /// Number of items (values / components).
    size_t count() const;
    /// The first value as text (a number as a stream prints it), as variables
    /// hold values; nothing when there is no value.
    std::optional<std::string> firstValueText() const;
};

/// A "color <name>" parameter made by the renderer itself (no source location).
Param colorParam(std::string const& name, Vec3 const& value);
/// A name RenderMan keeps for its own bookkeeping: a leading "__", as in
/// "__materialid", "__instanceid", "__category" and "__islight". Exporters add
/// them to any node; they carry no value a plugin reads, so nobody warns about them.
inline bool isRendererMetadata(std::string const& name) { return name.rfind("__", 0) == 0; }

/// Gives a parameter written without a type the type its owner declares for it
/// (a plugin's table, a light's parameters), with `arraySize` elements per item;
/// false, leaving it as it was, when its values cannot be of that type (strings
/// for numbers, a count that is no multiple of the type's size, a fraction for an int).
bool giveType(Param& param, ParamType type, int arraySize = 1);

/// A "float <name>" parameter made by the renderer itself.
Param floatParam(std::string const& name, float value);
/// An "int <name>" parameter made by the renderer itself.
Param intParam(std::string const& name, int value);
/// A "string <name>" parameter made by the renderer itself.
Param stringParam(std::string const& name, std::string const& value);

class ParamList {
public:
    void add(Param param);
    /// Types each parameter written without a type that `declared` names, as giveType
    /// does; a located RibError (naming `owner`) when its values cannot be that type.
    void typeUntyped(std::map<std::string, ParamType> const& declared, std::string const& owner);
    bool has(std::string const& name) const { return find(name) != nullptr; }
    /// The parameter, or nullptr when absent. Only looks: see take().
    Param const* find(std::string const& name) const;
    /// The parameter, marked used (so it is not reported as skipped); nullptr
    /// when absent. Throws a located RibError when it was written without a
    /// type and is not standard: whoever takes a value needs its type.
    Param const* take(std::string const& name) const;
    /// Marks a parameter as read and deliberately ignored, if present.
    void ignore(std::string const& name) const;
    /// Notes a name a reader asked for and did not find (take() does this
    /// itself): warnUnused offers it for a parameter spelled nearly so.
    void noteAbsent(std::string const& name) const;
    std::vector<Param> const& all() const { return m_params; }
    bool empty() const { return m_params.empty(); }

    // Typed single-value getters: return the default when absent, throw a
    // located RibError when present with the wrong type or count.
    float getFloat(std::string const& name, float dflt) const;
    int getInt(std::string const& name, int dflt) const;
    Vec3 getColor(std::string const& name, Vec3 const& dflt) const;
    Vec3 getVector(std::string const& name, Vec3 const& dflt) const;
    std::string getString(std::string const& name, std::string const& dflt) const;
    /// Array getters (any length); absent gives an empty vector.
    std::vector<float> const* getFloats(std::string const& name, ParamType type) const;
    std::vector<int> const* getInts(std::string const& name) const;
    /// A shape's normals ("N"): a normal or vector array, three numbers each. Null when absent or
    /// connected to a pattern (a reference, which no shape reads).
    std::vector<float> const* getNormals(std::string const& name) const;

    /// Warns once for each parameter that no one read (typos, unsupported
    /// options), and for each untyped one that is not a standard name; a
    /// name a reader asked for in vain that is a letter or two away is
    /// offered ("did you mean ...?").
    /// With `firstTime`, a parameter is warned about only when firstTime(its name)
    /// is true (a caller that warns once per name across many statements).
    void warnUnused(Diagnostics& diagnostics, std::string const& owner,
                    std::function<bool(std::string const& name)> const& firstTime = {}) const;

private:
    Param const& expect(Param const& p, std::initializer_list<ParamType> types, size_t count) const;
    std::vector<Param> m_params;
    mutable std::vector<std::string> m_absentAskedFor;
};

}  // namespace bxdflab
