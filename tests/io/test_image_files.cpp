// writeFilm and readFilm (OpenEXR, libpng): an EXR reads back bit for bit, every PNG holds its
// own layer whichever thread wrote it (read back by libpng's own simplified reader), and a file
// that cannot be written leaves no output, no temporary and any older image as it was.
#include <doctest/doctest.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <png.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "io/image_reader.h"
#include "io/image_writer.h"

namespace lightpath {
namespace {

namespace fs = std::filesystem;

fs::path freshDirectory(const std::string& name) {
    const fs::path directory = fs::path(LIGHTPATH_TEST_OUTPUT_DIR) / name;
    fs::remove_all(directory);
    fs::create_directories(directory);
    return directory;
}

std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An 8-bit RGB PNG decoded by libpng's simplified API, which converts any PNG to the format
// asked for: what a viewer would show.
struct PngPixels {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

PngPixels readPng(const fs::path& file) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    REQUIRE_MESSAGE(png_image_begin_read_from_file(&image, file.c_str()) != 0, image.message);
    image.format = PNG_FORMAT_RGB;
    PngPixels png{static_cast<int>(image.width), static_cast<int>(image.height), {}};
    png.rgb.resize(PNG_IMAGE_SIZE(image));
    REQUIRE_MESSAGE(png_image_finish_read(&image, nullptr, png.rgb.data(), 0, nullptr) != 0, image.message);
    return png;
}

// Every layer and pixel different, with values below 0 and above 1 that PNG must clamp.
Film patternFilm() {
    Film film(37, 23, {"beauty", "direct", "mirror", "rest"});
    for (std::size_t l = 0; l < film.layerCount(); ++l)
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x)
                film.at(l, x, y) = {0.3f * static_cast<float>(l) + 0.03f * static_cast<float>(x) - 0.1f,
                                    0.04f * static_cast<float>(y), 1.0f / static_cast<float>(1 + x + y + l)};
    return film;
}

TEST_CASE("a multi-layer EXR reads back bit for bit, layer names included") {
    const Film film = patternFilm();
    const fs::path file = freshDirectory("exr") / "film.exr";
    CHECK(writeFilm(film, file, {{"lightpath:test", "yes"}}) == std::vector<fs::path>{file});
    const Film back = readFilm(file);
    CHECK(back.layerNames() == film.layerNames());
    REQUIRE(back.width() == film.width());
    REQUIRE(back.height() == film.height());
    const auto a = film.interleaved(), b = back.interleaved();
    CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
}

TEST_CASE("an EXR or a PNG encoded in memory (serve's answers) is the file's bytes; the EXR keeps the metadata") {
    const Film film = patternFilm();
    const fs::path directory = freshDirectory("memory");
    const ImageMetadata metadata{{"lightpath:test", "yes"}, {"lightpath:lpe:caustic", "E(D|G)S+<L.>"}};
    writeFilm(film, directory / "film.exr", metadata);
    const std::vector<unsigned char> exr = encodeExr(film, metadata);
    const std::string file = contents(directory / "film.exr");
    CHECK(std::string(exr.begin(), exr.end()) == file);
    Imf::InputFile in((directory / "film.exr").c_str());
    for (const auto& entry : metadata) {  // no structured binding: clang 14 cannot capture one in CHECK's lambda
        const auto* attribute = in.header().findTypedAttribute<Imf::StringAttribute>(entry.first);
        REQUIRE_MESSAGE(attribute != nullptr, entry.first);
        CHECK(attribute->value() == entry.second);
    }
    const std::vector<fs::path> pngs = writeFilm(film, directory / "film.png", {});
    for (std::size_t l = 0; l < pngs.size(); ++l) {
        const std::vector<unsigned char> png = encodePng(film, l);
        CHECK_MESSAGE(std::string(png.begin(), png.end()) == contents(pngs[l]), pngs[l].string());
    }
}

TEST_CASE("each PNG holds its own layer, sRGB-encoded, whichever thread wrote it") {
    const Film film = patternFilm();
    for (int threads : {1, 3}) {
        CAPTURE(threads);
        const fs::path file = freshDirectory("png-" + std::to_string(threads)) / "film.png";
        const std::vector<fs::path> written = writeFilm(film, file, {}, threads);
        REQUIRE(written.size() == film.layerCount());
        CHECK(written[1].filename() == "film.direct.png");
        for (std::size_t l = 0; l < film.layerCount(); ++l) {
            const PngPixels png = readPng(written[l]);
            REQUIRE(png.width == film.width());
            REQUIRE(png.height == film.height());
            int mismatches = 0;
            for (int y = 0; y < film.height(); ++y)
                for (int x = 0; x < film.width(); ++x)
                    for (int c = 0; c < 3; ++c)
                        if (png.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(png.width) + static_cast<std::size_t>(x)) * 3 +
                                    static_cast<std::size_t>(c)] != toSrgb8(film.at(l, x, y)[c]))
                            ++mismatches;
            CHECK_MESSAGE(mismatches == 0, written[l].string());
        }
    }
    // The bytes do not depend on the number of writing threads.
    for (const char* name : {"film.png", "film.direct.png", "film.rest.png"})
        CHECK(contents(fs::path(LIGHTPATH_TEST_OUTPUT_DIR) / "png-1" / name) ==
              contents(fs::path(LIGHTPATH_TEST_OUTPUT_DIR) / "png-3" / name));
}

TEST_CASE("a layer that cannot be written: no image written, no temporary left, older images kept") {
    const Film film = patternFilm();
    const fs::path directory = freshDirectory("failure");
    const fs::path file = directory / "film.png";
    const std::string older = "an older image";
    std::ofstream(file) << older;
    std::ofstream(directory / "film.mirror.png") << older;
    // The last layer's temporary name is taken by a non-empty folder, so that file cannot be
    // opened while the other layers are written on other threads.
    const fs::path blocker = directory / (".film.rest.png.tmp-" + std::to_string(::getpid()));
    fs::create_directories(blocker / "occupied");
    CHECK_THROWS_WITH_AS(writeFilm(film, file, {}, 3), doctest::Contains("film.rest.png: cannot write image"),
                         ImageWriteError);
    CHECK(contents(file) == older);
    CHECK(contents(directory / "film.mirror.png") == older);
    CHECK_FALSE(fs::exists(directory / "film.direct.png"));
    for (const auto& entry : fs::directory_iterator(directory)) {
        const std::string name = entry.path().filename().string();
        CHECK_MESSAGE((name.find(".tmp-") == std::string::npos || entry.path() == blocker), name);
    }
}

}  // namespace
}  // namespace lightpath
