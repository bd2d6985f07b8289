#pragma once
// A folder of one test's own in the temporary directory, removed with everything in it when the
// object goes (also when a REQUIRE fails): the suite leaves nothing behind. The name is random
// because ctest runs test processes at once.
#include <filesystem>
#include <random>
#include <string>
#include <system_error>

namespace lightpath::test {

class TempFolder {
public:
    explicit TempFolder(const std::string& prefix)
        : path_(std::filesystem::temp_directory_path() / (prefix + "-" + std::to_string(std::random_device{}()))) {
        std::filesystem::create_directories(path_);
    }
    ~TempFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace lightpath::test
