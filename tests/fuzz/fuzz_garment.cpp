// A garment (panels, seams, fabric, pins) read, validated and written back.
#include <nlohmann/json.hpp>

#include "core/garment/garment_json.h"
#include "core/io/json_fields.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  mq::fuzz::expectOnlyErrors([&] {
    const nlohmann::json j = mq::parseJsonText(text, "garment.json");
    const mq::Garment garment = mq::garmentFromJson(j);
    mq::garmentFromJson(mq::garmentToJson(garment));
  });
  return 0;
}
