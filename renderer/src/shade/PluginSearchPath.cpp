#include "shade/PluginSearchPath.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

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
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string key, value;
        if (!(words >> key) || key[0] == '#') continue;
        if (key != "/standardrixpluginpath") continue;
        std::getline(words >> std::ws, value);
        for (std::string const& item : splitSearchPath(value)) {
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

    std::vector<std::string> iniFiles;
    if (!inputs.sceneFile.empty()) {
        fs::path dir = fs::path(inputs.sceneFile).parent_path();
        iniFiles.push_back(((dir.empty() ? fs::path(".") : dir) / "rixrender.ini").string());
    }
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"))
        iniFiles.push_back(std::string(xdg) + "/bxdflab/rixrender.ini");
    else if (const char* home = std::getenv("HOME"))
        iniFiles.push_back(std::string(home) + "/.config/bxdflab/rixrender.ini");
    for (auto const& ini : iniFiles)
        for (auto const& f : readIniPluginPath(ini)) folders.push_back(f);

    for (auto const& f : builtinPluginFolders()) folders.push_back(f);
    return folders;
}

}  // namespace bxdflab
