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

    /// Where `address` lies when it is in another loaded plugin (a shared
    /// object that exports a Rix plugin's create function), not this one:
    /// that plugin's file and the symbol there (demangled); empty otherwise.
    struct Elsewhere {
        std::string file, symbol;
    };
    Elsewhere inAnotherPlugin(void const* address) const;

private:
    void* m_handle = nullptr;
};

}  // namespace bxdflab
