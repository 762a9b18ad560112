// A hostile submission that does no work of its own but hands over a compiled
// plugin of the course (COURSE_PLUGIN, relative to the course's build) that
// does it, or comes close:
//   - built with BORROW_INTEGRATOR, a chapter-11 "mypath" that opens the
//     course's PxrPathTracer, which renders exactly what the grader compares;
//   - otherwise a Bxdf: a chapter-6 "diffuse" that opens the stock PxrDiffuse
//     (the diffuse solution under another name), or a chapter-9 "ggx" that
//     opens PxrDisney (a GGX lobe of its own, loaded by another chapter's scene).
// It looks wherever the plugin could be: the build folder it was compiled in
// (BORROWED: a student knows that path), the course folder inside the sandbox,
// and the folder next to the program that loads it. The grader must leave none
// of them within reach at any stage: the factory then comes back empty.
#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#ifdef BORROW_INTEGRATOR
#include "RixIntegrator.h"
#else
#include "RixBxdf.h"
#endif

namespace {

void* g_handle = nullptr;

/// The course's plugin, opened from the first place that has it (null: none).
void* openBorrowed() {
    char exe[4096] = {};
    ssize_t length = readlink("/proc/self/exe", exe, sizeof exe - 1);
    std::string besideProgram = length > 0 ? std::string(exe, static_cast<size_t>(length)) : std::string();
    besideProgram = besideProgram.substr(0, besideProgram.rfind('/')) + "/../" COURSE_PLUGIN;
    for (std::string const& path : {std::string(BORROWED), std::string("/course/" COURSE_PLUGIN), besideProgram}) {
        if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
            std::fprintf(stderr, "borrowed the course's plugin from %s\n", path.c_str());
            return handle;
        }
    }
    return nullptr;
}

/// The borrowed plugin's entry point `name`, cast to F (null when there is none).
template <class F>
F borrowed(char const* name) {
    if (!g_handle) g_handle = openBorrowed();
    return g_handle ? reinterpret_cast<F>(dlsym(g_handle, name)) : nullptr;
}

}  // namespace

#ifdef BORROW_INTEGRATOR
RIX_INTEGRATORCREATE {
    auto create = borrowed<RixIntegrator* (*)(RixParameterList const*, RixMessages*)>("CreateRixIntegrator");
    return create ? create(params, messages) : nullptr;
}

RIX_INTEGRATORDESTROY {
    if (auto destroy = borrowed<void (*)(RixIntegrator*)>("DestroyRixIntegrator")) destroy(integrator);
}
#else
RIX_BXDFPLUGINCREATE {
    auto create = borrowed<RixBxdfFactory* (*)(char const*)>("CreateRixBxdfFactory");
    return create ? create(hint) : nullptr;
}

RIX_BXDFPLUGINDESTROY {
    if (auto destroy = borrowed<void (*)(RixBxdfFactory*)>("DestroyRixBxdfFactory")) destroy(bxdf);
}
#endif
