#include "fuzz_input.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

#include "core/character/default_mannequin.h"
#include "core/util/error.h"

namespace mq::fuzz {

std::string inputFile(const uint8_t* data, size_t size, const std::string& extension) {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path base =
        std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    auto d = base / ("mannequin_fuzz_" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::string path = (dir / ("input." + extension)).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

const Character& mannequin() {
  static const Character character = makeDefaultMannequin();
  return character;
}

void expectOnlyErrors(const std::function<void()>& read) {
  try {
    read();
  } catch (const Error&) {
    // a refusal with a message: what bad input should get
  } catch (const std::exception& e) {
    std::cerr << "not an mq::Error: " << e.what() << "\n";
    std::abort();
  }
}

}  // namespace mq::fuzz
