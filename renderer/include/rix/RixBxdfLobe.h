// RixBxdfLobe.h — lobes: naming what part of a Bxdf a sample came from.
//
// A Bxdf is a sum of LOBES (e.g. a diffuse lobe plus a specular highlight).
// Integrators need to know which lobe produced a sample (for light path
// expressions, per-lobe outputs, and to decide whether a path may continue),
// so every sample is tagged with a RixBXLobeSampled, and every weight is stored
// per lobe in a RixBXLobeWeights.
//
//   RixBXLobeSampled  one specific lobe (a sample's tag)
//   RixBXLobeTraits   a SET of lobes (what a Bxdf has, what an integrator wants)
//   RixBXLobeWeights  per-lobe arrays of weights W = f * |cos(theta_L)|
#pragma once

#include <cstdint>
#include <cstring>

#include "RiTypesHelper.h"
#include "RixInterfaces.h"
#include "RixShading.h"

static constexpr int k_RixBXMaxNumDiffuseLobes = 4;
static constexpr int k_RixBXMaxNumSpecularLobes = 8;
static constexpr int k_RixBXMaxNumUserLobes = 12;

/// One lobe, as chosen by GenerateSample. "Diffuse" means neither specular nor
/// user. An INVALID sample ends the path (use it when no direction could be
/// generated, e.g. below the horizon); a valid sample with zero weight does not.
/// A default-made lobe is invalid; one made from its kind (as RixBXLookupLobeByName
/// makes yours) is valid, as in RenderMan, so that the common idiom
///     lobeSampled[i].SetValid(false);           // first: nothing generated yet
///     ... lobeSampled[i] = s_diffuseLobe;       // on success: valid, and tagged
/// works; calling SetValid(true) after the assignment, as the chapters do, says it aloud.
class RixBXLobeSampled {
public:
    RixBXLobeSampled() = default;
    RixBXLobeSampled(bool discrete, bool specular, bool reflect, bool user,
                     unsigned char lpeId, unsigned char lobeId)
        : m_valid(true), m_discrete(discrete), m_specular(specular), m_reflect(reflect),
          m_user(user), m_lpeId(lpeId), m_lobeId(lobeId) {}

    void SetValid(bool valid) { m_valid = valid; }
    bool GetValid() const { return m_valid; }
    bool GetDiscrete() const { return m_discrete; }
    bool GetSpecular() const { return m_specular && !m_user; }
    bool GetDiffuse() const { return !m_specular && !m_user; }
    bool GetUser() const { return m_user; }
    bool GetReflect() const { return m_reflect; }
    bool GetTransmit() const { return !m_reflect; }
    unsigned char GetLpeId() const { return m_lpeId; }
    unsigned char GetLobeId() const { return m_lobeId; }
    /// The same lobe: the same kind and light path expression id (as RenderMan
    /// tells lobes apart), and direction.
    bool operator==(RixBXLobeSampled const& o) const {
        return m_specular == o.m_specular && m_user == o.m_user && m_lpeId == o.m_lpeId && m_reflect == o.m_reflect;
    }

private:
    bool m_valid = false;
    bool m_discrete = false;
    bool m_specular = false;
    bool m_reflect = true;
    bool m_user = false;
    unsigned char m_lpeId = 0;
    unsigned char m_lobeId = 0;
};

/// A set of lobes plus the directions (reflect / transmit) they cover.
/// Combine sets with & and |; HasAny() asks "is any lobe left?".
class RixBXLobeTraits {
public:
    RixBXLobeTraits() = default;
    /// The set holding exactly the given lobe (its kind and direction; whether a
    /// sample is valid is said of the set written to lobesEvaluated, with SetValid).
    /// Lobes are told apart by kind and light path expression id, as in RenderMan.
    explicit RixBXLobeTraits(RixBXLobeSampled lobe) {
        int bit = lobe.GetUser() ? k_userShift + lobe.GetLpeId() % k_RixBXMaxNumUserLobes
                  : lobe.GetSpecular() ? k_specularShift + lobe.GetLpeId() % k_RixBXMaxNumSpecularLobes
                                       : lobe.GetLpeId() % k_RixBXMaxNumDiffuseLobes;
        m_bits = (1u << bit) | (lobe.GetReflect() ? k_reflectBit : k_transmitBit);
    }
    /// Every lobe in both directions (what a general integrator asks for).
    static RixBXLobeTraits All() { RixBXLobeTraits t; t.SetAll(); return t; }

