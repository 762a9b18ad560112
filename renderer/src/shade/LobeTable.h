// The renderer's table of named lobes (RixLPEInfo): every lobe name a plugin
// looks up gets a light path expression id within its kind, the same for all
// plugins and renders in the process. The ids tell lobes apart in the weight
// arrays and lobe sets (RixBxdfLobe.h).
#pragma once

#include <map>
#include <mutex>
#include <string>

#include "RixInterfaces.h"

namespace bxdflab {

class LobeTable final : public RixLPEInfo {
public:
    /// The one table of the process.
    static LobeTable& instance();
    unsigned char GetLpeIdByName(bool specular, bool user, const char* name) override;

private:
    std::mutex m_mutex;
    std::map<std::string, unsigned char> m_ids[3];  ///< diffuse, specular, user
};

}  // namespace bxdflab
