#include "shade/PluginLoader.h"

#include <dlfcn.h>

#include <filesystem>

namespace bxdflab {
namespace {
constexpr size_t kMaxParams = 1024;  // a table longer than this has lost its end marker

std::string describeType(RixSCType type) {
    switch (type) {
        case k_RixSCFloat: return "float";
        case k_RixSCInteger: return "int";
        case k_RixSCColor: return "color";
        case k_RixSCNormal: return "normal";
        case k_RixSCVector: return "vector";
        case k_RixSCPoint: return "point";
        case k_RixSCString: return "string";
        case k_RixSCFloat2: return "float[2]";
        default: return "invalid";
    }
}
}  // namespace

BxdfPlugin::BxdfPlugin(std::string name, std::string path, Diagnostics& diagnostics)
    : m_name(std::move(name)), m_path(std::move(path)), m_messages(diagnostics, m_name), m_context(m_messages) {
    std::string where = "plugin \"" + m_name + "\" (" + m_path + ")";
    dlerror();
    m_handle = dlopen(m_path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!m_handle) {
        const char* why = dlerror();
        throw RenderError("cannot load " + where + ": " + (why ? why : "unknown dlopen error"));
    }
    auto fail = [&](std::string const& message) {
        dlclose(m_handle);
        m_handle = nullptr;
        throw RenderError(where + ": " + message);
    };
    auto create = reinterpret_cast<CreateFn>(dlsym(m_handle, "CreateRixBxdfFactory"));
    m_destroy = reinterpret_cast<DestroyFn>(dlsym(m_handle, "DestroyRixBxdfFactory"));
    if (!create)
        fail("does not export CreateRixBxdfFactory (define it with RIX_BXDFPLUGINCREATE, or extern \"C\" PRMANEXPORT)");
    if (!m_destroy)
        fail("does not export DestroyRixBxdfFactory (define it with RIX_BXDFPLUGINDESTROY, or extern \"C\" PRMANEXPORT)");
    if (auto version = reinterpret_cast<VersionFn>(dlsym(m_handle, "RixBxdfPluginApiVersion"))) {
        int v = version();
        if (v != RIX_BXDF_API_VERSION)
            fail("was built against Rix API version " + std::to_string(v) + ", this renderer provides version " +
                 std::to_string(RIX_BXDF_API_VERSION) + "; rebuild the plugin");
    }
    m_factory = create(m_name.c_str());
    if (!m_factory) fail("CreateRixBxdfFactory returned null");
    if (int status = m_factory->Init(m_context, RtUString(m_path.c_str())); status != 0) {
        m_destroy(m_factory);
        m_factory = nullptr;
        fail("Init failed with status " + std::to_string(status));
    }
    RixSCParamInfo const* table = m_factory->GetParamTable();
    if (!table) {
        m_factory->Finalize(m_context);
        m_destroy(m_factory);
        m_factory = nullptr;
        fail("GetParamTable returned null (return a table that ends with RixSCParamInfo())");
    }
    for (size_t i = 0;; ++i) {
        if (i == kMaxParams) {
            m_factory->Finalize(m_context);
            m_destroy(m_factory);
            m_factory = nullptr;
            fail("the parameter table has no end marker RixSCParamInfo() in its first " + std::to_string(kMaxParams) + " entries");
        }
        if (table[i].IsEndOfTable()) break;
        if (table[i].name.Empty() || describeType(table[i].type) == "invalid") {
            m_factory->Finalize(m_context);
            m_destroy(m_factory);
            m_factory = nullptr;
            fail("parameter table entry " + std::to_string(i) + " has an empty name or an invalid type");
        }
        m_table.push_back(table[i]);
    }
}

BxdfPlugin::~BxdfPlugin() {
    if (m_factory) {
        m_factory->Finalize(m_context);
        m_destroy(m_factory);
    }
    if (m_handle) dlclose(m_handle);
}

int BxdfPlugin::paramId(std::string const& name) const {
    for (size_t i = 0; i < m_table.size(); ++i)
        if (name == m_table[i].name.CStr()) return static_cast<int>(i);
    return -1;
}

BxdfPlugin& PluginLoader::bxdf(std::string const& name, SourceLocation const& where) {
    auto found = m_plugins.find(name);
    if (found != m_plugins.end()) return *found->second;
    if (name.find('/') != std::string::npos)
        throw RenderError((where.known() ? where.str() + ": " : "") + "plugin names may not contain '/': \"" + name + "\"");
    for (std::string const& folder : m_searchPath) {
        std::filesystem::path candidate = std::filesystem::path(folder) / (name + ".so");
        if (std::filesystem::is_regular_file(candidate)) {
            auto plugin = std::make_unique<BxdfPlugin>(name, candidate.string(), m_diagnostics);
            return *m_plugins.emplace(name, std::move(plugin)).first->second;
        }
    }
    std::string searched;
    for (auto const& folder : m_searchPath) searched += "\n    " + folder;
    throw RenderError((where.known() ? where.str() + ": " : "") + "Bxdf plugin \"" + name + "\" not found: no " + name +
                      ".so in any folder of the plugin search path:" + searched +
                      "\n  (add a folder with --plugin-path, $RIX_PLUGIN_PATH or Option \"searchpath\" \"string rixplugin\")");
}

}  // namespace bxdflab
