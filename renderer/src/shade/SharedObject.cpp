#include "shade/SharedObject.h"

#include <dlfcn.h>
#include <link.h>

#include <cxxabi.h>

#include <cstdlib>
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

SharedObject::Elsewhere SharedObject::inAnotherPlugin(void const* address) const {
    link_map* self = nullptr;
    Dl_info where;
    if (!address || dlinfo(m_handle, RTLD_DI_LINKMAP, &self) != 0 || !self || !dladdr(address, &where) ||
        !where.dli_fname || (self->l_name && std::strcmp(where.dli_fname, self->l_name) == 0))
        return {};
    // Only a plugin counts: a table kept in a helper library the plugin links is its own affair.
    void* other = dlopen(where.dli_fname, RTLD_NOW | RTLD_NOLOAD);
    if (!other) return {};
    bool const plugin = dlsym(other, "CreateRixBxdfFactory") || dlsym(other, "CreateRixPattern");
    dlclose(other);
    if (!plugin) return {};
    std::string symbol = where.dli_sname ? where.dli_sname : "";
    int status = 0;
    if (char* readable = abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status)) {
        if (status == 0) symbol = readable;
        std::free(readable);
    }
    return {where.dli_fname, symbol};
}

}  // namespace bxdflab
