#include "shade/BatchMemory.h"

#include <algorithm>

namespace bxdflab {

void* BatchMemory::allocateOwn(size_t bytes, size_t alignment) {
    alignment = std::max<size_t>(alignment, alignof(std::max_align_t));
    size_t space = std::max<size_t>(bytes, 1) + alignment;
    m_own.push_back(std::unique_ptr<std::byte[]>(new std::byte[space]));
    void* start = m_own.back().get();
    return std::align(alignment, std::max<size_t>(bytes, 1), start, space);
}

}  // namespace bxdflab
