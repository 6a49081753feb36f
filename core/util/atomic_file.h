#pragma once
// Saves that never leave a half-written file: write a temporary file beside
// the target, flush it to disk, rename it over the target, sync the folder.

#include <functional>
#include <ostream>
#include <string>

namespace mq {

// Calls write(stream) on a temporary file next to `path`, then renames it to
// `path`. Throws FileError naming `path` if anything fails; the previous
// file, if any, is left untouched in that case.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary = false);

// Reads a whole file; throws FileError when it cannot be opened.
std::string readFileText(const std::string& path);

}  // namespace mq
