#include "shade/PluginSearchPath.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Variables.h"

namespace bxdflab {
namespace fs = std::filesystem;

std::vector<std::string> splitSearchPath(std::string const& colonSeparated) {
    std::vector<std::string> parts;
    std::stringstream in(colonSeparated);
    for (std::string item; std::getline(in, item, ':');)
        if (!item.empty()) parts.push_back(item);
    return parts;
}

std::vector<std::string> readIniPluginPath(std::string const& iniFile) {
    std::ifstream in(iniFile);
    if (!in) return {};
    std::vector<std::string> folders;
    fs::path base = fs::path(iniFile).parent_path();
    // As RenderMan's ini files write ${RMANTREE}: an unset variable is empty.
    auto unsetIsEmpty = [](std::string const& name) { return environmentVariable(name).value_or(""); };
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string key, value;
        if (!(words >> key) || key[0] == '#') continue;
        if (key != "/standardrixpluginpath") continue;
        std::getline(words >> std::ws, value);
        for (std::string const& item : splitSearchPath(expandVariables(value, unsetIsEmpty))) {
            if (item == "@" || item == "&") continue;  // RenderMan's "the default" and "the path so far"
            fs::path path(item);
            folders.push_back(path.is_relative() ? (base / path).lexically_normal().string() : item);
        }
    }
    return folders;
}

std::vector<std::string> builtinPluginFolders() {
    std::vector<std::string> folders;
    // Relative to the executable (build/bin/../plugins/...), so a moved build still works.
    std::error_code error;
    fs::path exe = fs::read_symlink("/proc/self/exe", error);
    for (const char* collection : {"solutions", "integrators", "stock"}) {
        if (!error) folders.push_back((exe.parent_path().parent_path() / "plugins" / collection).string());
#ifdef BXDFLAB_PLUGIN_ROOT
        std::string configured = std::string(BXDFLAB_PLUGIN_ROOT) + "/" + collection;
        if (folders.empty() || fs::path(folders.back()) != fs::path(configured)) folders.push_back(configured);
#endif
    }
    return folders;
}

std::vector<std::string> pluginSearchPath(PluginSearchInputs const& inputs) {
    std::vector<std::string> folders = splitSearchPath(inputs.commandLine);
    if (const char* env = std::getenv("RIX_PLUGIN_PATH"))
        for (auto const& f : splitSearchPath(env)) folders.push_back(f);
    folders.insert(folders.end(), inputs.ribSearchPath.begin(), inputs.ribSearchPath.end());

    // This renderer's rixrender.ini, and RenderMan's rendermn.ini / renderman.ini
    // (as the course text sets up a plugin folder): beside the scene, in the
    // folder the renderer runs in, in the user's home, then in $RMANTREE/etc.
    std::vector<std::string> iniFiles;
    auto addFolder = [&iniFiles](fs::path const& dir, std::vector<char const*> const& names) {
        for (char const* name : names) {
            std::string file = (dir / name).string();
            if (std::find(iniFiles.begin(), iniFiles.end(), file) == iniFiles.end()) iniFiles.push_back(file);
        }
    };
    if (!inputs.sceneFile.empty()) {
        fs::path dir = fs::path(inputs.sceneFile).parent_path();
        addFolder(dir.empty() ? fs::path(".") : dir, {"rixrender.ini", "rendermn.ini", "renderman.ini"});
    }
    addFolder(".", {"rendermn.ini", "renderman.ini"});
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"))
        iniFiles.push_back(std::string(xdg) + "/bxdflab/rixrender.ini");
    else if (const char* home = std::getenv("HOME"))
        iniFiles.push_back(std::string(home) + "/.config/bxdflab/rixrender.ini");
    if (const char* home = std::getenv("HOME")) addFolder(home, {".rendermn.ini", ".renderman.ini"});
    if (const char* tree = std::getenv("RMANTREE")) addFolder(fs::path(tree) / "etc", {"rendermn.ini", "renderman.ini"});
    for (auto const& ini : iniFiles)
        for (auto const& f : readIniPluginPath(ini)) folders.push_back(f);

    for (auto const& f : builtinPluginFolders()) folders.push_back(f);
    return folders;
}

}  // namespace bxdflab
