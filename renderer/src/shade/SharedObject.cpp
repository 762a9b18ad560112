#include "shade/SharedObject.h"

#include <dlfcn.h>
#include <link.h>

#include <cstring>

#include "core/CrashReport.h"
#include "core/Error.h"

namespace bxdflab {

SharedObject::SharedObject(std::string const& path, std::string const& description) {
    dlerror();
    m_handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!m_handle) {
        const char* why = dlerror();
        throw RenderError("cannot load " + description + ": " + (why ? why : "unknown dlopen error"));
    }
    link_map* loaded = nullptr;
    if (dlinfo(m_handle, RTLD_DI_LINKMAP, &loaded) == 0 && loaded && loaded->l_name)
        crashreport::notePlugin(loaded->l_name);  // a crash in its code will be put on it
}

SharedObject::~SharedObject() {
    if (m_handle) dlclose(m_handle);
}

void* SharedObject::symbol(const char* name) const { return dlsym(m_handle, name); }

void* SharedObject::ownSymbol(const char* name) const {
    void* address = symbol(name);
    link_map* self = nullptr;
    Dl_info where;
    if (!address || dlinfo(m_handle, RTLD_DI_LINKMAP, &self) != 0 || !self || !dladdr(address, &where)) return nullptr;
    // dladdr names the object that contains the address by the same link-map name.
    return where.dli_fname && self->l_name && std::strcmp(where.dli_fname, self->l_name) == 0 ? address : nullptr;
}

}  // namespace bxdflab
