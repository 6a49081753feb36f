#pragma once
// Whole-file reads for the importers, with errors that name the file.

#include <cstdint>
#include <string>
#include <vector>

namespace mq {

// Throws FileError when the file is missing or unreadable.
std::vector<uint8_t> readFileBytes(const std::string& path);
// Like readFileText in core/util/atomic_file.h, with clearer messages for
// missing files and directories.
std::string loadFileText(const std::string& path);

// Lower-case extension without the dot ("gltf", "glb", ...), "" if none.
std::string fileExtension(const std::string& path);

}  // namespace mq
