// RixShading.h — parameters, parameter lists and the shading context.
//
// A shading context (RixShadingContext) is a BATCH of shade points that all use
// the same Bxdf instance: numPts points hit by rays in the same bucket. Every
// per-point quantity you read from it (position, normals, parameters) is an
// array of numPts entries, and every per-point answer you give back is too.
// Working on batches is what makes the renderer fast: one virtual call per
// batch instead of one per point.
#pragma once

#include <cstddef>
#include <cstdint>

#include "RiTypesHelper.h"
#include "RixInterfaces.h"

/// The type of a plugin parameter, as declared in the parameter table.
enum RixSCType {
    k_RixSCInvalidType = 0,
    k_RixSCFloat,
    k_RixSCInteger,
    k_RixSCColor,
    k_RixSCNormal,
    k_RixSCVector,
    k_RixSCPoint,
    k_RixSCString,
    k_RixSCFloat2,
    k_RixSCStructBegin,  ///< opens a struct in a parameter table (see RixSCParamInfo)
    k_RixSCStructEnd,    ///< closes it
};

/// What a parameter is for. Bxdf inputs read during scattering are
/// k_RixSCScatterInput; k_RixSCInput is the generic input. (This renderer
/// reads every input the same way; only k_RixSCOutput marks a pattern's output.)
enum RixSCAccess {
    k_RixSCInput = 0,
    k_RixSCOutput,
    k_RixSCScatterInput,
    k_RixSCPresenceInput,
    k_RixSCOpacityInput,
    k_RixSCInteriorInput,
    k_RixSCAnyInput,
    k_RixSCInvalidAccess,
};

class RixBxdf;

/// How much a value varies over a shading context.
enum RixSCDetail {
    k_RixSCInvalidDetail = 0,  ///< no such parameter / wrong type
    k_RixSCUniform,            ///< one value for every point (result points at 1 value)
    k_RixSCVarying,            ///< one value per point (result points at numPts values)
};

/// Where a parameter's value comes from (GetParamInfo): a plugin that does
/// something special when an input is left alone, or connected, asks first.
enum RixSCConnectionInfo {
    k_RixSCDefaultValue = 0,    ///< not given: EvalParam answers with your default
    k_RixSCParameterListValue,  ///< a value written on the RIB statement (uniform)
    k_RixSCNetworkValue,        ///< connected to a pattern's output (may vary per point)
    k_RixSCInvalidConnection,
};

/// Why the renderer calls a plugin's Synchronize.
enum RixSCSyncMsg {
    k_RixSCRenderBegin = 0,  ///< once, before the first pixel: look lobes up here
    k_RixSCRenderEnd,
    k_RixSCInstanceEdit,
    k_RixSCCancel,
    k_RixSCCheckpointRecover,
    k_RixSCCheckpointWrite,
    k_RixSCIncrementBarrier,
};

/// What the renderer wants from a shading context.
enum RixSCShadingMode {
    k_RixSCScatterQuery = 0,
    k_RixSCOpacityQuery,
    k_RixSCPresenceQuery,
    k_RixSCInteriorQuery,
    k_RixSCVolumeScatterQuery,
};

/// One row of a plugin's parameter table. The table is a static array that
/// ends with a default-constructed entry, e.g.
///
///   static RixSCParamInfo s_ptable[] = {
///       RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
///       RixSCParamInfo()   // end of table
///   };
///
/// A parameter's id is its row number; the renderer passes it to EvalParam.
struct RixSCParamInfo {
    RtUString name;
    RixSCType type = k_RixSCInvalidType;
    RixSCAccess access = k_RixSCInvalidAccess;
    int arraySize = -1;  ///< -1: not an array

