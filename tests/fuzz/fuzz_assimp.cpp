// FBX and Collada through Assimp (read first in a bounded child) and our
// conversion of what it returns. XML is read as Collada, the rest as FBX.
#include <cctype>

#include "core/character/posed_character.h"
#include "core/io/character_import.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  size_t first = 0;
  while (first < size && std::isspace(data[first])) ++first;
  const bool xml = first < size && data[first] == '<';
  const std::string path = mq::fuzz::inputFile(data, size, xml ? "dae" : "fbx");
  mq::fuzz::expectOnlyErrors([&] {
    mq::Character character = mq::importCharacter(path);
    character.validate();
    mq::PosedCharacter posed;
    for (int clip = -1; clip < int(character.clips.size()); ++clip)
      posed.evaluate(character, clip, clip < 0 ? 0.0f : character.clips[clip].endTime() * 0.5f, nullptr, nullptr);
  });
  return 0;
}
