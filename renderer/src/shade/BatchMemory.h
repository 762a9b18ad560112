// The memory one shading context hands out: its builtins, parameter values and
// pattern outputs, and what plugins Allocate from it. All of it must last as
// long as the context does.
//
// It comes from the shared arena, which frees memory a mark at a time. While
// the context's own mark is the innermost one, that is right. But an
// integrator may come back to the context from inside a deeper mark (a
// TraceIndirect callback, which shades the next bounce while this batch is
// still open); what the arena gives then is freed when the deeper mark is,
// long before the context ends. Those requests get memory of the context's
// own instead, freed with it.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "shade/MemoryArena.h"

namespace bxdflab {

class BatchMemory {
public:
    explicit BatchMemory(MemoryArena& arena) : m_arena(arena), m_depth(arena.depth()) {}
    BatchMemory(BatchMemory const&) = delete;
    BatchMemory& operator=(BatchMemory const&) = delete;

    void* allocate(size_t bytes, size_t alignment) {
        return m_arena.depth() == m_depth ? m_arena.allocate(bytes, alignment) : allocateOwn(bytes, alignment);
    }
    template <typename T> T* allocArray(size_t count) {
        return static_cast<T*>(allocate(sizeof(T) * count, alignof(T)));
    }

private:
    void* allocateOwn(size_t bytes, size_t alignment);

    MemoryArena& m_arena;
    size_t m_depth;  ///< the arena's depth when the context began
    std::vector<std::unique_ptr<std::byte[]>> m_own;
};

}  // namespace bxdflab