    RixSCParamInfo() = default;  ///< the end-of-table marker
    RixSCParamInfo(RtUString paramName, RixSCType paramType,
                   RixSCAccess paramAccess = k_RixSCInput, int length = -1)
        : name(paramName), type(paramType), access(paramAccess), arraySize(length) {}
    /// A struct's first or last row (`marker` is k_RixSCStructBegin or
    /// k_RixSCStructEnd), as RenderMan's patterns declare a manifold:
    ///   RixSCParamInfo(RtUString("PxrManifold"), RtUString("result"), k_RixSCStructBegin, k_RixSCOutput),
    ///   RixSCParamInfo(RtUString("Q"), k_RixSCPoint, k_RixSCOutput),        // "result.Q"
    ///   RixSCParamInfo(RtUString("Qradius"), k_RixSCFloat, k_RixSCOutput),  // "result.Qradius"
    ///   RixSCParamInfo(RtUString("PxrManifold"), RtUString("result"), k_RixSCStructEnd, k_RixSCOutput),
    /// The rows between are its members; each keeps its own id. A RIB
    /// connection to the struct ("reference struct manifold" ["node:result"])
    /// joins its point member, the manifold's Q: here a manifold travels as
    /// that point (the struct's type name is not kept).
    RixSCParamInfo(RtUString structType, RtUString structName, RixSCType marker,
                   RixSCAccess paramAccess = k_RixSCInput)
        : name(structName), type(marker), access(paramAccess) {
        PIXAR_ARGUSED(structType);
    }
    bool IsEndOfTable() const { return type == k_RixSCInvalidType; }
};

/// The parameters written on a RIB statement (e.g. a Bxdf line), as handed to
/// CreateInstanceData. Values not written in the RIB are simply absent.
class RixParameterList {
public:
    virtual ~RixParameterList() = default;
    virtual int GetNumParams() const = 0;
    /// Finds a parameter by name: returns 0 and sets *id, or returns 1 when the
    /// RIB did not set it.
    virtual int GetParamId(RtUString name, int* id) const = 0;
    /// Name and type of parameter id; returns 0 on success.
    virtual int GetParamInfo(int id, RtUString* name, RixSCType* type) const = 0;
    /// RenderMan's form: the type of parameter `id`, where its value comes from
    /// and, for an array parameter, how many elements it has (-1 when it is not
    /// an array). Any pointer may be null. Returns 0, or 1 for an unknown id.
    ///   RixSCType type; RixSCConnectionInfo cinfo;
    ///   pList->GetParamInfo(k_roughness, &type, &cinfo);
    ///   if (cinfo == k_RixSCDefaultValue) ...
    int GetParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength = nullptr) const {
        return ParamInfo(id, type, cinfo, arrayLength);
    }

    // Each EvalParam copies the value of parameter `id` (element `arrayIndex`
    // of an array parameter; pass -1 or 0 for a single value) into *result and
    // returns k_RixSCUniform, or k_RixSCInvalidDetail when the id or type is wrong.
    RixSCDetail EvalParam(int id, int arrayIndex, RtFloat* result) const { return Eval(id, arrayIndex, k_RixSCFloat, result); }
    RixSCDetail EvalParam(int id, int arrayIndex, RtInt* result) const { return Eval(id, arrayIndex, k_RixSCInteger, result); }
    RixSCDetail EvalParam(int id, int arrayIndex, RtColorRGB* result) const { return Eval(id, arrayIndex, k_RixSCColor, result); }
    RixSCDetail EvalParam(int id, int arrayIndex, RtFloat3* result) const { return Eval(id, arrayIndex, k_RixSCVector, result); }
    RixSCDetail EvalParam(int id, int arrayIndex, RtUString* result) const { return Eval(id, arrayIndex, k_RixSCString, result); }

protected:
    virtual RixSCDetail Eval(int id, int arrayIndex, RixSCType wanted, void* result) const = 0;
    virtual int ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const = 0;
};

/// T itself, in a place where a template does not deduce it: GetPrimVar takes
/// T from its result's type, and converts the fill value to it.
template <typename T> struct RixNotDeduced { typedef T type; };

/// Per-context flags: what kind of rays led here.
struct RixSCTraits {
    bool eyePath = true;      ///< the path started at the camera
    bool lightPath = false;   ///< the path started at a light (not used by this renderer)
    bool primaryHit = true;   ///< these points were hit directly by camera rays
    bool missContext = false; ///< the rays hit nothing
};

