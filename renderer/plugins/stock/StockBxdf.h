// What the stock Bxdf plugins share: a factory with nothing to set up, tear
// down or release after a batch (each keeps only its parameter table, its
// lobe lookup and BeginScatter), and the exported create/destroy pair.
#pragma once

#include "RixBxdf.h"

namespace stockbxdfs {

class StockBxdfFactory : public RixBxdfFactory {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    void EndScatter(RixBxdf*) override {}
};

}  // namespace stockbxdfs

/// Exports the create/destroy pair the renderer looks up in a Bxdf plugin.
#define STOCK_BXDF_PLUGIN(Factory)              \
    RIX_BXDFPLUGINCREATE {                      \
        PIXAR_ARGUSED(hint);                    \
        return new Factory();                   \
    }                                           \
    RIX_BXDFPLUGINDESTROY { delete static_cast<Factory*>(bxdf); }
