#pragma once
// Shared by the fuzz targets: libFuzzer hands bytes, our readers take paths.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "core/character/character.h"

namespace mq::fuzz {

// Writes the input to `input.<extension>` in this process's scratch folder
// (on /dev/shm when it exists) and returns its path.
std::string inputFile(const uint8_t* data, size_t size, const std::string& extension);

// The built-in mannequin, built once (call it from LLVMFuzzerInitialize: it
// takes seconds under ASan, longer than libFuzzer's limit for one input).
const Character& mannequin();

// Runs `read`: an mq::Error is the expected refusal of bad input; anything
// else (another exception, a crash, a leak) is a finding.
void expectOnlyErrors(const std::function<void()>& read);

}  // namespace mq::fuzz
