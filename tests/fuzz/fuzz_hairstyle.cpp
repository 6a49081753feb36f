// A hairstyle (the "hair" section or a style object), read and written back.
#include <nlohmann/json.hpp>

#include "core/hair/hairstyle_json.h"
#include "core/io/json_fields.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  mq::fuzz::expectOnlyErrors([&] {
    const nlohmann::json j = mq::parseJsonText(text, "hair.json");
    const mq::HairSection section = mq::hairSectionFromJson(j);
    const mq::HairSection again = mq::hairSectionFromJson(mq::toJson(section));
    if (mq::toJson(again) != mq::toJson(section)) std::abort();
  });
  return 0;
}
