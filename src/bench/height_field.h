#pragma once
// The wavy height field of the memory test and of `bench rays`: a SIDE x SIDE grid of quads over
// [-1, 1]^2 in x and z, each split into two triangles, with y = a smooth sum of waves. The waves
// give the triangles varied heights and normals, so a SAH build does real work (a flat plane
// would not). Standard library only: tests/memory/make_grid_mesh.cpp writes it as an OBJ.
#include <cmath>
#include <cstddef>

namespace lightpath::height_field {

struct Wave {
    float amplitude, kx, kz, phase;
};
// A few incommensurate waves: smooth everywhere, never periodic over the grid.
inline constexpr Wave kWaves[] = {{0.12f, 3.1f, 1.7f, 0.3f}, {0.05f, -7.3f, 5.9f, 1.1f}, {0.02f, 13.7f, 17.9f, 2.0f}};

inline float height(float x, float z) {
    float y = 0.0f;
    for (const Wave& w : kWaves) y += w.amplitude * std::sin(w.kx * x + w.kz * z + w.phase);
    return y;
}

// The unit normal of y = height(x, z): (-dy/dx, 1, -dy/dz), normalised.
inline void normalAt(float x, float z, float n[3]) {
    float dx = 0.0f, dz = 0.0f;
    for (const Wave& w : kWaves) {
        const float c = w.amplitude * std::cos(w.kx * x + w.kz * z + w.phase);
        dx += c * w.kx;
        dz += c * w.kz;
    }
    const float length = std::sqrt(dx * dx + 1.0f + dz * dz);
    n[0] = -dx / length;
    n[1] = 1.0f / length;
    n[2] = -dz / length;
}

// The x (of column i) or z (of row i) of a grid line.
inline float coordinate(std::size_t i, std::size_t side) {
    return -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(side);
}

// Vertex k (0-based) is at row k / (side + 1), column k % (side + 1).
inline std::size_t vertexIndex(std::size_t row, std::size_t column, std::size_t side) {
    return row * (side + 1) + column;
}

// Calls triangle(a, b, c) with the 0-based vertex indices of each of the 2 side^2 triangles,
// counter-clockwise seen from +y, so the geometric normals face up like normalAt.
template <typename Emit>
void forEachTriangle(std::size_t side, Emit triangle) {
    for (std::size_t row = 0; row < side; ++row) {
        for (std::size_t column = 0; column < side; ++column) {
            const std::size_t corner = vertexIndex(row, column, side);
            const std::size_t below = vertexIndex(row + 1, column, side);
            triangle(corner, below, below + 1);
            triangle(corner, below + 1, corner + 1);
        }
    }
}

}  // namespace lightpath::height_field
