// main() of the fuzz targets in a build without a fuzzing engine (g++, or
// clang without -DDLAB_FUZZ=ON): runs LLVMFuzzerTestOneInput once on each
// file given, and on each regular file of each directory given (in name
// order), as libFuzzer does when given files. So a crash file or a seed
// corpus replays in the ordinary build, and ctest replays the seeds there.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

int run_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "%s: cannot read\n", p.c_str());
    return 2;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE|DIR...  (standalone replay: built without a fuzzing engine)\n", argv[0]);
    return 2;
  }
  std::size_t runs = 0;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path arg = argv[i];
    if (arg.string().starts_with("-")) {
      std::fprintf(stderr, "%s: unknown option %s (this build has no fuzzing engine: configure with clang and "
                   "-DDLAB_FUZZ=ON, fuzz/README.md)\n", argv[0], argv[i]);
      return 2;
    }
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(arg, ec)) {
      for (const auto& e : std::filesystem::directory_iterator(arg, ec))
        if (e.is_regular_file()) files.push_back(e.path());
      if (ec) {
        std::fprintf(stderr, "%s: cannot list: %s\n", arg.c_str(), ec.message().c_str());
        return 2;
      }
      std::sort(files.begin(), files.end());
    } else {
      files.push_back(arg);
    }
    for (const auto& f : files) {
      if (run_file(f) != 0) return 2;
      ++runs;
    }
  }
  std::printf("%s: %zu inputs replayed, no failure\n", argv[0], runs);
  return 0;
}
