// The scratch folder of one grading: a private temporary folder holding a
// copy of the submission and everything its build and checks write; the
// only folder a sandbox may write. Removed when the grading ends.
#pragma once

#include <string>
#include <vector>

namespace rixgrade {

class Scratch {
public:
    /// A new folder under `parent` (the system's temporary folder when empty).
    explicit Scratch(std::string const& parent = {});
    ~Scratch();  ///< removes the folder and everything in it (unless kept)
    Scratch(Scratch const&) = delete;
    Scratch& operator=(Scratch const&) = delete;

    /// The folder scratch folders go in: `parent`, or else TMPDIR, or else /tmp.
    static std::string parentFolder(std::string const& parent);

    std::string const& path() const { return m_path; }
    void keep() { m_keep = true; }

    struct CopyReport {
        std::vector<std::string> skipped;   ///< what was left out, and why
        std::vector<std::string> lookAt;    ///< files for the instructor to look at (compiled code, embedded data), and why
        unsigned long long bytes = 0;
        int files = 0;
    };
    /// Copies a submission folder into `name` under the scratch folder without
    /// following symbolic links (links are copied as links: inside the sandbox
    /// they can only point at what it sees), leaving out special files, build
    /// and version-control folders, and anything past the size limits.
    CopyReport copySubmission(std::string const& source, std::string const& name) const;
    /// Copies the *.so files of a folder of built plugins into `name`.
    CopyReport copyPlugins(std::string const& source, std::string const& name) const;
    /// Hands the folder to the user the sandboxes run as (when grading as root).
    void handOver() const;
    /// Copies the plugins built in `name` (the regular *.so files of a real
    /// folder, not a link, under the scratch folder) into a folder beside it
    /// that student code may read but not write, and returns that folder. Call
    /// it once the build has ended: from then on no check or render can change
    /// what another loads.
    std::string freezePlugins(std::string const& name);
    /// Puts the plugin file `relative` (under the scratch folder, a regular file)
    /// among the frozen plugins as `name`, in place of the one built there.
    /// Returns false when there is no such file.
    bool freezeAs(std::string const& relative, std::string const& name);
    /// A folder beside the scratch one that only the grader writes (files it
    /// hands to a sandbox read-only); made on first use.
    std::string const& graderFolder();

private:
    std::string m_path;
    std::string m_frozen;  ///< the frozen plugins' folder, once made
    std::string m_grader;  ///< the grader's own folder, once made
    bool m_keep = false;
};

}  // namespace rixgrade
