#include "shade/PluginLoader.h"

#include <algorithm>
#include <filesystem>

#include "core/Spelling.h"
#include "shade/ParamTypes.h"
#include "shade/RibParameterList.h"

namespace bxdflab {
namespace fs = std::filesystem;
namespace {
constexpr size_t kMaxParams = 1024;  // a table longer than this has lost its end marker

/// Why a plugin built against other Rix headers cannot be used, or empty.
/// Calling into a plugin whose classes have another layout crashes or
/// silently corrupts memory, so a stale build is refused before any call.
std::string apiMismatch(SharedObject const& library) {
    using VersionFn = int (*)();
    auto version = reinterpret_cast<VersionFn>(library.ownSymbol("RixPluginApiVersion"));
    if (!version)
        return "was built against older Rix headers (it does not export RixPluginApiVersion); rebuild it";
    if (int v = version(); v != RIX_PLUGIN_API_VERSION)
        return "was built against Rix API version " + std::to_string(v) + ", this renderer provides version " +
               std::to_string(RIX_PLUGIN_API_VERSION) + "; rebuild it";
    return "";
}
}  // namespace

ShadingPlugin::ShadingPlugin(Kind kind, std::string name, std::string path, Diagnostics& diagnostics)
    : m_kind(kind),
      m_name(std::move(name)),
      m_path(std::move(path)),
      m_messages(diagnostics, m_name),
      m_context(m_messages),
      m_library(m_path, "plugin \"" + m_name + "\" (" + m_path + ")") {
    std::string where = "plugin \"" + m_name + "\" (" + m_path + ")";
    auto fail = [&](std::string const& message) {
        release();
        throw RenderError(where + ": " + message);
    };
    bool const bxdf = kind == Kind::Bxdf;
    char const* createName = bxdf ? "CreateRixBxdfFactory" : "CreateRixPattern";
    char const* destroyName = bxdf ? "DestroyRixBxdfFactory" : "DestroyRixPattern";
    char const* createMacro = bxdf ? "RIX_BXDFPLUGINCREATE" : "RIX_PATTERNCREATE";
    char const* destroyMacro = bxdf ? "RIX_BXDFPLUGINDESTROY" : "RIX_PATTERNDESTROY";
    void* create = m_library.symbol(createName);
    void* destroy = m_library.symbol(destroyName);
    if (!create)
        fail(std::string("does not export ") + createName + " (define it with " + createMacro +
             ", or extern \"C\" PRMANEXPORT)" + (bxdf && m_library.symbol("CreateRixPattern") ? "; it is a pattern" : "") +
             (!bxdf && m_library.symbol("CreateRixBxdfFactory") ? "; it is a Bxdf" : ""));
    if (!destroy) fail(std::string("does not export ") + destroyName + " (define it with " + destroyMacro + ")");
    if (std::string why = apiMismatch(m_library); !why.empty()) fail(why);
    if (bxdf) {
        m_destroyBxdf = reinterpret_cast<void (*)(RixBxdfFactory*)>(destroy);
        m_factory = reinterpret_cast<RixBxdfFactory* (*)(const char*)>(create)(m_name.c_str());
    } else {
        m_destroyPattern = reinterpret_cast<void (*)(RixPattern*)>(destroy);
        m_factory = reinterpret_cast<RixPattern* (*)(const char*)>(create)(m_name.c_str());
    }
    if (!m_factory) fail(std::string(createName) + " returned null");
    if (int status = m_factory->Init(m_context, RtUString(m_path.c_str())); status != 0) {
        destroyFactory();
        fail("Init failed with status " + std::to_string(status));
    }
    RixSCParamInfo const* table = m_factory->GetParamTable();
    if (!table) fail("GetParamTable returned null (return a table that ends with RixSCParamInfo())");
    // Two plugins whose factories share a class name and write GetParamTable inside the class: GCC makes
    // that function's static table one object for the whole process (STB_GNU_UNIQUE, even across RTLD_LOCAL),
    // so the second plugin hands back the first one's table and its parameters would be read wrongly.
    if (SharedObject::Elsewhere other = m_library.inAnotherPlugin(table); !other.file.empty())
        fail("GetParamTable returned the table of another plugin, " + other.file +
             (other.symbol.empty() ? "" : " (" + other.symbol + ")") +
             ": the two define a class of the same name with GetParamTable written in the class, and the "
             "compiler makes that function's static table one object for the whole program. Give each "
             "plugin's classes their own names (or put them in an anonymous namespace), or build the plugins "
             "with -fvisibility=hidden or -fno-gnu-unique");
    std::string openStruct;  // the struct whose members the rows are, if any
    for (size_t i = 0;; ++i) {
        if (i == kMaxParams)
            fail("the parameter table has no end marker RixSCParamInfo() in its first " + std::to_string(kMaxParams) + " entries");
        RixSCParamInfo const& row = table[i];
        if (row.IsEndOfTable()) break;
        std::string const rowName = row.name.CStr();
        std::string const entry = "parameter table entry " + std::to_string(i) + " (\"" + rowName + "\")";
        bool const marker = row.type == k_RixSCStructBegin || row.type == k_RixSCStructEnd;
        if (rowName.empty() || (!marker && std::string(ribTypeFor(row.type)) == "invalid"))
            fail("parameter table entry " + std::to_string(i) + " has an empty name or an invalid type");
        if (row.type == k_RixSCStructBegin && !openStruct.empty())
            fail(entry + " begins a struct inside struct \"" + openStruct + "\" (structs do not nest)");
        if (row.type == k_RixSCStructEnd && rowName != openStruct)
            fail(entry + " ends a struct that " +
                 (openStruct.empty() ? std::string("was never begun") : "is not the open one, \"" + openStruct + "\""));
        m_names.push_back(row.type == k_RixSCStructEnd                 ? ""
                          : openStruct.empty() || marker ? rowName
                                                         : openStruct + "." + rowName);
        openStruct = row.type == k_RixSCStructBegin ? rowName : row.type == k_RixSCStructEnd ? "" : openStruct;
        m_table.push_back(row);
    }
    if (!openStruct.empty()) fail("the parameter table's struct \"" + openStruct + "\" has no k_RixSCStructEnd row");
}

void ShadingPlugin::destroyFactory() {
    if (!m_factory) return;
    if (m_kind == Kind::Bxdf)
        m_destroyBxdf(static_cast<RixBxdfFactory*>(m_factory));
    else
        m_destroyPattern(static_cast<RixPattern*>(m_factory));
    m_factory = nullptr;
}

void ShadingPlugin::release() {
    if (!m_factory) return;
    m_factory->Finalize(m_context);
    destroyFactory();
}

ShadingPlugin::~ShadingPlugin() { release(); }

int ShadingPlugin::paramId(std::string const& name) const {
    for (size_t i = 0; i < m_table.size(); ++i) {
        if (name.empty() || name != m_names[i]) continue;
        if (m_table[i].type == k_RixSCStructBegin)
            for (size_t member = i + 1; m_table[member].type != k_RixSCStructEnd; ++member)
                if (m_table[member].type == k_RixSCPoint) return static_cast<int>(member);
        return static_cast<int>(i);
    }
    return -1;
}

namespace {
/// The plugin in `folder` whose name matches `name` but for case (the first in
/// sorted order, so that the choice does not depend on the directory's order), or empty.
std::string caseInsensitiveMatch(std::string const& folder, std::string const& name) {
    std::string const wanted = lowered(name) + ".so";
    std::string best;
    std::error_code error;
    for (auto it = fs::directory_iterator(folder, error); !error && it != fs::directory_iterator(); it.increment(error)) {
        std::string file = it->path().filename().string();
        if (lowered(file) == wanted && it->is_regular_file(error) && (best.empty() || file < best))
            best = file;
    }
    return best.empty() ? "" : (fs::path(folder) / best).string();
}

/// Stops at the statement that names the plugin, where there is one.
[[noreturn]] void refuse(SourceLocation const& where, std::string const& message) {
    if (where.known()) throw RibError(where, message);
    throw RenderError(message);
}

/// The plugins the folders hold, by name (their file names without ".so"), sorted.
std::vector<std::string> pluginNames(std::vector<std::string> const& folders) {
    std::vector<std::string> names;
    for (std::string const& folder : folders) {
        std::error_code error;
        for (auto it = fs::directory_iterator(folder, error); !error && it != fs::directory_iterator();
             it.increment(error))
            if (it->path().extension() == ".so") names.push_back(it->path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}
}  // namespace

std::string PluginLoader::locate(std::string const& name) const {
    // Asked once per material: a name is looked for once, the folders' listings read at most once for it.
    auto known = m_located.find(name);
    if (known != m_located.end()) return known->second;
    std::string& found = m_located[name];
    if (name.find('/') != std::string::npos) return found;
    for (std::string const& folder : m_searchPath) {
        std::filesystem::path candidate = std::filesystem::path(folder) / (name + ".so");
        std::error_code error;  // a name the file system rejects (too long, ...) is simply not found
        if (std::filesystem::is_regular_file(candidate, error)) return found = candidate.string();
    }
    // A file system that ignores case (macOS's, Windows') finds "PXRDisney" as PxrDisney.so,
    // so scenes written there use such names; they are found here too, with a warning from find().
    for (std::string const& folder : m_searchPath)
        if (std::string match = caseInsensitiveMatch(folder, name); !match.empty()) return found = match;
    return found;
}

bool PluginLoader::has(std::string const& name) const { return m_plugins.count(name) > 0 || !locate(name).empty(); }

std::string PluginLoader::find(std::string const& name, const char* kind, SourceLocation const& where) const {
    if (name.find('/') != std::string::npos) refuse(where, "plugin names may not contain '/': \"" + name + "\"");
    std::string found = locate(name);
    if (!found.empty()) {
        std::string spelled = fs::path(found).stem().string();
        if (spelled != name)
            m_diagnostics.warn(where, std::string(kind) + " plugin \"" + name + "\" is spelled \"" + spelled +
                                          "\" on the plugin search path: " + found +
                                          " is used (a file system that tells case apart, as Linux's, finds it only as \"" +
                                          spelled + "\")");
        return found;
    }
    std::string searched;
    for (auto const& folder : m_searchPath) searched += "\n    " + folder;
    std::string const near = closestSpelling(name, pluginNames(m_searchPath));
    std::string const hint = near.empty() ? "" : " (did you mean \"" + near + "\"?)";
    refuse(where, std::string(kind) + " plugin \"" + name + "\" not found" + hint + ": no " + name +
                  ".so in any folder of the plugin search path:" + searched +
                  "\n  (add a folder with --plugin-path, $RIX_PLUGIN_PATH or Option \"searchpath\" "
                  "\"string rixplugin\")");
}

std::unique_ptr<ShadingPlugin> PluginLoader::load(ShadingPlugin::Kind kind, std::string const& name,
                                                  SourceLocation const& where) {
    std::string const path = find(name, kind == ShadingPlugin::Kind::Bxdf ? "Bxdf" : "Pattern", where);
    try {
        return std::make_unique<ShadingPlugin>(kind, name, path, m_diagnostics);
    } catch (RibError const&) {
        throw;
    } catch (RenderError const& refused) {
        if (!where.known()) throw;
        throw RibError(where, refused.what());  // the statement that asked for the plugin, first
    }
}

ShadingPlugin& PluginLoader::bxdf(std::string const& name, SourceLocation const& where) {
    auto found = m_plugins.find(name);
    if (found != m_plugins.end()) return *found->second;
    return *m_plugins.emplace(name, load(ShadingPlugin::Kind::Bxdf, name, where)).first->second;
}

ShadingPlugin& PluginLoader::pattern(std::string const& name, SourceLocation const& where) {
    auto found = m_patterns.find(name);
    if (found != m_patterns.end()) return *found->second;
    return *m_patterns.emplace(name, load(ShadingPlugin::Kind::Pattern, name, where)).first->second;
}

std::unique_ptr<IntegratorPlugin> PluginLoader::integrator(std::string const& name, ParamList const& params,
                                                           SourceLocation const& where) {
    return std::make_unique<IntegratorPlugin>(name, find(name, "Integrator", where), params, where, m_diagnostics);
}

namespace {
/// Forwards an integrator's messages and keeps its errors, to report a refusal.
class CapturingMessages final : public RixMessages {
public:
    CapturingMessages(Diagnostics& diagnostics, std::string const& name, SourceLocation const& where)
        : m_forward(diagnostics, name, where) {}
    std::string errors;

protected:
    void Report(Severity severity, const char* message) override {
        if (severity == k_Error) {
            errors += (errors.empty() ? "" : "; ") + std::string(message);
            return;
        }
        m_forward.Warning("%s", message);
    }

private:
    PluginMessages m_forward;
};
}  // namespace

IntegratorPlugin::IntegratorPlugin(std::string name, std::string path, ParamList const& params,
                                   SourceLocation const& where, Diagnostics& diagnostics)
    : m_name(std::move(name)), m_path(std::move(path)), m_library(m_path, "integrator \"" + m_name + "\" (" + m_path + ")") {
    std::string what = "integrator \"" + m_name + "\" (" + m_path + ")";
    auto create = reinterpret_cast<CreateFn>(m_library.symbol("CreateRixIntegrator"));
    m_destroy = reinterpret_cast<DestroyFn>(m_library.symbol("DestroyRixIntegrator"));
    if (!create || !m_destroy)
        throw RenderError(what + ": does not export CreateRixIntegrator and DestroyRixIntegrator "
                                 "(define them with RIX_INTEGRATORCREATE and RIX_INTEGRATORDESTROY)");
    if (std::string why = apiMismatch(m_library); !why.empty()) throw RenderError(what + ": " + why);
    CapturingMessages messages(diagnostics, m_name, where);
    RibParameterList list(params);
    m_integrator = create(&list, &messages);
    if (!m_integrator)
        throw RibError(where, m_name + ": " + (messages.errors.empty() ? "the integrator refused its parameters" : messages.errors));
    params.warnUnused(diagnostics, "Integrator \"" + m_name + "\"");
}

IntegratorPlugin::~IntegratorPlugin() {
    if (m_integrator) m_destroy(m_integrator);
}

}  // namespace bxdflab
