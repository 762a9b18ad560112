#include "shade/MemoryArena.h"

#include <algorithm>
#include <cstdint>

namespace bxdflab {

void* MemoryArena::allocate(size_t bytes, size_t alignment) {
    alignment = std::max<size_t>(alignment, alignof(std::max_align_t));
    bytes = std::max<size_t>(bytes, 1);
    for (;;) {
        if (m_current < m_blocks.size()) {
            Block& block = m_blocks[m_current];
            auto base = reinterpret_cast<std::uintptr_t>(block.memory.get());
            std::uintptr_t aligned = (base + m_offset + alignment - 1) & ~(alignment - 1);
            size_t end = static_cast<size_t>(aligned - base) + bytes;
            if (end <= block.size) {
                m_offset = end;
                return reinterpret_cast<void*>(aligned);
            }
            ++m_current;
            m_offset = 0;
            continue;
        }
        size_t size = std::max(m_blockSize, bytes + alignment);
        m_blocks.push_back({std::make_unique<std::byte[]>(size), size});
        m_current = m_blocks.size() - 1;
        m_offset = 0;
    }
}

void MemoryArena::reset() {
    // Keep the blocks of ordinary size for reuse; drop oversized ones.
    std::vector<Block> kept;
    for (auto& block : m_blocks)
        if (block.size == m_blockSize) kept.push_back(std::move(block));
    m_blocks = std::move(kept);
    m_current = 0;
    m_offset = 0;
}

}  // namespace bxdflab
