// Bump allocator for per-batch memory (shading contexts, Bxdf objects, their
// arrays): no per-point malloc, everything freed at once.
//
// Requests that fit a block are carved from fixed-size blocks that are kept
// and reused; larger requests (a batch's lobe-weight arrays can exceed a
// block) get an allocation of their own that is freed as soon as the mark
// before it is released. Either way, what a render holds is bounded by the
// largest amount live at one time, never by how many batches it shaded.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace bxdflab {

class MemoryArena {
public:
    explicit MemoryArena(size_t blockSize = 256 * 1024) : m_blockSize(blockSize) {}
    MemoryArena(MemoryArena const&) = delete;
    MemoryArena& operator=(MemoryArena const&) = delete;

    void* allocate(size_t bytes, size_t alignment);
    template <typename T> T* allocArray(size_t count) {
        return static_cast<T*>(allocate(sizeof(T) * count, alignof(T)));
    }

    /// A position in the arena. release(mark) frees everything allocated
    /// after mark() was taken, so nested users (a path tracer's bounces) can
    /// free their own memory while an outer batch's stays valid. Marks nest:
    /// each is released before the one taken ahead of it.
    struct Mark {
        size_t block = 0, offset = 0, large = 0;
        size_t depth = 0;  ///< depth() when the mark was taken
    };
    Mark mark() { return {m_current, m_offset, m_large.size(), m_depth++}; }
    void release(Mark const& m);
    /// Frees everything (keeps the blocks for reuse).
    void reset() { release(Mark{}); }
    /// How many marks are taken and not yet released: memory allocated now is
    /// freed when the innermost of them is.
    size_t depth() const { return m_depth; }

    /// Bytes currently held from the system (blocks, large allocations and
    /// released large allocations kept for reuse).
    size_t bytesHeld() const;

private:
    struct Allocation {
        std::unique_ptr<std::byte[]> memory;
        size_t size;
    };
    static void* alignWithin(Allocation const& a, size_t& offset, size_t bytes, size_t alignment);
    Allocation takeLarge(size_t size);

    size_t m_blockSize;
    std::vector<Allocation> m_blocks;  ///< all m_blockSize bytes, reused after release
    std::vector<Allocation> m_large;   ///< one per request too big for a block, in order
    std::vector<Allocation> m_spare;   ///< released large allocations, reused by later large requests
    size_t m_current = 0;              ///< index of the block being filled
    size_t m_offset = 0;               ///< bytes used in it
    size_t m_depth = 0;                ///< marks taken and not released
};

}  // namespace bxdflab
