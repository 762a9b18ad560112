// The helper program of a Procedural "RunProgram": a process that makes RIB
// on request. It is started once and asked again for each procedural that
// names it, as RenderMan does: a line "detail datablock" goes to its standard
// input, and it answers with RIB on its standard output, ended by the byte 0xFF.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace bxdflab {

/// How a program is started.
struct ProgramLaunch {
    std::vector<std::string> command;      ///< the program, then its arguments
    std::vector<std::string> environment;  ///< "NAME=value" settings added to the renderer's own
    std::string note;                      ///< what stands in for what the program asked for, if anything
};

class ProceduralProgram {
   public:
    static constexpr int kSilenceLimitMilliseconds = 120'000;  ///< a program quiet this long is taken to hang

    /// Starts the program in `folder`; throws RenderError if it cannot.
    ProceduralProgram(ProgramLaunch const& launch, std::string const& folder,
                      int silenceLimitMilliseconds = kSilenceLimitMilliseconds);
    /// Closes the program's input, so that it ends; stops it if it does not end soon after.
    ~ProceduralProgram();
    ProceduralProgram(ProceduralProgram const&) = delete;
    ProceduralProgram& operator=(ProceduralProgram const&) = delete;

    /// The RIB the program writes for one procedural. Throws RenderError if the program
    /// ends, or stays silent too long, before its end mark.
    std::string generate(float detail, std::string const& datablock);

   private:
    /// Closes the pipes, gives the program `timeToEnd` to end, then stops it and what it started.
    void stop(std::chrono::milliseconds timeToEnd);

    int m_silenceLimitMilliseconds;
    pid_t m_process = -1;
    int m_toProgram = -1;    ///< the program's standard input
    int m_fromProgram = -1;  ///< its standard output
};

/// `name` looked for in the folders of PATH; empty if it is in none.
std::string programOnPath(std::string const& name);

/// Sets `launch` to start `wanted` (a path, or a name looked for on PATH) ahead of its arguments:
/// python3 stands in for RenderMan's own python (rmanpy) and for a python that is not here, and
/// the note then says so. False if there is no such program.
bool launchInterpreter(std::string const& wanted, ProgramLaunch& launch);

/// How a program file is started: its "#!" interpreter (see launchInterpreter), then the file, then
/// `arguments`; a file without "#!" is run itself. Throws RenderError if its interpreter is not here.
ProgramLaunch programLaunch(std::string const& file, std::vector<std::string> const& arguments);

}  // namespace bxdflab
