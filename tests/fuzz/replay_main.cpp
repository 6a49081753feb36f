// Runs a fuzz target's entry point over files (seeds, regression inputs), so
// the normal build's ctest replays what fuzzing found without libFuzzer.
//   fuzz_replay_<target> FILE|DIR ...
// A file ending in .patch is an input made from a test asset of ../shared
// (which the repository must not copy): its first line is `base <path under
// MANNEQUIN_SHARED_DIR>`, each further line `<offset> <byte>` (decimal offset
// from 0, byte in hex) changes one byte of it.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
// Optional in a target, as in libFuzzer.
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace {

std::vector<uint8_t> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<uint8_t> patchedInput(const std::filesystem::path& patch) {
  std::ifstream in(patch);
  std::string word, base;
  if (!(in >> word >> base) || word != "base") throw std::runtime_error(patch.string() + ": no `base <path>` line");
  std::vector<uint8_t> bytes = readBytes(std::filesystem::path(MANNEQUIN_SHARED_DIR) / base);
  size_t offset = 0;
  std::string value;
  while (in >> offset >> value) {
    if (offset >= bytes.size()) throw std::runtime_error(patch.string() + ": offset past the base file");
    bytes[offset] = uint8_t(std::stoul(value, nullptr, 16));
  }
  return bytes;
}

}  // namespace

int main(int argc, char** argv) {
  if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path arg = argv[i];
    if (std::filesystem::is_directory(arg)) {
      for (const auto& entry : std::filesystem::directory_iterator(arg))
        if (entry.is_regular_file() && entry.path().filename() != "README.md") inputs.push_back(entry.path());
    } else if (std::filesystem::is_regular_file(arg)) {
      inputs.push_back(arg);
    } else {
      std::cerr << arg << ": no such file or folder\n";
      return 2;
    }
  }
  std::sort(inputs.begin(), inputs.end());
  for (const auto& path : inputs) {
    try {
      const std::vector<uint8_t> bytes = path.extension() == ".patch" ? patchedInput(path) : readBytes(path);
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    } catch (const std::runtime_error& e) {
      std::cerr << e.what() << "\n";
      return 2;
    }
  }
  std::cout << "replayed " << inputs.size() << " inputs\n";
  return inputs.empty() ? 1 : 0;
}
