// RiTypesHelper.h — the small value types every Rix plugin uses.
//
// Scalars (RtFloat, RtInt), interned strings (RtUString), 2- and 3-component
// vectors (RtFloat2, RtPoint3, RtVector3, RtNormal3), colours (RtColorRGB) and
// a 4x4 matrix. They are plain value types with no heap memory, so arrays of
// them can live in the shading context's memory pool.
//
// Conventions used throughout the course:
//   * Directions handed to a Bxdf point AWAY from the surface (Vn toward the
//     viewer, Ln toward the light).
//   * Colours are linear RGB radiometric quantities (never gamma encoded).
#pragma once

#include <alloca.h>
#include <atomic>
#include <cassert>  // RenderMan's headers bring assert; plugin code uses it without including it
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>  // with <string>: what plugin code often uses without including it
#include <string>

#include "prmanapi.h"  // _PRMANAPI_VERSION_MAJOR_ and the others, as in RenderMan

typedef float RtFloat;
typedef int RtInt;
typedef void* RtPointer;
typedef const char* RtConstString;

#define PRMAN_INLINE inline
/// Marks an argument as deliberately unused (silences -Wunused-parameter).
#define PIXAR_ARGUSED(x) (void)(x)
/// Makes a symbol visible outside the shared object (plugins are built with
/// hidden visibility, so only the create/destroy entry points are exported).
#define PRMANEXPORT __attribute__((visibility("default")))
/// A parameter the plugin may ignore (the create functions' `hint`): no
/// -Wunused-parameter warning whether or not it writes PIXAR_ARGUSED(hint).
#define RIX_MAYBE_UNUSED __attribute__((unused))

/// The version of the plugin ABI these headers describe (class layouts and
/// virtual tables). Every plugin that includes them exports it, and the
/// renderer refuses a plugin built against another version with a message
/// instead of crashing inside it. tests/check_api_version.py fails when the
/// headers change without this number being reconsidered.
#define RIX_PLUGIN_API_VERSION 13
extern "C" PRMANEXPORT __attribute__((weak)) int RixPluginApiVersion() { return RIX_PLUGIN_API_VERSION; }
/// Stack memory that vanishes when the calling function returns. Use it for
/// small per-call scratch arrays (e.g. random numbers for one batch).
#define RixAlloca(nbytes) alloca(nbytes)

static constexpr float F_PI = 3.14159265358979323846f;
static constexpr float F_INVPI = 1.0f / F_PI;
static constexpr float F_TWOPI = 2.0f * F_PI;
static constexpr float F_INVTWOPI = 1.0f / F_TWOPI;
static constexpr float F_FOURPI = 4.0f * F_PI;
static constexpr float F_INVFOURPI = 1.0f / F_FOURPI;
static constexpr float F_PIDIV2 = 0.5f * F_PI;
static constexpr float F_PIDIV4 = 0.25f * F_PI;

/// An interned, immutable string. Two RtUStrings made from equal text compare
/// equal; copying one is as cheap as copying a pointer.
class RtUString {
public:
    RtUString() = default;
    RtUString(const char* text) : m_str(text ? Intern(text) : nullptr) {}
    /// The characters, or an empty string for a default-constructed RtUString.
    const char* CStr() const { return m_str ? m_str : ""; }
    bool Empty() const { return m_str == nullptr || m_str[0] == '\0'; }
    /// True when it holds text: `if (name && ...)` as RenderMan's plugins write it.
    explicit operator bool() const { return !Empty(); }
    bool operator==(RtUString const& o) const {
        return m_str == o.m_str || std::strcmp(CStr(), o.CStr()) == 0;
    }
    bool operator!=(RtUString const& o) const { return !(*this == o); }
    bool operator<(RtUString const& o) const { return std::strcmp(CStr(), o.CStr()) < 0; }

private:
    // One table per loaded module, freed when the module unloads; equality
    // falls back to strcmp, so strings interned by different plugins still
    // compare equal. The table is 256 lists that only ever grow at the front,
    // so a lookup takes no lock and the header needs no <mutex> or hash
    // containers: every plugin source includes it, and those headers would
    // make each one compile 20% slower.
    static const char* Intern(const char* text) {
        struct Entry {
            Entry* next;
            std::string text;
        };
        struct Table {
            std::atomic<Entry*> lists[256];
            ~Table() {
                for (auto& list : lists)
                    for (Entry* e = list.load(); e;) {
                        Entry* next = e->next;
                        delete e;
                        e = next;
                    }
            }
        };
        static Table table;
        unsigned hash = 2166136261u;  // FNV-1a
        for (const char* c = text; *c; ++c) hash = (hash ^ static_cast<unsigned char>(*c)) * 16777619u;
        std::atomic<Entry*>& list = table.lists[hash % 256];
        Entry* head = list.load(std::memory_order_acquire);
        Entry* added = nullptr;
        for (;;) {
            for (Entry* e = head; e; e = e->next)
                if (e->text == text) {
                    delete added;  // another thread added the same text first
                    return e->text.c_str();
                }
            if (!added) added = new Entry{nullptr, text};
            added->next = head;
            // On failure head becomes the list's new front, and the search runs again.
            if (list.compare_exchange_weak(head, added, std::memory_order_acq_rel, std::memory_order_acquire))
                return added->text.c_str();
        }
    }
    const char* m_str = nullptr;
};

