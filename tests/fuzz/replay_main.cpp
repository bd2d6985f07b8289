// Replays inputs through a fuzz target without libFuzzer, so that any compiler and build type can
// run the committed corpora as regression tests:
//     replay_lpe tests/fuzz/corpus/lpe [more files or directories...]
// Every file given, and every regular file of every directory given (in name order), is passed to
// LLVMFuzzerTestOneInput once. A broken invariant aborts, naming the input last printed.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::filesystem::path> inputsOf(const std::filesystem::path& argument) {
    if (!std::filesystem::is_directory(argument)) return {argument};
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(argument))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " FILE_OR_DIRECTORY...\n";
        return 2;
    }
    std::size_t replayed = 0;
    for (int i = 1; i < argc; ++i) {
        if (!std::filesystem::exists(argv[i])) {
            std::cerr << argv[0] << ": " << argv[i] << ": no such file or directory\n";
            return 2;
        }
        for (const std::filesystem::path& file : inputsOf(argv[i])) {
            std::ifstream in(file, std::ios::binary);
            const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
            if (!in.good() && !in.eof()) {
                std::cerr << argv[0] << ": cannot read " << file.string() << "\n";
                return 2;
            }
            // Printed first, so that a crash's output names the input that caused it.
            std::cout << "replaying " << file.string() << std::endl;
            LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
            ++replayed;
        }
    }
    if (replayed == 0) {
        std::cerr << argv[0] << ": no inputs found\n";
        return 2;
    }
    std::cout << "replayed " << replayed << " inputs: no crash, no broken invariant\n";
    return 0;
}
