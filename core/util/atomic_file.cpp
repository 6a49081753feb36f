#include "core/util/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "core/util/error.h"

namespace mq {
namespace {

std::string temporaryPathBeside(const std::string& path) {
  std::random_device rd;
  return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
}

void syncFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  const std::string tmp = temporaryPathBeside(path);
  try {
    std::ofstream out(tmp, binary ? std::ios::binary : std::ios::out);
    if (!out) throw FileError(path, std::string("cannot write: ") + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) throw FileError(path, "write failed (disk full?)");
    out.close();
    syncFile(tmp);
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw FileError(path, "cannot replace the file: " + ec.message());
    // The rename itself lives in the folder: sync it too, or a power cut can
    // bring back the old name.
    syncFile(std::filesystem::absolute(path).parent_path().string());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

std::string readFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace mq
