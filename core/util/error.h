#pragma once
// Errors a user can act on (bad files, bad arguments) derive from mq::Error;
// their message names the file and the problem. Programmer mistakes are
// asserts, not Errors.

#include <stdexcept>
#include <string>

namespace mq {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "<path>: <problem>"
class FileError : public Error {
 public:
  FileError(const std::string& path, const std::string& problem)
      : Error(path + ": " + problem), path_(path), problem_(problem) {}
  const std::string& path() const { return path_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string path_;
  std::string problem_;
};

}  // namespace mq
