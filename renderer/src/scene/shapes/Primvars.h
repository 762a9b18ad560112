// Primitive variables: values a RIB attaches to a shape ("color Cs",
// "uniform float id", "varying float[2] uv2", ...), read by plugins with
// RixShadingContext::GetPrimVar at any shading point.
//
// Storage follows how each value varies over the shape:
//   constant  one value for the whole shape
//   uniform   one value per face (per triangle of a mesh, once triangulated)
//   varying   values at the shape's vertices or corners, interpolated
// Polygon meshes store varying values per mesh vertex (their triangulation
// already made one vertex per corner, so vertex, varying and facevarying all
// end up there); quadrics take four corner values, in (u, v) order; patch
// meshes and subdivision surfaces keep the values as given and read them at
// the hit (PatchPrimvars, SubdivisionSurface).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "parse/ParamList.h"

namespace bxdflab {

/// Values laid out over a surface's parameters (a patch mesh's corners or
/// control points, a subdivision surface's points or face corners): read at a
/// hit, not blended from a tessellation's vertices.
class ParametricValues {
public:
    virtual ~ParametricValues() = default;
    /// The value on face `face` (a subdivision face; patch meshes ignore it) at
    /// its parameters (u, v): `out` receives the primvar's components.
    virtual void at(unsigned face, float u, float v, float* out) const = 0;
};

struct Primvar {
    enum class Detail { Constant, Uniform, Varying };
    std::string name;
    ParamType type = ParamType::Float;
    int components = 1;  ///< floats per value: 1, 2 (float[2]), 3 (color, point, vector, normal)
    Detail detail = Detail::Constant;
    std::vector<float> values;
    std::shared_ptr<ParametricValues const> parametric;  ///< when set, the values (`values` is then empty)
};

class PrimvarSet {
public:
    Primvar const* find(std::string const& name) const {
        for (auto const& p : m_vars)
            if (p.name == name) return &p;
        return nullptr;
    }
    void add(Primvar var) { m_vars.push_back(std::move(var)); }
    bool empty() const { return m_vars.empty(); }
    std::vector<Primvar> const& all() const { return m_vars; }
    std::vector<Primvar>& all() { return m_vars; }

private:
    std::vector<Primvar> m_vars;
};

/// The names a renderer gives meaning to (geometry, not primvars a plugin reads).
bool isGeometryParameter(std::string const& name);

/// Floats per value of a parameter used as a primvar, or 0 when it cannot be one (strings, matrices).
int primvarComponents(Param const& param);

/// The texture coordinates a shape's parametric primvars give: "st", or "s"
/// and "t" read together; nothing when it has neither.
std::shared_ptr<ParametricValues const> parametricTextureCoordinates(PrimvarSet const& primvars);

/// The primvars in a shape's parameter list that are not geometry: those with
/// one value (constant, or uniform over a shape of one face), and, when
/// `corners` is not 0, varying or vertex ones with a value per corner (a
/// quadric's four). With `elements` not 0, values given once per element
/// (a particle of Points) are kept as uniform, one per primitive. Meshes find
/// the rest themselves (MeshBuilders). Marks them used.
PrimvarSet shapePrimvars(ParamList const& params, size_t corners = 0, size_t elements = 0);

/// The value of `var` at parameters (u, v) of a four-corner shape, or its
/// constant value: `out` receives var.components floats.
void primvarAtCorners(Primvar const& var, float u, float v, float* out);

}  // namespace bxdflab