/// A batch of shade points for one material. The renderer builds it; plugins
/// only read from it (and allocate from its memory pool).
class RixShadingContext {
public:
    /// The per-point geometric quantities ("builtins"). Each is computed the
    /// first time somebody asks for it and cached for the batch; a builtin no
    /// one asks for is never computed.
    enum BuiltinId {
        k_P = 0,     ///< RtPoint3: the shade point, world space
        k_Nn,        ///< RtNormal3: unit shading normal (interpolated; not flipped toward V)
        k_Ngn,       ///< RtNormal3: unit geometric normal (the surface's "outside")
        k_Tn,        ///< RtVector3: unit tangent along dPdu, orthogonal to Nn (zero if undefined)
        k_Vn,        ///< RtVector3: unit direction from P toward the viewer (ray origin)
        k_VLen,      ///< RtFloat: distance from the ray origin to P
        k_u,         ///< RtFloat: surface parameter u in [0,1]
        k_v,         ///< RtFloat: surface parameter v in [0,1]
        k_du,        ///< RtFloat: change in u across the ray's footprint
        k_dv,        ///< RtFloat: change in v across the ray's footprint
        k_dPdu,      ///< RtVector3: derivative of P with respect to u (not normalized)
        k_dPdv,      ///< RtVector3: derivative of P with respect to v (not normalized)
        k_s,         ///< RtFloat: texture coordinate s ("st" primvar, else u)
        k_t,         ///< RtFloat: texture coordinate t ("st" primvar, else v)
        k_biasR,     ///< RtFloat: how far along Ngn a ray leaving P starts so that it cannot hit
                     ///< the surface it leaves again (P's floating-point error; integrators use it)
        k_Po,        ///< RtPoint3: P before displacement (the same as P here: nothing is displaced)
        k_PRadius,   ///< RtFloat: radius of the ray's footprint at P (the pixel's spread at P's distance)
        k_Non,       ///< RtNormal3: unit shading normal before displacement (the same as Nn here)
        k_dPdtime,   ///< RtVector3: how fast P moves, per unit of time (the whole shutter is one unit;
                     ///< zero where nothing moves)
        k_time,      ///< RtFloat: when the point was seen: 0 as the shutter opens, 1 as it closes
        k_numBuiltins
    };

    int numPts = 0;          ///< number of shade points in this batch
    RixSCTraits scTraits;    ///< what kind of rays led here

    /// Whether the batch holds hits (it always does here: rays that miss
    /// every surface never make a shading context in this renderer).
    bool HasHits() const { return numPts > 0; }
    bool HasMisses() const { return false; }
    /// The Bxdf made for this context by BeginScatter (null before, or when it returned null).
    RixBxdf* GetBxdf() const { return m_bxdf; }
    /// Which Bxdf statement of the scene this context shades (its index among them).
    int Id() const { return m_id; }

    virtual ~RixShadingContext() = default;

    // GetBuiltinVar sets *result to an array of numPts values and returns 0,
    // or returns a non-zero value (and sets *result to nullptr) when the
    // builtin does not have the type asked for (e.g. k_P as RtFloat).
    int GetBuiltinVar(BuiltinId id, RtFloat const** result) const { return Builtin(id, k_RixSCFloat, (void const**)result); }
    int GetBuiltinVar(BuiltinId id, RtPoint3 const** result) const { return Builtin(id, k_RixSCPoint, (void const**)result); }
    int GetBuiltinVar(BuiltinId id, RtVector3 const** result) const { return Builtin(id, k_RixSCVector, (void const**)result); }
    int GetBuiltinVar(BuiltinId id, RtNormal3 const** result) const { return Builtin(id, k_RixSCNormal, (void const**)result); }
    int GetBuiltinVar(BuiltinId id, RtFloat3 const** result) const { return Builtin(id, k_RixSCVector, (void const**)result); }

