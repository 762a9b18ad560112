#include "shade/MemoryArena.h"

#include <algorithm>
#include <cstdint>

namespace bxdflab {

void* MemoryArena::alignWithin(Allocation const& a, size_t& offset, size_t bytes, size_t alignment) {
    auto base = reinterpret_cast<std::uintptr_t>(a.memory.get());
    std::uintptr_t aligned = (base + offset + alignment - 1) & ~(alignment - 1);
    size_t end = static_cast<size_t>(aligned - base) + bytes;
    if (end > a.size) return nullptr;
    offset = end;
    return reinterpret_cast<void*>(aligned);
}

void* MemoryArena::allocate(size_t bytes, size_t alignment) {
    alignment = std::max<size_t>(alignment, alignof(std::max_align_t));
    bytes = std::max<size_t>(bytes, 1);
    if (bytes + alignment > m_blockSize) {
        m_large.push_back(takeLarge(bytes + alignment));
        size_t offset = 0;
        return alignWithin(m_large.back(), offset, bytes, alignment);
    }
    // Fill the current block; move on to the next (kept or new) when it is full.
    // Every block is big enough for this request once it is empty.
    for (;;) {
        if (m_current == m_blocks.size()) m_blocks.push_back({std::make_unique<std::byte[]>(m_blockSize), m_blockSize});
        if (void* p = alignWithin(m_blocks[m_current], m_offset, bytes, alignment)) return p;
        ++m_current;
        m_offset = 0;
    }
}

// Batches of the same size ask for the same large arrays again and again;
// handing back a released one avoids a fresh zero-filled mapping from the
// system each time (page faults were a quarter of a check process's time).
MemoryArena::Allocation MemoryArena::takeLarge(size_t size) {
    auto best = m_spare.end();
    for (auto it = m_spare.begin(); it != m_spare.end(); ++it)
        if (it->size >= size && (best == m_spare.end() || it->size < best->size)) best = it;
    if (best != m_spare.end()) {
        Allocation a = std::move(*best);
        m_spare.erase(best);
        return a;
    }
    // None fits: the spares are smaller than what is asked for now, so free
    // them rather than let them pile up.
    m_spare.clear();
    return {std::unique_ptr<std::byte[]>(new std::byte[size]), size};
}

void MemoryArena::release(Mark const& m) {
    m_current = m.block;
    m_offset = m.offset;
    m_depth = m.depth;
    while (m_large.size() > m.large) {
        m_spare.push_back(std::move(m_large.back()));
        m_large.pop_back();
    }
}

size_t MemoryArena::bytesHeld() const {
    size_t total = m_blocks.size() * m_blockSize;
    for (Allocation const& a : m_large) total += a.size;
    for (Allocation const& a : m_spare) total += a.size;
    return total;
}

}  // namespace bxdflab
