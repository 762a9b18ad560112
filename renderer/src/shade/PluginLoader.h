// Loads Bxdf plugins (shared objects) by name from the plugin search path.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "RixBxdf.h"
#include "RixIntegrator.h"
#include "core/Diagnostics.h"
#include "core/Error.h"
#include "parse/ParamList.h"
#include "shade/PluginMessages.h"
#include "shade/SharedObject.h"

namespace bxdflab {

/// One loaded plugin: its factory (initialised) and its parameter table.
class BxdfPlugin {
public:
    BxdfPlugin(std::string name, std::string path, Diagnostics& diagnostics);
    ~BxdfPlugin();
    BxdfPlugin(BxdfPlugin const&) = delete;
    BxdfPlugin& operator=(BxdfPlugin const&) = delete;

    std::string const& name() const { return m_name; }
    std::string const& path() const { return m_path; }
    RixBxdfFactory* factory() const { return m_factory; }
    std::vector<RixSCParamInfo> const& paramTable() const { return m_table; }
    /// Index of a parameter in the table, or -1.
    int paramId(std::string const& name) const;
    RixContext& context() { return m_context; }
    /// Messages from this plugin, prefixed with its name.
    RixMessages& messages() { return m_messages; }

private:
    using CreateFn = RixBxdfFactory* (*)(const char*);
    using DestroyFn = void (*)(RixBxdfFactory*);
    using VersionFn = int (*)();

    std::string m_name, m_path;
    PluginMessages m_messages;
    PluginContext m_context;
    SharedObject m_library;
    RixBxdfFactory* m_factory = nullptr;
    DestroyFn m_destroy = nullptr;
    std::vector<RixSCParamInfo> m_table;
};

/// One integrator plugin, created from an Integrator statement's parameters.
class IntegratorPlugin {
public:
    /// Throws a RibError located at `where` when the plugin refuses the parameters.
    IntegratorPlugin(std::string name, std::string path, ParamList const& params, SourceLocation const& where,
                     Diagnostics& diagnostics);
    ~IntegratorPlugin();
    IntegratorPlugin(IntegratorPlugin const&) = delete;
    IntegratorPlugin& operator=(IntegratorPlugin const&) = delete;

    std::string const& name() const { return m_name; }
    std::string const& path() const { return m_path; }
    RixIntegrator& integrator() const { return *m_integrator; }

private:
    using CreateFn = RixIntegrator* (*)(RixParameterList const*, RixMessages*);
    using DestroyFn = void (*)(RixIntegrator*);
    std::string m_name, m_path;
    SharedObject m_library;
    RixIntegrator* m_integrator = nullptr;
    DestroyFn m_destroy = nullptr;
};

class PluginLoader {
public:
    PluginLoader(std::vector<std::string> searchPath, Diagnostics& diagnostics)
        : m_searchPath(std::move(searchPath)), m_diagnostics(diagnostics) {}

    /// The plugin `name` (loading it on first use). Throws a RenderError that
    /// names the plugin and every folder searched when it cannot be found.
    BxdfPlugin& bxdf(std::string const& name, SourceLocation const& where = {});
    /// Whether a plugin of that name is on the search path.
    bool has(std::string const& name) const;
    /// Loads the integrator plugin `name` and creates it with `params`.
    std::unique_ptr<IntegratorPlugin> integrator(std::string const& name, ParamList const& params,
                                                 SourceLocation const& where);
    std::vector<std::string> const& searchPath() const { return m_searchPath; }

private:
    /// The file name.so in the first folder that has it; throws naming every folder tried.
    std::string find(std::string const& name, const char* kind, SourceLocation const& where) const;
    /// The same path, or empty when no folder has it.
    std::string locate(std::string const& name) const;
    std::vector<std::string> m_searchPath;
    Diagnostics& m_diagnostics;
    std::map<std::string, std::unique_ptr<BxdfPlugin>> m_plugins;
};

}  // namespace bxdflab