    /// Evaluates parameter `id` of the current Bxdf instance.
    ///  * When the RIB (or a connected pattern) gives the parameter, *result
    ///    points at its value(s); otherwise *result = dflt (your default).
    ///  * Returns k_RixSCUniform (one value) or k_RixSCVarying (numPts values).
    ///  * With promoteToVarying = true, *result is ALWAYS an array of numPts
    ///    values (uniform values are copied out), so you can index it by point.
    ///  * arrayIndex selects an element of an array parameter; use -1 otherwise.
    template <typename T>
    RixSCDetail EvalParam(int id, int arrayIndex, T const** result, T const* dflt = nullptr,
                          bool promoteToVarying = false) const {
        return Param(id, arrayIndex, TypeOf(static_cast<T const*>(nullptr)), sizeof(T),
                     reinterpret_cast<void const**>(result), dflt, promoteToVarying);
    }
    template <typename T>
    RixSCDetail EvalParam(int id, int arrayIndex, T** result, T const* dflt = nullptr,
                          bool promoteToVarying = false) const {
        return EvalParam(id, arrayIndex, const_cast<T const**>(result), dflt, promoteToVarying);
    }
    /// How parameter `id` of the plugin being shaded is given (see
    /// RixSCConnectionInfo), e.g. whether a manifold input is connected before
    /// reading it. Any pointer may be null; returns 0, or 1 for an unknown id.
    int GetParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength = nullptr) const {
        return ParamInfo(id, type, cinfo, arrayLength);
    }

    /// A primitive variable ("primvar") of the geometry being shaded: a value
    /// the RIB attaches to a shape, like "color Cs" [1 0 0] on a Sphere, or a
    /// "varying float s" with one value per vertex of a mesh. *result becomes
    /// an array of numPts values, interpolated across the surface where the
    /// value varies. Returns k_RixSCInvalidDetail (and *result = nullptr) when
    /// no shape in this batch has a primvar of that name and type; else
    /// k_RixSCUniform (the same value at every point) or k_RixSCVarying.
    /// Points on a shape without it get zeros. `radius`, if you pass it,
    /// receives the filter radius of each value (0 here: no filtering).
    /// Every surface has "st" (as float[2]), as in RenderMan: its st primvar,
    /// its TextureCoordinates, or else its (u, v), the values of k_s and k_t.
    ///   RtColorRGB const* Cs;
    ///   if (sCtx->GetPrimVar(RtUString("Cs"), &Cs) != k_RixSCInvalidDetail) ...
    RixSCDetail GetPrimVar(RtUString const name, RtFloat const** result, RtFloat const** radius = nullptr) const {
        return PrimVar(name, k_RixSCFloat, (void const**)result, radius, nullptr);
    }
    RixSCDetail GetPrimVar(RtUString const name, RtFloat2 const** result, RtFloat const** radius = nullptr) const {
        return PrimVar(name, k_RixSCFloat2, (void const**)result, radius, nullptr);
    }
    RixSCDetail GetPrimVar(RtUString const name, RtColorRGB const** result, RtFloat const** radius = nullptr) const {
        return PrimVar(name, k_RixSCColor, (void const**)result, radius, nullptr);
    }
    RixSCDetail GetPrimVar(RtUString const name, RtFloat3 const** result, RtFloat const** radius = nullptr) const {
        return PrimVar(name, k_RixSCVector, (void const**)result, radius, nullptr);
    }
    RixSCDetail GetPrimVar(RtUString const name, RtPoint3 const** result, RtFloat const** radius = nullptr) const {
        return PrimVar(name, k_RixSCPoint, (void const**)result, radius, nullptr);
    }
    RixSCDetail GetPrimVar(RtUString const name, RtNormal3 const** result, RtFloat const** radius = nullptr) const {
        return PrimVar(name, k_RixSCNormal, (void const**)result, radius, nullptr);
    }
    /// RenderMan's form with a fill value: the same, except that points whose
    /// shape lacks the primvar get `fill`, and *result is numPts values even
    /// when no shape has it (then all `fill`, and the answer is
    /// k_RixSCInvalidDetail), so it can be read without a test:
    ///   RtFloat2 const* st;
    ///   sCtx->GetPrimVar(Rix::k_st, RtFloat2(0.0f, 0.0f), &st);  // RixPredefinedStrings.hpp
    template <typename T>
    RixSCDetail GetPrimVar(RtUString const name, typename RixNotDeduced<T>::type const& fill, T const** result,
                           RtFloat const** radius = nullptr) const {
        return PrimVar(name, PrimVarType(static_cast<T const*>(nullptr)), (void const**)result, radius, &fill);
    }

    /// How Transform treats the values it is given.
    enum TransformInterpretation {
        k_AsPoints = 0,  ///< positions: the whole transform
        k_AsVectors,     ///< directions: no translation
        k_AsNormals,     ///< normals: the inverse transpose, so they stay perpendicular to the surface
    };
    /// Moves numPts values from one coordinate system to another, in place:
    /// "current" and "world" (where shading happens here: the same space),
    /// "object" (each point's own shape), "camera", or a system the RIB named
    /// with CoordinateSystem or ScopedCoordinateSystem (Rix::k_object and the
    /// others in RixPredefinedStrings.hpp name them). `radius`, if given, is
    /// scaled as lengths are. Returns 0, or 1 (values untouched) for a space
    /// this renderer does not know ("screen", "NDC" and "raster" among them).
    ///   sCtx->Transform(RixShadingContext::k_AsPoints, Rix::k_current, Rix::k_object, Q, Qradius);
    int Transform(TransformInterpretation interpretation, RtUString const fromSpace, RtUString const toSpace,
                  RtFloat3* values, RtFloat* radius = nullptr) const {
        return TransformValues(interpretation, fromSpace, toSpace, values, radius);
    }

    /// Renderer services (RixMessages) while shading.
    virtual RixInterface* GetRixInterface(RixInterfaceId id) const = 0;

    /// Memory that lives exactly as long as this shading context: use it for
    /// your RixBxdf object and its per-point arrays. Never free it yourself.
    ///
    ///   RixShadingContext::Allocator pool(sCtx);
    ///   void* mem = pool.AllocForBxdf<MyBxdf>(1);
    ///   MyBxdf* bxdf = new (mem) MyBxdf(sCtx, this, ...);
    class Allocator {
    public:
        explicit Allocator(RixShadingContext const* ctx) : m_ctx(ctx) {}
        template <typename T> T* AllocForBxdf(int count) { return AllocFor<T>(count); }
        template <typename T> T* AllocForPattern(int count) { return AllocFor<T>(count); }
        template <typename T> T* AllocFor(int count) {
            return static_cast<T*>(m_ctx->Allocate(sizeof(T) * static_cast<size_t>(count), alignof(T)));
        }

    private:
        RixShadingContext const* m_ctx;
    };

