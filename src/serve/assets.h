#pragma once
// The page's files (web/), compiled into the binary by CMake (cmake/embed_assets.cmake) so the
// server reads no file at run time and works offline.
#include <string_view>

namespace lightpath::serve {

struct Asset {
    std::string_view path;  // the URL path: "/", "/app.js", ...
    std::string_view contentType;
    std::string_view content;
};

// Null when `path` names no asset.
const Asset* findAsset(std::string_view path);

}  // namespace lightpath::serve
