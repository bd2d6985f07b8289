// Writes a Wavefront OBJ of a wavy height field: a SIDE x SIDE grid of quads over [-1, 1]^2 in
// x and z, each split into two triangles, with y = a smooth sum of waves. The memory test renders
// it as a large mesh whose BVH is realistic: the waves give the triangles varied heights and
// normals, so the SAH build does real work (a flat plane would not).
//
//   make_grid_mesh OUT.obj [SIDE] [--normals]
//
// SIDE defaults to 708 (2 * 708^2 = 1,002,528 triangles). --normals adds the analytic vertex
// normals (`vn`, `f a//a b//b c//c`), as a scanned mesh would have them.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "bench/height_field.h"

namespace {

using namespace lightpath::height_field;

// Text goes through one buffer written in large blocks: with to_chars, a million-triangle file
// takes about a second.
class Writer {
public:
    explicit Writer(std::FILE* file) : file_(file) { buffer_.reserve(kFlushAt + 256); }

    void text(const char* s) { buffer_.append(s); }
    void number(float v) {
        char digits[32];
        const auto end = std::to_chars(digits, digits + sizeof digits, v, std::chars_format::fixed, 6).ptr;
        buffer_.append(digits, end);
    }
    void number(std::size_t v) {
        char digits[24];
        const auto end = std::to_chars(digits, digits + sizeof digits, v).ptr;
        buffer_.append(digits, end);
    }
    void endLine() {
        buffer_.push_back('\n');
        if (buffer_.size() >= kFlushAt) flush();
    }
    // Writes what is left; false if any write failed.
    bool finish() {
        flush();
        return ok_;
    }

private:
    void flush() {
        ok_ = std::fwrite(buffer_.data(), 1, buffer_.size(), file_) == buffer_.size() && ok_;
        buffer_.clear();
    }

    static constexpr std::size_t kFlushAt = 1 << 20;
    std::FILE* file_;
    std::string buffer_;
    bool ok_ = true;
};

int usage() {
    std::fprintf(stderr, "usage: make_grid_mesh OUT.obj [SIDE] [--normals]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage();
    const char* output = argv[1];
    std::size_t side = 708;
    bool normals = false;
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--normals") == 0) {
            normals = true;
            continue;
        }
        const char* end = argv[i] + std::strlen(argv[i]);
        const auto [ptr, error] = std::from_chars(argv[i], end, side);
        if (error != std::errc() || ptr != end || side < 1 || side > 20000) return usage();
    }

    std::FILE* file = std::fopen(output, "wb");
    if (!file) {
        std::perror(output);
        return 1;
    }
    Writer out(file);
    const std::size_t triangles = 2 * side * side;
    out.text("# make_grid_mesh: ");
    out.number(side);
    out.text(" x ");
    out.number(side);
    out.text(" quads, ");
    out.number(triangles);
    out.text(" triangles");
    out.endLine();

    const std::size_t columns = side + 1;
    for (std::size_t row = 0; row < columns; ++row) {
        for (std::size_t column = 0; column < columns; ++column) {
            const float x = coordinate(column, side), z = coordinate(row, side);
            out.text("v ");
            out.number(x);
            out.text(" ");
            out.number(height(x, z));
            out.text(" ");
            out.number(z);
            out.endLine();
        }
    }
    if (normals) {
        for (std::size_t row = 0; row < columns; ++row) {
            for (std::size_t column = 0; column < columns; ++column) {
                float n[3];
                normalAt(coordinate(column, side), coordinate(row, side), n);
                out.text("vn ");
                out.number(n[0]);
                out.text(" ");
                out.number(n[1]);
                out.text(" ");
                out.number(n[2]);
                out.endLine();
            }
        }
    }
    // OBJ indices are 1-based; normal k belongs to vertex k.
    const auto corner = [&](std::size_t vertex) {
        out.text(" ");
        out.number(vertex + 1);
        if (normals) {
            out.text("//");
            out.number(vertex + 1);
        }
    };
    forEachTriangle(side, [&](std::size_t a, std::size_t b, std::size_t c) {
        out.text("f");
        corner(a);
        corner(b);
        corner(c);
        out.endLine();
    });
    if (!out.finish()) {
        std::perror(output);
        std::fclose(file);
        return 1;
    }
    if (std::fclose(file) != 0) {
        std::perror(output);
        return 1;
    }
    return 0;
}
