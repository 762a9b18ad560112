#include "app/ImageModule.h"

#include <dlfcn.h>

#include <mutex>

#include "core/Error.h"

namespace bxdflab {
namespace {

class ImageModule final : public ImageFiles {
public:
    explicit ImageModule(std::string path) : m_path(std::move(path)) {}

    ImagePixels read(std::string const& path, std::string const& what) const override {
        return loaded().read(path, what);
    }
    void write(std::string const& path, std::vector<float> const& pixels, int width, int height, int channels,
               std::vector<std::string> const& names) const override {
        loaded().write(path, pixels, width, height, channels, names);
    }
    void makeTexture(std::string const& texture, MadeTexture const& made) const override {
        loaded().makeTexture(texture, made);
    }
    std::unique_ptr<TextureService> openTextures(Diagnostics& diagnostics) const override {
        return loaded().openTextures(diagnostics);
    }

private:
    ImageFiles const& loaded() const {
        std::call_once(m_once, [this] {
            // Never unloaded: OpenImageIO keeps threads and caches for the life of the process.
            void* module = dlopen(m_path.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!module) {
                m_error = dlerror();
                return;
            }
            using Entry = ImageFiles const* (*)();
            auto entry = reinterpret_cast<Entry>(dlsym(module, "bxdflabOpenImageFiles"));
            if (entry) m_files = entry();
            else m_error = "it has no bxdflabOpenImageFiles";
        });
        if (!m_files) throw RenderError("cannot load the image module \"" + m_path + "\" (OpenImageIO): " + m_error);
        return *m_files;
    }

    std::string m_path;
    mutable std::once_flag m_once;
    mutable ImageFiles const* m_files = nullptr;
    mutable std::string m_error;
};

}  // namespace

void useImageModule(std::string const& modulePath) {
    static ImageModule const module(modulePath);
    installImageFiles(&module);
}

}  // namespace bxdflab