    bool HasAny() const { return (m_bits & k_lobeMask) != 0 && (m_bits & (k_reflectBit | k_transmitBit)) != 0; }
    void SetNone() { m_bits = 0; }
    void SetAll() { m_bits = k_lobeMask | k_reflectBit | k_transmitBit; }
    void SetValid(bool valid) { m_bits = valid ? (m_bits | k_validBit) : (m_bits & ~k_validBit); }
    bool GetValid() const { return (m_bits & k_validBit) != 0; }
    bool GetReflect() const { return (m_bits & k_reflectBit) != 0; }
    bool GetTransmit() const { return (m_bits & k_transmitBit) != 0; }
    bool HasDiffuse() const { return (m_bits & k_diffuseMask) != 0; }
    bool HasSpecular() const { return (m_bits & k_specularMask) != 0; }
    bool HasUser() const { return (m_bits & k_userMask) != 0; }
    uint32_t GetBits() const { return m_bits; }
    /// The set whose GetBits() is `bits` (for passing a set between processes).
    static RixBXLobeTraits FromBits(uint32_t bits) { RixBXLobeTraits t; t.m_bits = bits; return t; }

    RixBXLobeTraits operator&(RixBXLobeTraits const& o) const { return FromBits(m_bits & o.m_bits); }
    RixBXLobeTraits operator|(RixBXLobeTraits const& o) const { return FromBits(m_bits | o.m_bits); }
    RixBXLobeTraits& operator&=(RixBXLobeTraits const& o) { m_bits &= o.m_bits; return *this; }
    RixBXLobeTraits& operator|=(RixBXLobeTraits const& o) { m_bits |= o.m_bits; return *this; }
    bool operator==(RixBXLobeTraits const& o) const { return m_bits == o.m_bits; }
    bool operator!=(RixBXLobeTraits const& o) const { return m_bits != o.m_bits; }

private:
    static constexpr int k_specularShift = k_RixBXMaxNumDiffuseLobes;                     // bits 4..11
    static constexpr int k_userShift = k_specularShift + k_RixBXMaxNumSpecularLobes;       // bits 12..23
    static constexpr uint32_t k_diffuseMask = (1u << k_specularShift) - 1u;
    static constexpr uint32_t k_specularMask = ((1u << k_userShift) - 1u) & ~k_diffuseMask;
    static constexpr uint32_t k_userMask = ((1u << (k_userShift + k_RixBXMaxNumUserLobes)) - 1u) & ~((1u << k_userShift) - 1u);
    static constexpr uint32_t k_lobeMask = k_diffuseMask | k_specularMask | k_userMask;
    static constexpr uint32_t k_reflectBit = 1u << 24;
    static constexpr uint32_t k_transmitBit = 1u << 25;
    static constexpr uint32_t k_validBit = 1u << 26;
    uint32_t m_bits = 0;
};

/// Looks a lobe up by name ("Diffuse", "Specular", "Clearcoat", ...): the
/// renderer gives each name of a kind its own light path expression id, and
/// that id is what tells lobes apart: two lobes of one Bxdf need two names
/// (a second specular lobe named "Specular" again would share the first's
/// weights). lobeId is yours, to tell your own lobes apart. Call it from
/// Synchronize at k_RixSCRenderBegin and keep the result in a static.
PRMAN_INLINE RixBXLobeSampled RixBXLookupLobeByName(RixContext& ctx, bool discrete, bool specular,
                                                    bool reflect, bool user, unsigned char lobeId,
                                                    const char* name) {
    unsigned char lpeId = 1;
    if (RixLPEInfo* table = static_cast<RixLPEInfo*>(ctx.GetRixInterface(k_RixLPEInfo)))
        lpeId = table->GetLpeIdByName(specular, user, name ? name : "");
    else if (name && std::strcmp(name, "Emission") == 0)
        lpeId = 0;
    return RixBXLobeSampled(discrete, specular, reflect, user, lpeId, lobeId);
}

