// Bump allocator for per-batch memory (shading contexts, Bxdf objects, their
// arrays). Everything is released at once by reset(): no per-point malloc.
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
    /// Frees everything allocated since the last reset (keeps the first block).
    void reset();

    /// A position in the arena. release(mark) frees everything allocated
    /// after mark() was taken, so nested users (a path tracer's bounces) can
    /// free their own memory while an outer batch's stays valid.
    struct Mark {
        size_t block = 0, offset = 0;
    };
    Mark mark() const { return {m_current, m_offset}; }
    void release(Mark const& m) {
        m_current = m.block;
        m_offset = m.offset;
    }

private:
    struct Block {
        std::unique_ptr<std::byte[]> memory;
        size_t size;
    };
    size_t m_blockSize;
    std::vector<Block> m_blocks;
    size_t m_current = 0;  ///< index of the block being filled
    size_t m_offset = 0;   ///< bytes used in it
};

}  // namespace bxdflab
