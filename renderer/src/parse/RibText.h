// Writing RIB text, for the programs that make their own scenes (the benchmark,
// the lobe plots).
#pragma once

#include <ostream>

namespace bxdflab {

/// A PointsPolygons grid's two arrays, "[4 4 ...] [a b c d ...]": rows x columns
/// quads over (rows + 1) x (columns + 1) points numbered row after row.
inline void writeQuadGridFaces(std::ostream& rib, int rows, int columns) {
    rib << "[";
    for (int k = 0; k < rows * columns; ++k) rib << "4 ";
    rib << "] [";
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            int const a = i * (columns + 1) + j;
            rib << a << ' ' << a + 1 << ' ' << a + columns + 2 << ' ' << a + columns + 1 << ' ';
        }
    rib << "]";
}

}  // namespace bxdflab