protected:
    RixBxdf* m_bxdf = nullptr;  ///< set by the renderer after BeginScatter
    int m_id = 0;               ///< set by the renderer
    /// Renderer side: returns 0 and the array, or non-zero on a type mismatch.
    virtual int Builtin(BuiltinId id, RixSCType wanted, void const** result) const = 0;
    virtual RixSCDetail Param(int id, int arrayIndex, RixSCType wanted, size_t elementSize,
                              void const** result, void const* dflt, bool promote) const = 0;
    virtual void* Allocate(size_t bytes, size_t alignment) const = 0;
    virtual int ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const = 0;
    /// Renderer side of GetPrimVar: numPts values of the type asked for, or
    /// k_RixSCInvalidDetail; `fill` (null: zeros) where a shape lacks it.
    virtual RixSCDetail PrimVar(RtUString const name, RixSCType wanted, void const** result,
                                RtFloat const** radius, void const* fill) const = 0;
    /// Renderer side of Transform.
    virtual int TransformValues(TransformInterpretation interpretation, RtUString const fromSpace,
                                RtUString const toSpace, RtFloat3* values, RtFloat* radius) const = 0;

private:
    static RixSCType TypeOf(RtFloat const*) { return k_RixSCFloat; }
    static RixSCType TypeOf(RtInt const*) { return k_RixSCInteger; }
    static RixSCType TypeOf(RtColorRGB const*) { return k_RixSCColor; }
    static RixSCType TypeOf(RtNormal3 const*) { return k_RixSCNormal; }
    static RixSCType TypeOf(RtVector3 const*) { return k_RixSCVector; }
    static RixSCType TypeOf(RtPoint3 const*) { return k_RixSCPoint; }
    static RixSCType TypeOf(RtFloat3 const*) { return k_RixSCVector; }
    static RixSCType TypeOf(RtUString const*) { return k_RixSCString; }
    static RixSCType TypeOf(RtFloat2 const*) { return k_RixSCFloat2; }
    // The types a primvar can have (one to three floats).
    static RixSCType PrimVarType(RtFloat const*) { return k_RixSCFloat; }
    static RixSCType PrimVarType(RtFloat2 const*) { return k_RixSCFloat2; }
    static RixSCType PrimVarType(RtColorRGB const*) { return k_RixSCColor; }
    static RixSCType PrimVarType(RtFloat3 const*) { return k_RixSCVector; }
    static RixSCType PrimVarType(RtVector3 const*) { return k_RixSCVector; }
    static RixSCType PrimVarType(RtPoint3 const*) { return k_RixSCPoint; }
    static RixSCType PrimVarType(RtNormal3 const*) { return k_RixSCNormal; }
};

