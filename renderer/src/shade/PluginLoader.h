// Loads Bxdf, pattern and integrator plugins (shared objects) by name from
// the plugin search path.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "RixBxdf.h"
#include "RixIntegrator.h"
#include "RixPattern.h"
#include "core/Diagnostics.h"
#include "core/Error.h"
#include "parse/ParamList.h"
#include "shade/PluginMessages.h"
#include "shade/SharedObject.h"

namespace bxdflab {

/// One loaded shading plugin, a Bxdf or a pattern: its factory (initialised)
/// and its parameter table.
class ShadingPlugin {
public:
    enum class Kind { Bxdf, Pattern };
    ShadingPlugin(Kind kind, std::string name, std::string path, Diagnostics& diagnostics);
    ~ShadingPlugin();
    ShadingPlugin(ShadingPlugin const&) = delete;
    ShadingPlugin& operator=(ShadingPlugin const&) = delete;

    std::string const& name() const { return m_name; }
    std::string const& path() const { return m_path; }
    Kind kind() const { return m_kind; }
    /// The Bxdf factory (null for a pattern) and the pattern (null for a Bxdf).
    RixBxdfFactory* factory() const { return m_kind == Kind::Bxdf ? static_cast<RixBxdfFactory*>(m_factory) : nullptr; }
    RixPattern* pattern() const { return m_kind == Kind::Pattern ? static_cast<RixPattern*>(m_factory) : nullptr; }
    RixShadingPlugin* plugin() const { return m_factory; }
    std::vector<RixSCParamInfo> const& paramTable() const { return m_table; }
    /// The name RIB gives each row of the table: a struct member's is
    /// "struct.member"; a struct's closing row has none ("").
    std::vector<std::string> const& paramNames() const { return m_names; }
    /// Index of a parameter in the table by its RIB name, or -1. A struct's
    /// name gives its point member (a manifold travels as its Q here).
    int paramId(std::string const& name) const;
    RixContext& context() { return m_context; }
    /// Messages from this plugin, prefixed with its name.
    RixMessages& messages() { return m_messages; }

private:
    /// Finalizes and destroys the factory (a failed constructor's clean-up too).
    void release();
    void destroyFactory();

    Kind m_kind;
    std::string m_name, m_path;
    PluginMessages m_messages;
    PluginContext m_context;
    SharedObject m_library;
    RixShadingPlugin* m_factory = nullptr;
    void (*m_destroyBxdf)(RixBxdfFactory*) = nullptr;
    void (*m_destroyPattern)(RixPattern*) = nullptr;
    std::vector<RixSCParamInfo> m_table;
    std::vector<std::string> m_names;
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
    ShadingPlugin& bxdf(std::string const& name, SourceLocation const& where = {});
    /// The pattern plugin `name`, the same way.
    ShadingPlugin& pattern(std::string const& name, SourceLocation const& where = {});
    /// Whether a plugin of that name is on the search path.
    bool has(std::string const& name) const;
    /// Loads the integrator plugin `name` and creates it with `params`.
    std::unique_ptr<IntegratorPlugin> integrator(std::string const& name, ParamList const& params,
                                                 SourceLocation const& where);
    std::vector<std::string> const& searchPath() const { return m_searchPath; }

private:
    /// The file name.so in the first folder that has it (warning when only its
    /// case differs); throws naming every folder tried.
    std::string find(std::string const& name, const char* kind, SourceLocation const& where) const;
    /// The same path, or empty when no folder has it. A name found in no folder
    /// as spelled is looked for again ignoring case.
    std::string locate(std::string const& name) const;
    /// Finds and loads a Bxdf or pattern plugin; a plugin refused on loading is
    /// reported at the statement that named it.
    std::unique_ptr<ShadingPlugin> load(ShadingPlugin::Kind kind, std::string const& name, SourceLocation const& where);
    std::vector<std::string> m_searchPath;
    mutable std::map<std::string, std::string> m_located;  ///< locate()'s answers (the folders do not change)
    Diagnostics& m_diagnostics;
    std::map<std::string, std::unique_ptr<ShadingPlugin>> m_plugins;   ///< Bxdfs
    std::map<std::string, std::unique_ptr<ShadingPlugin>> m_patterns;
};

}  // namespace bxdflab
