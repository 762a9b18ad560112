#include "scene/ProceduralProgram.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/Error.h"

extern char** environ;

namespace bxdflab {
namespace fs = std::filesystem;

namespace {
constexpr size_t kMaxOutputBytes = size_t(1) << 30;    // more RIB than this for one procedural is a runaway
constexpr std::chrono::milliseconds kTimeToEnd(2000);  // after its input closes, before it is stopped
constexpr std::chrono::milliseconds kNoTime(0);        // for a program that failed: stopped at once
constexpr char kEndMark = '\377';

std::string systemMessage() { return std::strerror(errno); }
}  // namespace

std::string programOnPath(std::string const& name) {
    char const* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "/usr/bin:/bin");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        fs::path const candidate = fs::path(folder.empty() ? "." : folder) / name;
        if (access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) return candidate.string();
    }
    return "";
}

bool launchInterpreter(std::string const& wanted, ProgramLaunch& launch) {
    std::string found = fs::path(wanted).is_absolute() ? (access(wanted.c_str(), X_OK) == 0 ? wanted : "")
                                                        : programOnPath(wanted);
    std::string const base = fs::path(wanted).filename().string();
    bool const python = base.rfind("python", 0) == 0 || base.rfind("rmanpy", 0) == 0;
    if (found.empty() && python) {
        // RenderMan runs its procedurals' scripts with its own python, rmanpy; course scripts also name
        // /usr/bin/python, which Debian no longer has. Both run with python3 here.
        found = programOnPath("python3");
        if (!found.empty()) launch.note = "it asks for " + wanted + ", which is not here: it is run with " + found;
    }
    if (found.empty()) return false;
    // Scripts written for python 2 end each answer with sys.stdout.write("\377"). Written as Latin-1, as
    // python 2 writes it, that is the byte 0xFF; python 3's UTF-8 would make two bytes and no end mark.
    if (python) launch.environment.push_back("PYTHONIOENCODING=latin-1");
    launch.command.push_back(found);
    return true;
}

ProgramLaunch programLaunch(std::string const& file, std::vector<std::string> const& arguments) {
    std::ifstream in(file);
    std::string firstLine;
    std::getline(in, firstLine);
    ProgramLaunch launch;
    if (firstLine.rfind("#!", 0) == 0) {
        std::istringstream words(firstLine.substr(2));
        std::string interpreter, option;
        words >> interpreter >> option;
        std::string wanted = interpreter;  // "#!/usr/bin/env python3" wants python3 from PATH
        if (fs::path(interpreter).filename() == "env") {
            wanted = option;
            option.clear();
        }
        if (!launchInterpreter(wanted, launch))
            throw RenderError("its first line asks for \"" + wanted + "\", which is not here");
        if (!option.empty()) launch.command.push_back(option);
    }
    launch.command.push_back(file);
    launch.command.insert(launch.command.end(), arguments.begin(), arguments.end());
    return launch;
}

ProceduralProgram::ProceduralProgram(ProgramLaunch const& launch, std::string const& folder,
                                     int silenceLimitMilliseconds)
    : m_silenceLimitMilliseconds(silenceLimitMilliseconds) {
    // A program that ends early must not end the renderer with it when it is written to.
    signal(SIGPIPE, SIG_IGN);
    int input[2], output[2];
    if (pipe2(input, O_CLOEXEC) != 0) throw RenderError("cannot make a pipe: " + systemMessage());
    if (pipe2(output, O_CLOEXEC) != 0) {
        close(input[0]);
        close(input[1]);
        throw RenderError("cannot make a pipe: " + systemMessage());
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, input[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, output[1], STDOUT_FILENO);
    posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
    std::vector<char*> argv, environment;
    for (std::string const& word : launch.command) argv.push_back(const_cast<char*>(word.c_str()));
    argv.push_back(nullptr);
    for (std::string const& setting : launch.environment)
        environment.push_back(const_cast<char*>(setting.c_str()));
    for (char** setting = environ; *setting; ++setting) {  // the renderer's own, but for the names set above
        std::string const name(*setting, std::strcspn(*setting, "="));
        bool const replaced = std::any_of(launch.environment.begin(), launch.environment.end(),
                                          [&](std::string const& added) { return added.rfind(name + "=", 0) == 0; });
        if (!replaced) environment.push_back(*setting);
    }
    environment.push_back(nullptr);
    // In a process group of its own, so that stopping it stops what it started too.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    int const failed =
        posix_spawn(&m_process, argv[0], &actions, &attributes, argv.data(), environment.data());
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    close(input[0]);
    close(output[1]);
    m_toProgram = input[1];
    m_fromProgram = output[0];
    if (failed != 0) {
        m_process = -1;
        stop(kNoTime);
        throw RenderError("cannot start \"" + launch.command.front() + "\": " + std::strerror(failed));
    }
}

ProceduralProgram::~ProceduralProgram() { stop(kTimeToEnd); }

void ProceduralProgram::stop(std::chrono::milliseconds timeToEnd) {
    if (m_toProgram >= 0) close(m_toProgram);
    if (m_fromProgram >= 0) close(m_fromProgram);
    m_toProgram = m_fromProgram = -1;
    if (m_process < 0) return;
    auto const deadline = std::chrono::steady_clock::now() + timeToEnd;
    while (waitpid(m_process, nullptr, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() >= deadline) {
            kill(-m_process, SIGKILL);
            waitpid(m_process, nullptr, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    m_process = -1;
}

std::string ProceduralProgram::generate(float detail, std::string const& datablock) {
    if (m_toProgram < 0) throw RenderError("the program has ended");
    std::ostringstream request;
    request << detail << ' ' << datablock << '\n';
    std::string const line = request.str();
    for (size_t written = 0; written < line.size();) {
        ssize_t const n = write(m_toProgram, line.data() + written, line.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            stop(kNoTime);
            throw RenderError("the program has ended (" + systemMessage() + ")");
        }
        written += size_t(n);
    }
    std::string rib;
    char buffer[1 << 16];
    for (;;) {
        pollfd wait{m_fromProgram, POLLIN, 0};
        int const ready = poll(&wait, 1, m_silenceLimitMilliseconds);
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) {
            stop(kNoTime);
            std::ostringstream message;
            message << "the program wrote nothing for " << m_silenceLimitMilliseconds / 1000.0
                    << " s without ending its answer (the byte 0xFF), so it was stopped";
            throw RenderError(message.str());
        }
        ssize_t const n = read(m_fromProgram, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            stop(kTimeToEnd);
            throw RenderError("the program ended after " + std::to_string(rib.size()) +
                              " bytes, without the byte 0xFF that ends its answer");
        }
        char const* end = static_cast<char const*>(std::memchr(buffer, kEndMark, size_t(n)));
        rib.append(buffer, end ? size_t(end - buffer) : size_t(n));
        if (end) return rib;  // the program answers one request at a time: nothing follows the mark
        if (rib.size() > kMaxOutputBytes) {
            stop(kNoTime);
            throw RenderError(
                "the program wrote more than 1 GiB of RIB for one procedural, so it was stopped");
        }
    }
}

}  // namespace bxdflab
