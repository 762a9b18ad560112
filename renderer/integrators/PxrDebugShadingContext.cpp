// PxrDebugShadingContext: shows one builtin of the shading context as a
// colour. "string viewchannel": Nn, Ngn, Vn, Tn, P, dPdu, dPdv map x, y, z to
// red, green, blue with 0 at mid-grey (P, dPdu and dPdv, which are not unit
// vectors, as v / (1 + |v|): their direction shows without saturating, and
// where they vanish the colour is mid-grey); VLen is grey; UV and ST map (u, v) to
// (red, green); InsideOutside is green where the viewer is on the outside
// (the side Ngn points to) and red inside.
#include <string>

#include "common/Params.h"

using namespace bxdflab;

namespace {

const char* const kChannels[] = {"Nn", "Ngn", "Vn", "Tn", "P", "dPdu", "dPdv", "VLen", "UV", "ST", "InsideOutside"};

class DebugShadingContext : public RixIntegrator {
public:
    explicit DebugShadingContext(std::string channel) : m_channel(std::move(channel)) {}

    void DescribeEffects(int, RixEffects& effects) const override {
        effects.Simulate("camera rays");
        effects.Simulate(("shading-context view of " + m_channel).c_str());
        effects.Skip("light sampling and shadow rays", "PxrDebugShadingContext shows geometry only");
        effects.Skip("indirect rays", "PxrDebugShadingContext shows geometry only");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf&, RixRNG&, RixIntegratorContext&, RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        auto asColor = [](RtFloat3 const& v) { return RtColorRGB(0.5f + 0.5f * v.x, 0.5f + 0.5f * v.y, 0.5f + 0.5f * v.z); };
        auto showVector = [&](RixShadingContext::BuiltinId id) {
            RtVector3 const* values;
            ctx.GetBuiltinVar(id, &values);
            for (int i = 0; i < n; ++i) radiance[i] = asColor(values[i]);
        };
        auto showLongVector = [&](RixShadingContext::BuiltinId id) {
            RtVector3 const* values;
            ctx.GetBuiltinVar(id, &values);
            for (int i = 0; i < n; ++i) radiance[i] = asColor(values[i] / (1.0f + values[i].Length()));
        };
        auto showPair = [&](RixShadingContext::BuiltinId a, RixShadingContext::BuiltinId b) {
            float const *x, *y;
            ctx.GetBuiltinVar(a, &x);
            ctx.GetBuiltinVar(b, &y);
            for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(x[i], y[i], 0.0f);
        };
        if (m_channel == "Nn") showVector(RixShadingContext::k_Nn);
        else if (m_channel == "Ngn") showVector(RixShadingContext::k_Ngn);
        else if (m_channel == "Vn") showVector(RixShadingContext::k_Vn);
        else if (m_channel == "Tn") showVector(RixShadingContext::k_Tn);
        else if (m_channel == "P") showLongVector(RixShadingContext::k_P);
        else if (m_channel == "dPdu") showLongVector(RixShadingContext::k_dPdu);
        else if (m_channel == "dPdv") showLongVector(RixShadingContext::k_dPdv);
        else if (m_channel == "UV") showPair(RixShadingContext::k_u, RixShadingContext::k_v);
        else if (m_channel == "ST") showPair(RixShadingContext::k_s, RixShadingContext::k_t);
        else if (m_channel == "VLen") {
            float const* length;
            ctx.GetBuiltinVar(RixShadingContext::k_VLen, &length);
            for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(length[i]);
        } else {  // InsideOutside
            RtVector3 const* Vn;
            RtNormal3 const* Ngn;
            ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
            ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
            for (int i = 0; i < n; ++i) radiance[i] = Vn[i].Dot(Ngn[i]) >= 0.0f ? RtColorRGB(0, 1, 0) : RtColorRGB(1, 0, 0);
        }
    }

private:
    std::string m_channel;
};

}  // namespace

RIX_INTEGRATORCREATE {
    std::string channel = ReadString(params, "viewchannel", "Nn");
    for (const char* known : kChannels)
        if (channel == known) return new DebugShadingContext(channel);
    std::string list;
    for (const char* known : kChannels) list += std::string(list.empty() ? "" : ", ") + known;
    messages->Error("unknown viewchannel \"%s\" (choose one of %s)", channel.c_str(), list.c_str());
    return nullptr;
}

RIX_INTEGRATORDESTROY { delete integrator; }
