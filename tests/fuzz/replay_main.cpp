// Replays fuzz corpora (files or folders of files) through the fuzz target as an ordinary test.
//     NAME_replay [--leading-bytes] PATH...
// --leading-bytes: each file is also replayed behind every byte 0..127, for targets that read their
// first byte as options (decode) or whose behaviour a leading byte and the size change (loader).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
    std::size_t runs = 0;
    bool leading_bytes = argc > 1 && std::strcmp(argv[1], "--leading-bytes") == 0;
    for (int i = leading_bytes ? 2 : 1; i < argc; ++i) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[i])) {
            if (!entry.is_regular_file()) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
            LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
            ++runs;
            for (int pick = 0; leading_bytes && pick < 128; ++pick) {
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
