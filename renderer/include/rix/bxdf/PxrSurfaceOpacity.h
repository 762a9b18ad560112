// PxrSurfaceOpacity: a ready-made RixOpacity for a Bxdf whose presence is one
// of its parameters (as PxrSurface's "presence" is). BeginOpacity evaluates
// the parameter and hands the values to this object, which gives them back
// to the renderer:
//
//   RixOpacity* BeginOpacity(RixShadingContext const* sCtx, RixSCShadingMode, void*, RtPointer) override {
//       float const one = 1.0f;
//       float const* presence;
//       RixSCDetail detail = sCtx->EvalParam(k_presence, -1, &presence, &one);
//       void* mem = RixShadingContext::Allocator(sCtx).AllocForBxdf<PxrSurfaceOpacity>(1);
//       return new (mem) PxrSurfaceOpacity(sCtx, this, presence, nullptr, detail == k_RixSCUniform);
//   }
//
// The values must live as long as the batch: EvalParam's do.
#pragma once

#include "RixBxdf.h"

class PxrSurfaceOpacity : public RixOpacity {
public:
    /// presence: numPts values, or one when uniformPresence (null: fully
    /// present). opacity: numPts colours for shadows, one when uniformOpacity,
    /// or null (opaque shadows).
    PxrSurfaceOpacity(RixShadingContext const* sCtx, RixBxdfFactory* factory, float const* presence,
                      RtColorRGB const* opacity, bool uniformPresence = false, bool uniformOpacity = false)
        : RixOpacity(sCtx, factory),
          m_presence(presence),
          m_opacity(opacity),
          m_uniformPresence(uniformPresence),
          m_uniformOpacity(uniformOpacity) {}

    bool GetPresence(float* result) override {
        if (!m_presence) return false;
        for (int i = 0; i < shadingCtx->numPts; ++i) result[i] = m_presence[m_uniformPresence ? 0 : i];
        return true;
    }
    bool GetOpacity(RtColorRGB* result) override {
        if (!m_opacity) return false;
        for (int i = 0; i < shadingCtx->numPts; ++i) result[i] = m_opacity[m_uniformOpacity ? 0 : i];
        return true;
    }

private:
    float const* m_presence;
    RtColorRGB const* m_opacity;
    bool m_uniformPresence;
    bool m_uniformOpacity;
};
