// Where Rix plugins are looked for, in order:
//   1. --plugin-path (colon-separated)
//   2. $RIX_PLUGIN_PATH
//   3. Option "searchpath" "string rixplugin" in the RIB
//   4. /standardrixpluginpath in rixrender.ini, next to the scene, then in
//      $XDG_CONFIG_HOME/bxdflab/ (default ~/.config/bxdflab/)
//   5. the built-in folders: the solutions, the integrators and the stock plugins of this build.
#pragma once

#include <string>
#include <vector>

namespace bxdflab {

struct PluginSearchInputs {
    std::string commandLine;                 ///< --plugin-path value
    std::vector<std::string> ribSearchPath;  ///< from the scene
    std::string sceneFile;                   ///< for the ini file next to it
};

std::vector<std::string> pluginSearchPath(PluginSearchInputs const& inputs);

/// The /standardrixpluginpath entry of an ini file, relative entries resolved
/// against the file's folder; empty if the file or the entry is absent.
std::vector<std::string> readIniPluginPath(std::string const& iniFile);

/// The folders of plugins built with the renderer (solutions first).
std::vector<std::string> builtinPluginFolders();

std::vector<std::string> splitSearchPath(std::string const& colonSeparated);

}  // namespace bxdflab
