// What the stock Bxdf plugins share: a factory with nothing to set up, tear
// down or release after a batch (each keeps only its parameter table, its
// lobe lookup and BeginScatter), RenderMan's presence parameter for those
// that have one, and the exported create/destroy pair.
#pragma once

#include <new>

#include "RixBxdf.h"
#include "bxdf/PxrSurfaceOpacity.h"

namespace stockbxdfs {

class StockBxdfFactory : public RixBxdfFactory {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    void EndScatter(RixBxdf*) override {}
};

/// A stock factory with RenderMan's "float presence" parameter (row
/// `presenceRow` of its table, default 1). An instance computes presence only
/// when its RIB statement asks for it (a value below 1, or a pattern
/// connected), so every other surface stays trivially opaque and costs nothing.
class StockBxdfWithPresence : public StockBxdfFactory {
public:
    explicit StockBxdfWithPresence(int presenceRow) : m_presenceRow(presenceRow) {}

    void CreateInstanceData(RixContext&, RtUString const, RixParameterList const* params,
                            InstanceData* instance) override {
        RixSCType type;
        RixSCConnectionInfo given = k_RixSCDefaultValue;
        if (params->GetParamInfo(m_presenceRow, &type, &given) != 0) return;
        float value = 1.0f;
        if (given == k_RixSCParameterListValue) params->EvalParam(m_presenceRow, -1, &value);
        // Any non-null pointer marks the instance as cut out; nothing to free.
        if (given == k_RixSCNetworkValue || value < 1.0f) instance->data = &m_presenceRow;
    }
    int GetInstanceHints(RtPointer instanceData) const override {
        return instanceData ? k_ComputesPresence : k_TriviallyOpaque;
    }
    RixOpacity* BeginOpacity(RixShadingContext const* sCtx, RixSCShadingMode, void*, RtPointer) override {
        float const one = 1.0f;
        float const* presence;
        RixSCDetail const detail = sCtx->EvalParam(m_presenceRow, -1, &presence, &one);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<PxrSurfaceOpacity>(1))
            PxrSurfaceOpacity(sCtx, this, presence, nullptr, detail == k_RixSCUniform);
    }

private:
    int m_presenceRow;
};

}  // namespace stockbxdfs

/// Exports the create/destroy pair the renderer looks up in a Bxdf plugin.
#define STOCK_BXDF_PLUGIN(Factory)              \
    RIX_BXDFPLUGINCREATE {                      \
        PIXAR_ARGUSED(hint);                    \
        return new Factory();                   \
    }                                           \
    RIX_BXDFPLUGINDESTROY { delete static_cast<Factory*>(bxdf); }
