#include "film/OiioTextures.h"

#include <OpenImageIO/texture.h>

#include <filesystem>
#include <map>
#include <mutex>

#include "film/OiioImageFiles.h"

namespace bxdflab {
namespace {

class OiioTextures final : public TextureService {
public:
    explicit OiioTextures(Diagnostics& diagnostics)
        : m_diagnostics(diagnostics), m_system(OIIO::TextureSystem::create(/*shared=*/true)) {
        // The process-wide texture system: its tile cache outlives one render
        // (frames and test renders reuse it) and is never destroyed here --
        // OpenImageIO 2.4's destroy() of a private one deletes it with the
        // wrong size, which AddressSanitizer rightly reports.
        // Tiles stay within a fixed budget however large or many the textures;
        // plain (untiled, unmipped) images are tiled and mip-mapped in memory.
        m_system->attribute("max_memory_MB", 256.0f);
        m_system->attribute("autotile", 64);
        m_system->attribute("automip", 1);
        // A grey image is grey in a colour lookup, as in RenderMan (not red with black green and blue).
        m_system->attribute("gray_to_rgb", 1);
    }

    void setLocator(TextureLocator locator) override { m_locator = std::move(locator); }

    int Texture(RtUString filename, TxParams const& params, int numPts, RtFloat2 const* st, RtFloat const* width,
                int numChannels, RtFloat* result) override {
        numChannels = std::clamp(numChannels, 1, 4);
        OIIO::TextureSystem::TextureHandle* handle = open(filename.CStr());
        auto fillMissing = [&](int from) {
            for (int i = from; i < numPts; ++i)
                for (int c = 0; c < numChannels; ++c)
                    result[i * numChannels + c] = c < 3 ? params.missingColor[c] : 1.0f;
        };
        if (!handle) {
            fillMissing(0);
            return 1;
        }
        OIIO::TextureOpt options;
        options.firstchannel = params.firstChannel;
        options.fill = 1.0f;  // channels the image does not have: an RGB image's alpha is opaque
        options.swrap = options.twrap = params.periodic ? OIIO::TextureOpt::WrapPeriodic : OIIO::TextureOpt::WrapClamp;
        OIIO::TextureSystem::Perthread* thread = m_system->get_perthread_info();
        for (int i = 0; i < numPts; ++i) {
            float w = width ? std::max(width[i], 0.0f) : 0.0f;
            // An axis-aligned footprint of side w: ds/dx = w, dt/dy = w.
            if (!m_system->texture(handle, thread, options, st[i].x, st[i].y, w, 0.0f, 0.0f, w, numChannels,
                                   result + i * numChannels)) {
                m_diagnostics.warn("texture \"" + std::string(filename.CStr()) + "\": " + m_system->geterror() +
                                   "; its lookups return missingColor");
                fillMissing(i);
                return 1;
            }
        }
        m_lookups.fetch_add(static_cast<uint64_t>(numPts), std::memory_order_relaxed);
        return 0;
    }

private:
    /// The file's handle, checked once: null (and one warning) when it cannot be read or is too large.
    OIIO::TextureSystem::TextureHandle* open(std::string const& name) {
        std::lock_guard<std::mutex> lock(m_lock);
        auto found = m_files.find(name);
        if (found != m_files.end()) return found->second;
        OIIO::TextureSystem::TextureHandle* handle = nullptr;
        OIIO::ImageSpec spec;
        OIIO::ustring file(m_locator.find(name).value_or(name));
        if (name.empty()) {
            m_diagnostics.warn("a texture lookup names no file; it returns missingColor");
        } else if (!m_system->get_imagespec(file, 0, spec)) {
            std::string why = m_system->geterror(), pointer = notAnImageBecause(file.string());
            why = why.substr(0, why.find('\n'));  // OpenImageIO says it again on a second line
            if (m_locator.reportedMissing.count(name)) {
                // said with its RIB line when the scene was read
            } else if (std::error_code error; !std::filesystem::exists(file.string(), error)) {
                m_diagnostics.warn("texture \"" + name + "\" does not exist (looked for from " +
                                   m_locator.searchedPlaces() + "); its lookups return missingColor");
            } else {
                m_diagnostics.warn("texture \"" + name + "\" cannot be read (" + (pointer.empty() ? why : pointer) +
                                   "); its lookups return missingColor");
            }
        } else if (spec.width > kMaxImageSide || spec.height > kMaxImageSide ||
                   static_cast<long long>(spec.width) * spec.height > kMaxImagePixels || spec.depth > 1) {
            m_diagnostics.warn("texture \"" + name + "\" declares " + std::to_string(spec.width) + " x " +
                               std::to_string(spec.height) + " pixels, more than the " + std::to_string(kMaxImageSide) +
                               " a side this renderer reads; its lookups return missingColor");
        } else {
            handle = m_system->get_texture_handle(file);
        }
        m_files.emplace(name, handle);
        return handle;
    }

    Diagnostics& m_diagnostics;
    TextureLocator m_locator;
    OIIO::TextureSystem* m_system;
    std::mutex m_lock;
    std::map<std::string, OIIO::TextureSystem::TextureHandle*> m_files;
};

}  // namespace

std::unique_ptr<TextureService> makeOiioTextures(Diagnostics& diagnostics) {
    return std::make_unique<OiioTextures>(diagnostics);
}

}  // namespace bxdflab