/// Two floats, e.g. a 2-D random sample. Index with [0] and [1].
struct RtFloat2 {
    float x = 0.0f, y = 0.0f;
    RtFloat2() = default;
    RtFloat2(float a, float b) : x(a), y(b) {}
    float& operator[](int i) { return i == 0 ? x : y; }
    float operator[](int i) const { return i == 0 ? x : y; }
};

/// Three floats with the vector algebra the course uses. RtPoint3, RtVector3
/// and RtNormal3 derive from it and convert freely into one another.
class RtFloat3 {
public:
    float x = 0.0f, y = 0.0f, z = 0.0f;

    RtFloat3() = default;
    RtFloat3(float a, float b, float c) : x(a), y(b), z(c) {}
    explicit RtFloat3(float s) : x(s), y(s), z(s) {}

    float& operator[](int i) { return (&x)[i]; }
    float operator[](int i) const { return (&x)[i]; }

    float Dot(RtFloat3 const& o) const { return x * o.x + y * o.y + z * o.z; }
    RtFloat3 Cross(RtFloat3 const& o) const {
        return RtFloat3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }
    float LengthSq() const { return Dot(*this); }
    float Length() const { return std::sqrt(LengthSq()); }
    /// Scales this vector to unit length in place. A zero vector stays zero
    /// (rather than becoming NaN), so callers can test for degeneracy.
    void Normalize() {
        float len = Length();
        if (len > 0.0f) {
            float inv = 1.0f / len;
            x *= inv; y *= inv; z *= inv;
        }
    }
    bool IsZero() const { return x == 0.0f && y == 0.0f && z == 0.0f; }
    /// For a unit vector: two more unit vectors s and t such that (s, t, this)
    /// is a right-handed orthonormal basis, e.g. a tangent frame around a
    /// normal to sample directions in. Continuous wherever this vector points
    /// (Duff et al., "Building an Orthonormal Basis, Revisited", 2017).
    void CreateOrthonormalBasis(RtFloat3& s, RtFloat3& t) const {
        float const sign = std::copysign(1.0f, z);
        float const a = -1.0f / (sign + z);
        float const b = x * y * a;
        s = RtFloat3(1.0f + sign * x * x * a, sign * b, -sign * x);
        t = RtFloat3(b, sign + y * y * a, -y);
    }

    RtFloat3& operator+=(RtFloat3 const& o) { x += o.x; y += o.y; z += o.z; return *this; }
    RtFloat3& operator-=(RtFloat3 const& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    RtFloat3& operator*=(float s) { x *= s; y *= s; z *= s; return *this; }
    RtFloat3& operator/=(float s) { return *this *= (1.0f / s); }
};

PRMAN_INLINE RtFloat3 operator+(RtFloat3 const& a, RtFloat3 const& b) { return RtFloat3(a.x + b.x, a.y + b.y, a.z + b.z); }
PRMAN_INLINE RtFloat3 operator-(RtFloat3 const& a, RtFloat3 const& b) { return RtFloat3(a.x - b.x, a.y - b.y, a.z - b.z); }
PRMAN_INLINE RtFloat3 operator-(RtFloat3 const& a) { return RtFloat3(-a.x, -a.y, -a.z); }
PRMAN_INLINE RtFloat3 operator*(RtFloat3 const& a, float s) { return RtFloat3(a.x * s, a.y * s, a.z * s); }
PRMAN_INLINE RtFloat3 operator*(float s, RtFloat3 const& a) { return a * s; }
PRMAN_INLINE RtFloat3 operator/(RtFloat3 const& a, float s) { return a * (1.0f / s); }
PRMAN_INLINE float Dot(RtFloat3 const& a, RtFloat3 const& b) { return a.Dot(b); }
PRMAN_INLINE RtFloat3 Cross(RtFloat3 const& a, RtFloat3 const& b) { return a.Cross(b); }
/// A unit-length copy of v (zero stays zero).
PRMAN_INLINE RtFloat3 Normalize(RtFloat3 v) { v.Normalize(); return v; }

/// A position in space.
class RtPoint3 : public RtFloat3 {
public:
    using RtFloat3::RtFloat3;
    RtPoint3() = default;
    RtPoint3(RtFloat3 const& v) : RtFloat3(v) {}
};

/// A direction (or displacement) in space.
class RtVector3 : public RtFloat3 {
public:
    using RtFloat3::RtFloat3;
    RtVector3() = default;
    RtVector3(RtFloat3 const& v) : RtFloat3(v) {}
};

/// A surface normal. The renderer hands out unit normals (Nn, Ngn).
class RtNormal3 : public RtFloat3 {
public:
    using RtFloat3::RtFloat3;
    RtNormal3() = default;
    RtNormal3(RtFloat3 const& v) : RtFloat3(v) {}
};

/// Linear RGB colour. Arithmetic is per channel, so `albedo * lightColor`
/// multiplies red by red, green by green and blue by blue.
class RtColorRGB {
public:
    float r = 0.0f, g = 0.0f, b = 0.0f;