/// Base class of every shading plugin factory (Bxdfs derive RixBxdfFactory).
class RixShadingPlugin {
public:
    /// Per-instance data made in CreateInstanceData and handed back to
    /// BeginScatter as `instanceData`. If you allocate it, set freefunc so the
    /// renderer can release it when the render ends.
    /// What an interactive session must refresh after an edit (RenderMan reads
    /// InstanceData::synchronizeHints; this renderer has no interactive edits).
    enum SynchronizeHints : uint32_t { k_None = 0u, k_All = 0xFFFFFFFFu };
    struct InstanceData {
        void* data = nullptr;
        size_t datalen = 0;
        void (*freefunc)(void*) = nullptr;
        /// RenderMan lets an instance replace GetParamTable's table with its own.
        /// Not here: leave it null (a plugin that sets it is refused, with that reason).
        RixSCParamInfo const* paramtable = nullptr;
        uint32_t synchronizeHints = k_None;  ///< kept for RenderMan code; nothing reads it here
    };

    virtual ~RixShadingPlugin() = default;
    /// Called once after the shared object is loaded. Return 0 on success.
    virtual int Init(RixContext& ctx, RtUString const pluginPath) = 0;
    /// Called once before the shared object is unloaded.
    virtual void Finalize(RixContext& ctx) = 0;
    /// The parameter table (see RixSCParamInfo). Must stay valid until Finalize.
    virtual RixSCParamInfo const* GetParamTable() = 0;
    /// Render-wide events; k_RixSCRenderBegin comes once before shading starts.
    virtual void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg,
                             RixParameterList const* parameterList) = 0;
    /// Called once per RIB statement that uses this plugin (`handle` is its name).
    virtual void CreateInstanceData(RixContext& ctx, RtUString const handle,
                                    RixParameterList const* parameterList, InstanceData* instance) {
        PIXAR_ARGUSED(ctx); PIXAR_ARGUSED(handle); PIXAR_ARGUSED(parameterList); PIXAR_ARGUSED(instance);
    }
    /// RenderMan calls this when an interactive session edits an instance's
    /// parameters. This renderer has no interactive edits: it is never called.
    virtual void SynchronizeInstanceData(RixContext& ctx, RtUString const handle, RixParameterList const* parameterList,
                                         uint32_t editHints, InstanceData* instance) {
        PIXAR_ARGUSED(ctx); PIXAR_ARGUSED(handle); PIXAR_ARGUSED(parameterList); PIXAR_ARGUSED(editHints);
        PIXAR_ARGUSED(instance);
    }
};
