// A test Bxdf that shows what GetParamInfo says, asked the way RenderMan's own
// plugins ask it (pList->GetParamInfo(id, &type, &cinfo) in CreateInstanceData,
// sCtx->GetParamInfo(id, &type, &cinfo) while shading). It emits
//   red   = the connection info of "float given" / 2
//   green = the connection info of "color connected" / 2
//   blue  = the array length of "float triple[3]" / 4
// and magenta (1, 0, 1) when the two questions disagree, a type is not the
// table's, "float untouched" is not k_RixSCDefaultValue or an unknown id is
// not refused. It reflects nothing.
#include <new>

#include "EmitOnlyBxdf.h"

namespace {

enum { kGiven = 0, kConnected, kUntouched, kTriple, kParamCount };

RixSCParamInfo const* table() {
    static RixSCParamInfo rows[] = {RixSCParamInfo(RtUString("given"), k_RixSCFloat, k_RixSCScatterInput),
                                    RixSCParamInfo(RtUString("connected"), k_RixSCColor, k_RixSCScatterInput),
                                    RixSCParamInfo(RtUString("untouched"), k_RixSCFloat, k_RixSCScatterInput),
                                    RixSCParamInfo(RtUString("triple"), k_RixSCFloat, k_RixSCScatterInput, 3),
                                    RixSCParamInfo()};
    return rows;
}

/// What one side (the parameter list or the shading context) answers.
struct Answers {
    RixSCConnectionInfo cinfo[kParamCount];
    int tripleLength = 0;
    bool consistent = true;
};

template <typename Asker>
Answers ask(Asker const* asker) {
    Answers a;
    for (int id = 0; id < kParamCount; ++id) {
        RixSCType type = k_RixSCInvalidType;
        int length = 0;
        if (asker->GetParamInfo(id, &type, &a.cinfo[id], &length) != 0 || type != table()[id].type)
            a.consistent = false;
        if (id == kTriple)
            a.tripleLength = length;
        else if (length != -1)
            a.consistent = false;  // not an array
    }
    RixSCConnectionInfo ignored;
    if (asker->GetParamInfo(kParamCount, nullptr, &ignored) == 0) a.consistent = false;
    if (a.cinfo[kUntouched] != k_RixSCDefaultValue) a.consistent = false;
    return a;
}

class Emitter : public EmitOnlyBxdf {
public:
    Emitter(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB emission)
        : EmitOnlyBxdf(sc, factory), m_emission(emission) {}
    bool EmitLocal(RtColorRGB* result) override {
        for (int i = 0; i < shadingCtx->numPts; ++i) result[i] = m_emission;
        return true;
    }

private:
    RtColorRGB m_emission;
};

class ParamInfoFactory : public RixBxdfFactory {
   public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    RixSCParamInfo const* GetParamTable() override { return table(); }
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    void CreateInstanceData(RixContext&, RtUString const, RixParameterList const* pList,
                            InstanceData* instance) override {
        instance->data = new Answers(ask(pList));
        instance->datalen = sizeof(Answers);
        instance->freefunc = [](void* data) { delete static_cast<Answers*>(data); };
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer instanceData) override {
        Answers const& fromList = *static_cast<Answers const*>(instanceData);
        Answers const whileShading = ask(sCtx);
        bool agree = fromList.consistent && whileShading.consistent &&
                     fromList.tripleLength == whileShading.tripleLength;
        for (int id = 0; id < kParamCount; ++id)
            agree = agree && fromList.cinfo[id] == whileShading.cinfo[id];
        RtColorRGB emission(0.5f * static_cast<float>(fromList.cinfo[kGiven]),
                            0.5f * static_cast<float>(fromList.cinfo[kConnected]),
                            0.25f * static_cast<float>(fromList.tripleLength));
        if (!agree) emission = RtColorRGB(1.0f, 0.0f, 1.0f);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Emitter>(1)) Emitter(sCtx, this, emission);
    }
    void EndScatter(RixBxdf*) override {}
};

}  // namespace

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new ParamInfoFactory();
}
RIX_BXDFPLUGINDESTROY { delete static_cast<ParamInfoFactory*>(bxdf); }
