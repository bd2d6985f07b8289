#include "io/text_file.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace lightpath {

std::filesystem::path temporaryName(const std::filesystem::path& target) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string once inlined.
    std::string name = ".";
    name += target.filename().string();
    name += ".tmp-" + std::to_string(::getpid());
    return target.parent_path() / name;
}

void writeTextFileAtomically(const std::filesystem::path& path, const std::string& contents) {
    namespace fs = std::filesystem;
    if (path.has_parent_path()) fs::create_directories(path.parent_path());
    const fs::path temporary = temporaryName(path);
    {
        std::ofstream out(temporary, std::ios::binary);
        out << contents;
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            throw std::runtime_error(path.string() + ": cannot write file");
        }
    }
    fs::rename(temporary, path);
}

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
            out += buffer;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

}  // namespace lightpath