    RtColorRGB() = default;
    RtColorRGB(float red, float green, float blue) : r(red), g(green), b(blue) {}
    explicit RtColorRGB(float grey) : r(grey), g(grey), b(grey) {}

    float& operator[](int i) { return (&r)[i]; }
    float operator[](int i) const { return (&r)[i]; }

    void Zero() { r = g = b = 0.0f; }
    bool IsBlack() const { return r == 0.0f && g == 0.0f && b == 0.0f; }
    float ChannelAvg() const { return (r + g + b) * (1.0f / 3.0f); }
    float ChannelMax() const { return std::fmax(r, std::fmax(g, b)); }
    /// Rec. 709 luminance of a linear colour.
    float Luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

    RtColorRGB& operator+=(RtColorRGB const& o) { r += o.r; g += o.g; b += o.b; return *this; }
    RtColorRGB& operator-=(RtColorRGB const& o) { r -= o.r; g -= o.g; b -= o.b; return *this; }
    RtColorRGB& operator*=(RtColorRGB const& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    RtColorRGB& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
    RtColorRGB& operator/=(float s) { return *this *= (1.0f / s); }
};

PRMAN_INLINE RtColorRGB operator+(RtColorRGB const& a, RtColorRGB const& b) { return RtColorRGB(a.r + b.r, a.g + b.g, a.b + b.b); }
PRMAN_INLINE RtColorRGB operator-(RtColorRGB const& a, RtColorRGB const& b) { return RtColorRGB(a.r - b.r, a.g - b.g, a.b - b.b); }
PRMAN_INLINE RtColorRGB operator*(RtColorRGB const& a, RtColorRGB const& b) { return RtColorRGB(a.r * b.r, a.g * b.g, a.b * b.b); }
PRMAN_INLINE RtColorRGB operator*(RtColorRGB const& a, float s) { return RtColorRGB(a.r * s, a.g * s, a.b * s); }
PRMAN_INLINE RtColorRGB operator*(float s, RtColorRGB const& a) { return a * s; }
PRMAN_INLINE RtColorRGB operator/(RtColorRGB const& a, float s) { return a * (1.0f / s); }

/// A 4x4 matrix in RenderMan's row-vector convention: a point p transforms as
/// p * M, so the translation sits in m[3][0..2].
struct RtMatrix4x4 {
    float m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    RtPoint3 TransformPoint(RtPoint3 const& p) const {
        float x = p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0] + m[3][0];
        float y = p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1] + m[3][1];
        float z = p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2] + m[3][2];
        float w = p.x * m[0][3] + p.y * m[1][3] + p.z * m[2][3] + m[3][3];
        return w != 1.0f && w != 0.0f ? RtPoint3(x / w, y / w, z / w) : RtPoint3(x, y, z);
    }
    RtVector3 TransformVector(RtVector3 const& v) const {
        return RtVector3(v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0],
                         v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
                         v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]);
    }
};

/// RenderMan's per-object bounce limits (RIB: Attribute "trace"), as a surface sets them;
/// integrators ask for them with RixIntegratorContext::TraceDepth.
struct RixTraceDepth {
    int maxDiffuse = 1;   ///< "int maxdiffusedepth": diffuse bounces a path may take on from here
    int maxSpecular = 2;  ///< "int maxspeculardepth": specular (glossy, mirror, refraction) bounces
};
