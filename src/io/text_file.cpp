#include "io/text_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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

std::optional<std::string> whyCannotWrite(const std::filesystem::path& target) {
    namespace fs = std::filesystem;
    const auto folderOf = [](const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); };
    std::error_code error;
    if (fs::is_directory(target, error)) return target.string() + ": is a folder; expected a file name";
    // The nearest folder that exists; the ones missing below it would be created, the first of
    // them by making an entry in it, as the probe file does.
    fs::path probe = target;
    fs::path folder = folderOf(target);
    while (true) {
        const fs::file_status status = fs::status(folder, error);
        if (fs::exists(status)) {
            if (!fs::is_directory(status)) return target.string() + ": " + folder.string() + " is a file, not a folder";
            break;
        }
        // Missing (ENOENT) or a file on the way (ENOTDIR): look one level up. Anything else
        // (EACCES: a folder on the way cannot be searched) is the answer.
        if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory)
            return target.string() + ": cannot reach " + folder.string() + " (" + error.message() + ")";
        if (folder == folderOf(folder)) return target.string() + ": no folder of it exists";
        probe = folder;
        folder = folderOf(folder);
    }
    const fs::path file = temporaryName(folder / probe.filename());
    const int descriptor = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (descriptor < 0 && errno == EEXIST) return std::nullopt;  // a stale probe of ours: files can be made there
    if (descriptor < 0) {
        const std::string reason = std::strerror(errno);
        if (probe == target) return target.string() + ": cannot create files in " + folder.string() + " (" + reason + ")";
        return target.string() + ": cannot create the folder " + probe.string() + " (" + reason + ")";
    }
    ::close(descriptor);
    ::unlink(file.c_str());
    return std::nullopt;
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
