// A loaded shared object (dlopen with RTLD_LOCAL), closed when destroyed.
#pragma once

#include <string>

namespace bxdflab {

class SharedObject {
public:
    /// Throws RenderError with dlerror()'s reason when the file cannot be loaded.
    SharedObject(std::string const& path, std::string const& description);
    ~SharedObject();
    SharedObject(SharedObject const&) = delete;
    SharedObject& operator=(SharedObject const&) = delete;

    /// The address of an exported symbol, or nullptr.
    void* symbol(const char* name) const;
    /// The symbol only if this object defines it itself (not one of the
    /// libraries it depends on, nor the program that loaded it), or nullptr.
    void* ownSymbol(const char* name) const;

private:
    void* m_handle = nullptr;
};

}  // namespace bxdflab
