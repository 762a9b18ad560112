// RixInterfaces.h — services the renderer offers to plugins.
//
// A plugin asks a RixContext (handed to Init/Synchronize/CreateInstanceData) or
// a RixShadingContext for an interface by id. The one every plugin needs is
// RixMessages: printf-style messages that the renderer prints with the plugin's
// name, counts, and shows in the render statistics.
#pragma once

#include <cstdarg>
#include <cstdio>

#include "RiTypesHelper.h"

enum RixInterfaceId {
    k_RixMessages = 0,
    k_RixRenderState,   ///< not provided by this renderer (GetRixInterface returns null)
    k_RixThreadUtils,   ///< not provided by this renderer (GetRixInterface returns null)
    k_RixLPEInfo,       ///< the light-path-expression lobe table (used by RixBXLookupLobeByName)
    k_RixTexture,       ///< filtered, mip-mapped texture lookups (from a RixShadingContext)
};

/// Base of every interface. Versions let a plugin check what it was built for.
class RixInterface {
public:
    virtual ~RixInterface() = default;
    virtual int GetVersion() const { return 1; }
};

/// The renderer's table of named lobes. Each name gets its own light path
/// expression id within its kind (diffuse, specular or user), the same for
/// every plugin that names it; RixBXLookupLobeByName asks it, so you rarely
/// call it yourself.
class RixLPEInfo : public RixInterface {
public:
    /// The id of the lobe `name` of that kind (1, 2, ... in order of first
    /// lookup; "Emission" is 0).
    virtual unsigned char GetLpeIdByName(bool specular, bool user, const char* name) = 0;
};

/// Texture lookups for pattern plugins. The renderer keeps one cache of
/// texture tiles for every plugin and thread, so a texture is read from disk
/// once however many patterns use it. Ask the shading context for it:
///
///   auto* tex = static_cast<RixTexture*>(sCtx->GetRixInterface(k_RixTexture));
///
/// Any image OpenImageIO reads works; mip-mapped tiled files made with
/// `maketx` (.tx) are filtered fastest and best.
class RixTexture : public RixInterface {
public:
    /// How one lookup is done.
    struct TxParams {
        int firstChannel = 0;           ///< first channel to read (0 = red)
        RtColorRGB missingColor{1.0f, 0.0f, 1.0f};  ///< returned where the file cannot be read
        bool periodic = true;           ///< repeat outside [0,1] (false: clamp to the edge)
    };
    /// Reads `numChannels` (1 to 4) channels of `filename` at `numPts` texture
    /// coordinates `st` (s across the image from its left edge, t down from its
    /// top row), filtered over a square of side `width[i]` in texture units
    /// (0: the finest level, bilinear). `result` receives numPts * numChannels
    /// floats, point by point. A one-channel (grey) image reads the same in its
    /// first three channels, and a channel past the image's last reads 1 (an RGB
    /// image's alpha is opaque). Returns 0, or 1 when the file cannot be read
    /// (then every point gets the missing colour, a fourth channel 1, and the
    /// renderer warns once).
    virtual int Texture(RtUString filename, TxParams const& params, int numPts, RtFloat2 const* st,
                        RtFloat const* width, int numChannels, RtFloat* result) = 0;
};

/// Messages from plugins. Use Warning for "your parameters make no physical
/// sense" and Error for "I cannot do what was asked"; neither stops the render.
/// Repeated identical messages are printed once and counted.
class RixMessages : public RixInterface {
public:
    enum Severity { k_Info = 0, k_Warning, k_Error };

    void Error(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
        va_list args; va_start(args, fmt); Emit(k_Error, fmt, args); va_end(args);
    }
    void Warning(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
        va_list args; va_start(args, fmt); Emit(k_Warning, fmt, args); va_end(args);
    }
    void Info(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
        va_list args; va_start(args, fmt); Emit(k_Info, fmt, args); va_end(args);
    }
    /// RenderMan's "always" variants bypass de-duplication; here every message
    /// is reported, so they behave like the plain forms.
    void ErrorAlways(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
        va_list args; va_start(args, fmt); Emit(k_Error, fmt, args); va_end(args);
    }
    void WarningAlways(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
        va_list args; va_start(args, fmt); Emit(k_Warning, fmt, args); va_end(args);
    }
    void InfoAlways(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
        va_list args; va_start(args, fmt); Emit(k_Info, fmt, args); va_end(args);
    }

protected:
    /// Receives one already-formatted message.
    virtual void Report(Severity severity, const char* message) = 0;

private:
    void Emit(Severity severity, const char* fmt, va_list args) {
        char buffer[1024];
        std::vsnprintf(buffer, sizeof buffer, fmt, args);
        Report(severity, buffer);
    }
};

/// The renderer, as seen from a plugin outside of shading (load, sync, instance creation).
class RixContext {
public:
    virtual ~RixContext() = default;
    /// The interface with this id, or nullptr when the renderer does not offer it.
    virtual RixInterface* GetRixInterface(RixInterfaceId id) const = 0;
};
