#include "shade/SharedObject.h"

#include <dlfcn.h>

#include "core/Error.h"

namespace bxdflab {

SharedObject::SharedObject(std::string const& path, std::string const& description) {
    dlerror();
    m_handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!m_handle) {
        const char* why = dlerror();
        throw RenderError("cannot load " + description + ": " + (why ? why : "unknown dlopen error"));
    }
}

SharedObject::~SharedObject() {
    if (m_handle) dlclose(m_handle);
}

void* SharedObject::symbol(const char* name) const { return dlsym(m_handle, name); }

}  // namespace bxdflab
