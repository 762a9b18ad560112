// RixMessages and RixContext as the renderer provides them to plugins: every
// message goes to the render's Diagnostics, prefixed with the plugin's name.
#pragma once

#include <string>

#include "RixInterfaces.h"
#include "shade/LobeTable.h"
#include "core/Diagnostics.h"

namespace bxdflab {

class PluginMessages final : public RixMessages {
public:
    /// `where`, when known, is the RIB statement that asked for the plugin.
    PluginMessages(Diagnostics& diagnostics, std::string pluginName, SourceLocation const& where = {})
        : m_diagnostics(diagnostics),
          m_prefix((where.known() ? where.str() + ": " : "") + "plugin " + std::move(pluginName) + ": ") {}

protected:
    void Report(Severity severity, const char* message) override {
        Diagnostics::Severity s = severity == k_Error     ? Diagnostics::Severity::Error
                                  : severity == k_Warning ? Diagnostics::Severity::Warning
                                                          : Diagnostics::Severity::Info;
        m_diagnostics.report(s, m_prefix + message);
    }

private:
    Diagnostics& m_diagnostics;
    std::string m_prefix;
};

class PluginContext final : public RixContext {
public:
    explicit PluginContext(RixMessages& messages) : m_messages(messages) {}
    RixInterface* GetRixInterface(RixInterfaceId id) const override {
        if (id == k_RixMessages) return &m_messages;
        if (id == k_RixLPEInfo) return &LobeTable::instance();
        return nullptr;
    }

private:
    RixMessages& m_messages;
};

}  // namespace bxdflab
