// Instancing: archives read from files (ReadArchive), inline archives
// (ArchiveBegin) and retained objects (ObjectBegin / ObjectInstance). Inline
// archives and objects are recorded as requests and replayed where used.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/Folders.h"
#include "core/GitLfs.h"
#include "parse/RibParser.h"
#include "parse/ZipMember.h"
#include "scene/SceneBuilder.h"

namespace bxdflab {
namespace fs = std::filesystem;

namespace {
constexpr long kMaxReplayedRequests = 4'000'000;  // what instancing may expand to
constexpr int kArchiveAncestorLevels = 6;            // how far up from the scene an exporter's project may be

/// An object's handle: a string (RenderMan 19+) or a number (older files), written as the file wrote it.
std::string objectHandle(RequestReader& in) {
    if (in.nextIsString()) return in.string("object handle");
    double const number = in.number("object handle");
    std::ostringstream text;
    text << number;
    return text.str();
}
}  // namespace

void SceneBuilder::readArchive(RequestReader& in) {
    // "${MATDIR}/m_shading.rib", as RenderMan for Maya's presets write.
    std::string name = expanded(in.string("archive file name"));
    in.params().warnUnused(m_diagnostics, "ReadArchive");
    readArchiveNamed(name, in.where());
}

std::vector<fs::path> SceneBuilder::placesToLook(std::string const& name,
                                                 std::vector<std::string> const& searchPath) const {
    if (fs::path(name).is_absolute()) return {fs::path(name)};
    std::vector<fs::path> places;
    auto add = [&](fs::path const& place) {  // each place once ("./a.rib" is "a.rib")
        for (fs::path const& earlier : places)
            if (earlier.lexically_normal() == place.lexically_normal()) return;
        places.push_back(place);
    };
    add(fs::path(currentDirectory()) / name);
    add(fs::path(name));
    for (std::string const& folder : searchPath) add(fs::path(folder) / name);
    return places;
}

void SceneBuilder::readArchiveNamed(std::string const& name, SourceLocation const& where) {
    auto inlineArchive = m_inlineArchives.find(name);
    if (inlineArchive != m_inlineArchives.end()) {
        replay("archive \"" + name + "\"", inlineArchive->second, where);
        return;
    }
    // "bundle.zip!member.rib": the zip file is looked for like any archive,
    // then the member is read out of it.
    std::optional<ZipMemberName> const zipped = splitZipMemberName(name);
    std::string const fileName = zipped ? zipped->zipFile : name;
    auto read = [&](fs::path const& found) {
        if (!zipped) {
            if (fileIsGitLfsPointer(found.string())) {  // the archive's text is not in this clone
                missingFile(where, "archive \"" + found.string() + "\" is " + gitLfsPointerNote("RIB file"));
                return;
            }
            readFile(found.string());
            return;
        }
        ZipMemberName const member{found.string(), zipped->member};
        std::string const problem = zipMemberProblem(member);
        if (!problem.empty()) {
            missingFile(where, "archive \"" + name + "\" not read: " + problem);
            return;
        }
        readFile(member.zipFile + "!" + member.member);
    };
    // A relative name is looked for beside the file that names it, in the
    // folder the renderer runs in (as RenderMan does), then on the search path.
    fs::path const path(fileName);
    std::vector<fs::path> const candidates = placesToLook(fileName, m_archiveSearchPath);
    std::string tried;
    auto exists = [](fs::path const& candidate) {
        std::error_code error;  // a name the file system rejects (too long, ...) is simply not found
        return fs::is_regular_file(candidate, error);
    };
    for (fs::path const& candidate : candidates) {
        tried += "\n    " + candidate.string();
        std::error_code error;
        if (fs::exists(candidate, error) && !fs::is_regular_file(candidate, error) && !fs::is_directory(candidate, error))
            throw RibError(where, "archive \"" + candidate.string() + "\" is not a regular file (a pipe or a device?)");
        if (exists(candidate)) {
            read(candidate);
            return;
        }
    }
    // Exporters write absolute paths of the machine they ran on, as the archive's
    // name or as search-path folders: the same files are often beside the scene,
    // under the end of such a path. The longest end that exists wins.
    std::vector<fs::path> absolutes;
    if (path.is_absolute())
        absolutes.push_back(path);
    else
        for (std::string const& folder : m_archiveSearchPath)
            if (fs::path(folder).is_absolute()) absolutes.push_back(fs::path(folder) / path);
    // Looked for below the including file's folder, the scene's folder, the folder
    // the renderer runs in (each once) and the scene's ancestors (an exporter's
    // project folder holds its scenes a few levels down: <project>/renderman/<scene>/rib/<frame>/).
    fs::path scene = fs::path(m_fileStack.front()).parent_path();
    if (scene.empty()) scene = ".";
    std::vector<fs::path> ancestors;  // the scene folder's parents, nearest first
    fs::path ancestor = absoluteFolder(scene);
    for (int level = 0; level < kArchiveAncestorLevels && ancestor.has_relative_path(); ++level) {
        ancestor = ancestor.parent_path();
        if (ancestor.has_relative_path()) ancestors.push_back(ancestor);
    }
    std::vector<fs::path> nearRoots;
    std::vector<fs::path> nearRootsSpelledOut;  // their absolute spellings, to name each folder once
    std::error_code noWorkingFolder;  // deleted under the renderer: then it is not looked in
    fs::path const workingFolder = fs::current_path(noWorkingFolder);
    for (fs::path const& root : {fs::path(currentDirectory()), scene, workingFolder}) {
        if (root.empty()) continue;
        fs::path const full = absoluteFolder(root);
        if (std::find(nearRootsSpelledOut.begin(), nearRootsSpelledOut.end(), full) != nearRootsSpelledOut.end())
            continue;
        nearRootsSpelledOut.push_back(full);
        nearRoots.push_back(root);
    }
    std::vector<fs::path> roots = nearRoots;
    roots.insert(roots.end(), ancestors.begin(), ancestors.end());
    for (fs::path const& absolute : absolutes) {
        std::vector<fs::path> parts(absolute.begin(), absolute.end());
        for (size_t first = 1; first < parts.size(); ++first) {
            fs::path tail;
            for (size_t k = first; k < parts.size(); ++k) tail /= parts[k];
            for (fs::path const& root : roots) {
                fs::path candidate = root / tail;
                if (!exists(candidate)) continue;
                std::string const whose = absolute == path ? "its path" : "its path on the search path (" + absolute.string() + ")";
                warnOnce("archive by tail", where,
                         "archive \"" + name + "\" not found; reading \"" + candidate.string() + "\", the end of " + whose +
                             " found beside the scene (and so for the other absolute paths)");
                read(candidate);
                return;
            }
        }
    }
    // A project's scene (<project>/rib/scene.rib) names its archives from the
    // folder it was rendered in ("rib/lights.rib"), most often the project's:
    // the scene's ancestors stand in for it when the renderer runs elsewhere.
    if (!path.is_absolute())
        for (fs::path const& parent : ancestors) {
            fs::path const candidate = parent / path;
            tried += "\n    " + candidate.string();
            if (!exists(candidate)) continue;
            warnOnce("archive from an ancestor", where,
                     "archive \"" + name + "\" read from the scene's ancestor folder \"" + parent.string() +
                         "\" (the scene names its archives from there: rendering from that folder finds them as named)");
            read(candidate);
            return;
        }
    if (!absolutes.empty()) {
        std::string under;
        for (fs::path const& root : nearRoots) under += (under.empty() ? "" : ", ") + root.string();
        tried += "\n    (and every end of the absolute paths under " + under + " and the scene's folder's " +
                 std::to_string(ancestors.size()) + " parents)";
    }
    // RenderMan renders on without a missing archive; so does this renderer, unless --strict.
    // An exporter's scene read without its archive files names dozens: after
    // the first few, each is one line.
    m_archiveMissing = true;
    int constexpr kListedWithPlacesTried = 3;
    if (++m_archivesNotFound <= kListedWithPlacesTried || m_options.strict)
        missingFile(where, "archive \"" + name + "\" not found; tried:" + tried);
    else
        missingFile(where, "archive \"" + name + "\" not found (looked for as the archives above)");
}

void SceneBuilder::procedural(RequestReader& in) {
    std::string kind = in.string("procedural type");
    std::vector<std::string> arguments = in.stringArray("procedural arguments");
    std::vector<float> const bound = in.numberArray("bound");
    in.finish();
    // A delayed archive is read when a ray first reaches its bound; reading it
    // now gives the same picture.
    if (kind == "DelayedReadArchive" && !arguments.empty()) {
        readArchiveNamed(arguments.front(), in.where());
        return;
    }
    if (kind == "RunProgram" && m_options.runPrograms && !arguments.empty()) {
        runProgram(arguments[0], arguments.size() > 1 ? arguments[1] : "", bound, in.where());
        return;
    }
    warnProcedural(kind, arguments.empty() ? "" : arguments.front(), in.where());
}

void SceneBuilder::procedural2(RequestReader& in) {
    // RenderMan 21+: Procedural2 "DelayedReadArchive2" "SimpleBound" "string filename" [...] "float[6] bound" [...]
    std::string kind = in.string("procedural type");
    in.string("bound function");
    ParamList params = in.params();
    if (kind == "DelayedReadArchive2") {
        std::string file = params.getString("filename", "");
        params.ignore("bound");
        params.warnUnused(m_diagnostics, "Procedural2 \"DelayedReadArchive2\"");
        if (file.empty()) {
            warnOnce("procedural without file", in.where(), "Procedural2 \"DelayedReadArchive2\" names no \"filename\"; skipped");
            return;
        }
        readArchiveNamed(file, in.where());
        return;
    }
    std::string const program = kind == "DynamicLoad" ? params.getString("dsoname", "") : "";
    for (auto const& p : params.all()) p.used = true;  // the plugin's own parameters
    warnProcedural(kind, program, in.where());
}

std::unique_ptr<ProceduralProgram> SceneBuilder::startProgram(std::string const& program, std::string& file,
                                                              SourceLocation const& where) {
    std::istringstream words(program);
    std::string name;
    words >> name;
    std::vector<std::string> arguments;
    for (std::string word; words >> word;) arguments.push_back(word);
    if (name.empty()) throw RenderError("it names no program");
    // A bare name not found where procedurals are looked for may also be a command on PATH.
    std::string searched;
    ProgramLaunch launch;
    for (fs::path const& candidate : placesToLook(name, m_proceduralSearchPath)) {
        searched += "\n    " + candidate.string();
        std::error_code error;
        if (!fs::is_regular_file(candidate, error)) continue;
        file = candidate.string();
        launch = programLaunch(file, arguments);
        break;
    }
    if (launch.command.empty() && name.find('/') == std::string::npos && launchInterpreter(name, launch)) {
        // "python3 spiral.py", say: its output's messages and names are taken as from beside the scene file.
        file = (fs::path(currentDirectory()) / name).string();
        launch.command.insert(launch.command.end(), arguments.begin(), arguments.end());
    }
    if (launch.command.empty())
        throw RenderError("the program is not in any place searched:" + searched + "\n    (nor on PATH)");
    if (!launch.note.empty())
        m_diagnostics.info(where.str() + ": Procedural \"RunProgram\" (\"" + program + "\"): " + launch.note);
    // It runs in the folder of the file that names it, where its own relative names most likely point.
    return std::make_unique<ProceduralProgram>(launch, currentDirectory());
}

void SceneBuilder::runProgram(std::string const& program, std::string const& datablock,
                              std::vector<float> const& bound, SourceLocation const& where) {
    if (m_failedPrograms.count(program)) return;  // its failure was said the first time
    std::string rib;
    auto running = m_programs.find(program);
    try {
        if (running == m_programs.end()) {
            RunningProgram started;
            started.process = startProgram(program, started.file, where);
            running = m_programs.emplace(program, std::move(started)).first;
        }
        // The program may choose what to make by how large its bound is on the image, as Detail does.
        float const detail =
            bound.size() == 6 && m_inWorld ? rasterArea(bound) * m_scene.relativeDetail : kInfinity;
        rib = running->second.process->generate(std::min(detail, 1e37f), datablock);
    } catch (RenderError const& problem) {
        if (running != m_programs.end()) m_programs.erase(running);
        m_failedPrograms.insert(program);
        m_diagnostics.warn(where.str() + ": Procedural \"RunProgram\" (\"" + program + "\"): " +
                           problem.what() + "; its geometry is skipped (and so for its other procedurals)");
        return;
    }
    // What it writes is read as if it stood here, inside an attribute block of its own: what it sets
    // stays in its geometry. Messages point into its output; relative names in it resolve beside it.
    if (static_cast<int>(m_fileStack.size()) >= kMaxArchiveDepth)
        throw RibError(
            where, "procedurals and archives nested more than " + std::to_string(kMaxArchiveDepth) + " deep");
    std::string const outputName = running->second.file + " (output)";
    size_t const depth = m_blocks.size();
    m_attributes.push_back(state());
    m_blocks.push_back(Block::Attribute);
    m_fileStack.push_back(outputName);
    parseRib(rib, outputName, [this](RibRequest const& r) { handle(r); });
    m_fileStack.pop_back();
    if (m_blocks.size() != depth + 1 || m_blocks.back() != Block::Attribute)
        throw RibError(where,
                       "Procedural \"RunProgram\" (\"" + program +
                           "\"): its output does not close every AttributeBegin and TransformBegin it opens, "
                           "or closes one it did not open");
    m_blocks.pop_back();
    m_attributes.pop_back();
}

void SceneBuilder::warnProcedural(std::string const& kind, std::string const& program, SourceLocation const& where) {
    if (kind == "RunProgram") {
        warnOnce("procedural " + kind, where,
                 "Procedural \"RunProgram\"" + (program.empty() ? "" : " (\"" + program + "\")") +
                     ": a scene's programs run only when asked for (rixrender --run-programs), as running one is "
                     "running the scene's code; its geometry is skipped");
        return;
    }
    if (kind != "DynamicLoad" || program.empty()) {
        warnOnce("procedural " + kind, where, "Procedural \"" + kind + "\" is not a procedural this renderer knows; skipped");
        return;
    }
    // A procedural plugin speaks RenderMan's C interface (Ri calls), which this
    // renderer does not offer: it is never loaded. Saying where it would have
    // been looked for still tells the reader whether the file is even there.
    fs::path found;
    std::string searched;
    for (fs::path const& candidate : placesToLook(program, m_proceduralSearchPath)) {
        fs::path const folder = candidate.parent_path();
        searched += "\n    " + (folder.empty() ? std::string(".") : folder.string());
        std::error_code error;
        if (fs::is_regular_file(candidate, error)) {
            found = candidate;
            break;
        }
    }
    std::string const name = "Procedural \"DynamicLoad\" (\"" + program + "\")";
    if (found.empty())
        warnOnce("procedural " + kind, where,
                 name + ": the plugin is not in any folder searched:" + searched +
                     "\n  and a RenderMan procedural plugin is not loaded here in any case; its geometry is skipped");
    else
        warnOnce("procedural " + kind, where,
                 name + ": " + found.string() +
                     " is a RenderMan procedural plugin (Ri C interface), which this renderer does not load; its "
                     "geometry is skipped");
}

void SceneBuilder::objectBegin(RequestReader& in) {
    // The handle may be a string (RenderMan 19+) or a number (older RIBs).
    std::string handle = objectHandle(in);
    in.finish();
    startRecording(m_objects[handle], "ObjectEnd");
}

void SceneBuilder::objectInstance(RequestReader& in) {
    std::string handle = objectHandle(in);
    in.finish();
    auto found = m_objects.find(handle);
    if (found == m_objects.end()) {
        std::string const message = "no object \"" + handle + "\" was defined with ObjectBegin";
        // Its ObjectBegin may be in an archive that was not found (a warning): then render on without it.
        if (!m_archiveMissing) in.fail(in.where(), message);
        warnOnce("undefined object", in.where(), message + " (perhaps in the archive not found above); skipped");
        return;
    }
    replay("object \"" + handle + "\"", found->second, in.where());
}

void SceneBuilder::archiveBegin(RequestReader& in) {
    std::string name = in.string("archive name");
    in.params();
    startRecording(m_inlineArchives[name], "ArchiveEnd");
}

void SceneBuilder::startRecording(Recording& slot, std::string const& end) {
    slot = std::make_shared<std::vector<RibRequest>>();
    m_recording = slot.get();
    m_recordingEnd = end;
}

void SceneBuilder::replay(std::string const& what, Recording requests, SourceLocation const& where) {
    if (!m_replaying.insert(what).second)
        throw RibError(where, what + " is used inside its own definition (directly or through another one)");
    m_replayedRequests += static_cast<long>(requests->size());
    if (m_replayedRequests > kMaxReplayedRequests)
        throw RibError(where, "instancing expands to more than " + std::to_string(kMaxReplayedRequests) +
                                  " requests (objects that instance others many times over?)");
    // An instance sees the graphics state in effect where it is used, and
    // leaves it as it found it.
    m_attributes.push_back(state());
    size_t depth = m_blocks.size();
    for (RibRequest const& request : *requests) handle(request);
    if (m_blocks.size() != depth) throw RibError(requests->back().where, "unbalanced blocks inside an object or archive");
    m_attributes.pop_back();
    m_replaying.erase(what);
}

}  // namespace bxdflab
