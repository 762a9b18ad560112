// A hostile chapter-11 submission: instead of a path tracer of its own, its
// "mypath" opens the course's PxrPathTracer and hands back that integrator,
// which renders exactly what the grader compares against. It tries every
// place the reference could be: the build folder it was compiled in (a
// student knows that path), the course folder inside the sandbox, and the
// folder next to the renderer that runs it. The grader must leave none of
// them within reach: the render then fails, and so do the renders and noise
// checks.
#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "RixIntegrator.h"

namespace {

using Create = RixIntegrator* (*)(RixParameterList const*, RixMessages*);
using Destroy = void (*)(RixIntegrator*);
Destroy g_destroy = nullptr;

void* openReference() {
    char exe[4096] = {};
    ssize_t length = readlink("/proc/self/exe", exe, sizeof exe - 1);
    std::string besideRenderer = length > 0 ? std::string(exe, static_cast<size_t>(length)) : std::string();
    besideRenderer = besideRenderer.substr(0, besideRenderer.rfind('/')) + "/../plugins/integrators/PxrPathTracer.so";
    for (std::string const& path : {std::string(REFERENCE_INTEGRATOR), std::string("/course/plugins/integrators/PxrPathTracer.so"),
                                    besideRenderer}) {
        if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
            std::fprintf(stderr, "borrowed the reference integrator from %s\n", path.c_str());
            return handle;
        }
    }
    return nullptr;
}

}  // namespace

RIX_INTEGRATORCREATE {
    void* handle = openReference();
    if (!handle) return nullptr;
    auto create = reinterpret_cast<Create>(dlsym(handle, "CreateRixIntegrator"));
    g_destroy = reinterpret_cast<Destroy>(dlsym(handle, "DestroyRixIntegrator"));
    return create ? create(params, messages) : nullptr;
}

RIX_INTEGRATORDESTROY {
    if (g_destroy) g_destroy(integrator);
}
