// Replays fuzz corpora (files or folders of files) through the fuzz target as an ordinary test.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
    std::size_t runs = 0;
    for (int i = 1; i < argc; ++i) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[i])) {
            if (!entry.is_regular_file()) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
            // Each file as it is, and behind every option byte the target knows.
            for (int pick = 0; pick < 128; ++pick) {
                bytes.insert(bytes.begin(), static_cast<std::uint8_t>(pick));
                LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
                bytes.erase(bytes.begin());
                ++runs;
            }
        }
    }
    std::printf("replayed %zu inputs\n", runs);
    return runs > 0 ? 0 : 1;
}
