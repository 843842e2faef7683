// POV-Ray's height_field from an image file: the grid of heights its pixels
// give (height_field_image.cpp) and the shape traced over it
// (height_field.cpp). The function form (height_field { function W, H
// {...} }) would fill the same grid.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/shape.h"

namespace lancer {

// Heights at the grid points, row by row: point (column c, row r) sits at
// object x = c / (columns - 1), z = r / (rows - 1), y = heights[r * columns
// + c]. Row 0 is z = 0, which is the image's BOTTOM row (POV-Ray turns the
// image over). POV-Ray's heights are a 16-bit value / 65536, so they lie
// in [0, 65535/65536].
struct HeightFieldGrid {
    int columns = 0, rows = 0;
    std::vector<float> heights;  // rows x columns
};

// The triangulated surface over the unit square, two triangles per cell
// split along the diagonal from (c + 1, r) to (c, r + 1); `smooth` gives
// POV's interpolated vertex normals, `water_level` (object units, 0..1)
// drops every part of the surface below it. Open: no sides, no bottom.
// Null for fewer than 2 x 2 points, a heights vector of the wrong size, a
// non-finite height or more cells than the face numbering can name.
std::shared_ptr<const Shape> make_height_field_shape(HeightFieldGrid grid, bool smooth, double water_level);

// Reads an image as POV-Ray 3.7 turns it into heights: grey images by
// their grey value, palette images (GIF, palette PNG) by the index * 256,
// 8-bit colour images by red * 256 + green, deeper colour and float images
// by their luminance. `gamma` is the `gamma` given in the scene (NaN:
// none, no decoding, as POV does for height fields). Throws
// std::runtime_error with a one-line message naming the file on a file
// that cannot be read, has no pixels, fewer than 2 x 2, more than 16384 x
// 16384 (refused before decoding) or is truncated.
HeightFieldGrid read_height_field_image(const std::string& path, double gamma);

// The grid of a 16-bit image's values (row-major, its top row first), as
// POV-Ray makes a height field of them: value / 65536, the top row at z = 1.
HeightFieldGrid grid_from_values(int width, int height, const std::vector<std::uint16_t>& values);

}  // namespace lancer
