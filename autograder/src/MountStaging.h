// Gives the folders a sandbox binds a second path that the user "nobody" can reach.
//
// A grader running as root starts bubblewrap as nobody, and bubblewrap resolves
// every bind source itself, as nobody: a course, class or TMPDIR below a folder
// only root may enter (/root, a mktemp folder) would stop it with "Permission
// denied" -- and a descriptor opened by root does not help, since bubblewrap
// follows it back to the same path. So the forked child, while it is still
// root, enters a private mount namespace, mounts a small tmpfs on an empty
// folder in /tmp and binds each source there; bubblewrap then binds the staged
// paths. None of it is visible outside that child and its sandbox.
#pragma once

#include <string>
#include <vector>

namespace rixgrade {

class MountStaging {
public:
    MountStaging() = default;
    MountStaging(MountStaging const&) = delete;
    MountStaging& operator=(MountStaging const&) = delete;
    ~MountStaging();  ///< removes the (empty, outside the child) staging folder

    /// The staged path of `real`, in the parent before fork. A path that does not
    /// exist is returned unchanged, so that bubblewrap names it in its error.
    std::string stage(std::string const& real);

    /// In the forked child, as root, before it drops to nobody: the namespace, the
    /// tmpfs and the binds. Makes system calls only (a multi-threaded parent's child
    /// may not allocate). True when everything was mounted; false leaves the real
    /// paths to be bound (nothing of the child's view is hidden by a partial attempt).
    bool mountAll() const noexcept;

private:
    struct Entry {
        std::string real, staged;
        bool folder;
    };
    std::string m_folder;
    std::vector<Entry> m_entries;
};

}  // namespace rixgrade
