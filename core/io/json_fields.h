#pragma once
// Reading JSON documents a user may have edited by hand: parse errors give
// the line and column, and every field is checked for type, finiteness and
// range where it is read, with its JSON path in the message
// ("hair.style.length_variation: must be between 0 and 1").

#include <cstdint>
#include <exception>
#include <initializer_list>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

namespace mq {

// Parses `text`; a syntax error or an out-of-range number throws
// FileError(path, "not valid JSON (line L, column C): ...").
nlohmann::json parseJsonText(std::string_view text, const std::string& pathForErrors);

// The message of a nlohmann exception without its "[json.exception.x.N] " tag.
std::string jsonProblem(const std::exception& e);

// Typed fields of one JSON object. Optional fields: absent or null gives the
// fallback. Errors are mq::Error("<path>.<key>: <problem>").
class JsonFields {
 public:
  JsonFields(const nlohmann::json& object, std::string path);

  const std::string& path() const { return path_; }
  std::string pathOf(std::string_view key) const;
  bool has(std::string_view key) const;
  const nlohmann::json& raw(std::string_view key) const;
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;

  // Fails on keys outside `known` (typos would otherwise be silently ignored).
  void allowOnly(std::initializer_list<std::string_view> known) const;

  // A finite number in [min, max].
  float number(std::string_view key, float fallback, double min = -3.0e38, double max = 3.0e38) const;
  float positive(std::string_view key, float fallback, double max = 3.0e38) const;
  float nonNegative(std::string_view key, float fallback, double max = 3.0e38) const;
  long long integer(std::string_view key, long long fallback, long long min, long long max) const;
  bool boolean(std::string_view key, bool fallback) const;
  std::string string(std::string_view key, const std::string& fallback) const;
  // Three finite numbers, each of magnitude at most maxAbs.
  glm::vec3 vec3(std::string_view key, glm::vec3 fallback, float maxAbs = 3.0e38f) const;
  // An array (empty when absent).
  const nlohmann::json& array(std::string_view key) const;
  // The object at `key`, read with its own path.
  JsonFields object(std::string_view key) const;
  // The object at `array(key)[index]`.
  JsonFields element(std::string_view key, size_t index) const;

 private:
  const nlohmann::json* find(std::string_view key) const;

  const nlohmann::json& json_;
  std::string path_;
};

}  // namespace mq
