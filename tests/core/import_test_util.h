#pragma once
// Scratch folders for the import/export tests: one per prefix and process,
// removed when the test program exits.
#include <filesystem>
#include <map>
#include <string>

#include <unistd.h>

namespace mq::test {

inline std::filesystem::path scratchDir(const std::string& prefix) {
  struct Registry {
    std::map<std::string, std::filesystem::path> dirs;
    ~Registry() {
      for (const auto& [name, dir] : dirs) {
        std::error_code ignored;
        std::filesystem::remove_all(dir, ignored);
      }
    }
  };
  static Registry registry;
  auto [it, added] = registry.dirs.emplace(
      prefix, std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid())));
  if (added) std::filesystem::create_directories(it->second);
  return it->second;
}

}  // namespace mq::test
