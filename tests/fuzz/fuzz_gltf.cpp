// glTF and GLB through our reader, then every clip posed and skinned.
#include <cstring>

#include "core/character/posed_character.h"
#include "core/io/character_import.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::string path = mq::fuzz::inputFile(data, size, binary ? "glb" : "gltf");
  mq::fuzz::expectOnlyErrors([&] {
    mq::Character character = mq::importCharacter(path);
    character.validate();
    mq::PosedCharacter posed;
    posed.evaluate(character, -1, 0.0f, nullptr, nullptr);
    for (int clip = 0; clip < int(character.clips.size()); ++clip)
      posed.evaluate(character, clip, character.clips[clip].endTime() * 0.5f, nullptr, nullptr);
  });
  return 0;
}