/// Per-lobe weight arrays. The integrator owns the storage; a Bxdf calls
/// AddActiveLobe(lobe) to get that lobe's array (numPts colours, zeroed on
/// first use) and writes W = f * |cos(theta_L)| into it. The integrator sums the
/// active lobes. There is one array per lobe kind and light path expression id.
class RixBXLobeWeights {
public:
    /// Renderer side, with all the storage up front: `storage` holds
    /// k_numSlots arrays of `numPoints` colours, one after the other.
    RixBXLobeWeights(int numPoints, RtColorRGB* storage) : m_numPoints(numPoints) {
        for (int slot = 0; slot < k_numSlots; ++slot)
            m_slots[slot] = storage + static_cast<size_t>(slot) * static_cast<size_t>(numPoints);
    }
    /// Renderer side, with storage taken from a shading context's memory pool
    /// one lobe at a time, when a Bxdf first activates that lobe (most Bxdfs
    /// use one or two of the k_numSlots lobes).
    RixBXLobeWeights(int numPoints, RixShadingContext const* pool) : m_numPoints(numPoints), m_pool(pool) {}

    int GetNumPoints() const { return m_numPoints; }

    /// The weight array of `lobe`, zeroed the first time it is requested.
    RtColorRGB* AddActiveLobe(RixBXLobeSampled lobe) {
        int slot = SlotOf(lobe);
        RtColorRGB*& weights = m_slots[slot];
        if (!weights) weights = RixShadingContext::Allocator(m_pool).AllocFor<RtColorRGB>(m_numPoints);
        if (!(m_activeMask & (1u << slot))) {
            m_activeMask |= 1u << slot;
            m_active[m_numActive++] = lobe;
            for (int i = 0; i < m_numPoints; ++i) weights[i].Zero();
        }
        return weights;
    }
    int GetNumActiveLobes() const { return m_numActive; }
    RixBXLobeSampled GetActiveLobe(int k) const { return m_active[k]; }
    RtColorRGB const* GetActiveLobeWeights(int k) const { return m_slots[SlotOf(m_active[k])]; }
    /// Sum of all active lobes at point i.
    RtColorRGB SumAtPoint(int i) const {
        RtColorRGB sum;
        for (int k = 0; k < m_numActive; ++k) sum += GetActiveLobeWeights(k)[i];
        return sum;
    }
    void ClearActiveLobes() { m_activeMask = 0; m_numActive = 0; }
    /// Renderer side: zeroes point i's weight in every active lobe.
    void ZeroAtPoint(int i) {
        for (int k = 0; k < m_numActive; ++k) m_slots[SlotOf(m_active[k])][i].Zero();
    }

    static constexpr int k_numSlots =
        k_RixBXMaxNumDiffuseLobes + k_RixBXMaxNumSpecularLobes + k_RixBXMaxNumUserLobes;

private:
    static int SlotOf(RixBXLobeSampled lobe) {
        int id = lobe.GetLpeId();
        if (lobe.GetUser()) return k_RixBXMaxNumDiffuseLobes + k_RixBXMaxNumSpecularLobes + id % k_RixBXMaxNumUserLobes;
        if (lobe.GetSpecular()) return k_RixBXMaxNumDiffuseLobes + id % k_RixBXMaxNumSpecularLobes;
        return id % k_RixBXMaxNumDiffuseLobes;
    }
    int m_numPoints;
    RixShadingContext const* m_pool = nullptr;
    RtColorRGB* m_slots[k_numSlots] = {};
    uint32_t m_activeMask = 0;
    int m_numActive = 0;
    RixBXLobeSampled m_active[k_numSlots];
};

/// Chooses one of `numLobes` lobes with probability proportional to
/// weights[k] (which need not sum to 1). Returns the index, or -1 when every
/// weight is zero. If `xiRemapped` is given it receives xi stretched back to
/// [0,1) inside the chosen interval, so the same number can be reused to
/// sample the chosen lobe; `probability` receives the chosen lobe's probability.
PRMAN_INLINE int RixBXChooseLobe(float xi, float const* weights, int numLobes,
                                 float* xiRemapped = nullptr, float* probability = nullptr) {
    float total = 0.0f;
    for (int k = 0; k < numLobes; ++k) total += weights[k] > 0.0f ? weights[k] : 0.0f;
    if (!(total > 0.0f)) return -1;
    float target = xi * total, start = 0.0f;
    int chosen = -1;
    for (int k = 0; k < numLobes; ++k) {
        float w = weights[k] > 0.0f ? weights[k] : 0.0f;
        if (w <= 0.0f) continue;
        chosen = k;
        if (target < start + w) break;
        start += w;
    }
    if (chosen < 0) return -1;
    float w = weights[chosen];
    if (xiRemapped) {
        float r = (target - start) / w;
        *xiRemapped = r < 0.0f ? 0.0f : (r < 0.99999994f ? r : 0.99999994f);
    }
    if (probability) *probability = w / total;
    return chosen;
}
