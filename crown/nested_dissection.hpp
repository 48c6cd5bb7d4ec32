#pragma once
// Geometric nested dissection of pixel sets (George 1973, "Nested dissection of a regular finite
// element mesh") as the elimination order of the inflation system: the pixels are split in two by
// a band of pixels (the separator) that no stencil couples across, each side is ordered
// recursively and the separator comes last, so the Cholesky factor fills in only within the
// halves and the separators. For the 13-point stencil of eq. 4.2 (offsets up to 2 along rows and
// columns, 1 along diagonals) every straight band must be 2 pixels wide; diagonal bands
// (x + y or x - y constant) hold 1/sqrt(2) as many pixels per length as row or column bands, and
// each split takes whichever of the four directions gives the smallest separator.
#include <cstddef>
#include <vector>

namespace fspm::crown {

// The pixel indices (row-major in a raster `width` pixels wide) in nested dissection order: a
// permutation of `pixels`. Pieces of at most `leaf_pixels` pixels keep their given order.
std::vector<std::size_t> nested_dissection_order(std::vector<std::size_t> pixels, int width,
                                                 std::size_t leaf_pixels = 16);

}  // namespace fspm::crown
