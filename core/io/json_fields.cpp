#include "core/io/json_fields.h"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/util/error.h"

namespace mq {

using nlohmann::json;

namespace {

std::string lineAndColumn(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line = 1, column = 1;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's parse error text repeats the place ("parse error at line 3,
// column 5: syntax error ..."); keep what follows it.
std::string afterPlace(const std::string& problem) {
  const size_t place = problem.find("parse error at ");
  if (place == std::string::npos) return problem;
  const size_t colon = problem.find(": ", place);
  return colon == std::string::npos ? problem : problem.substr(colon + 2);
}

std::string shortNumber(double d) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", d);
  return text;
}

}  // namespace

std::string jsonProblem(const std::exception& e) {
  const std::string what = e.what();
  if (what.rfind("[json.exception.", 0) != 0) return what;
  const size_t bracket = what.find("] ");
  return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

json parseJsonText(std::string_view text, const std::string& pathForErrors) {
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // `byte` is one past the character that could not be read.
    const size_t at = e.byte > 0 ? e.byte - 1 : 0;
    throw FileError(pathForErrors, "not valid JSON (" + lineAndColumn(text, at) + "): " + afterPlace(jsonProblem(e)));
  } catch (const json::exception& e) {
    // A number too large for a double ("number overflow parsing '1e3800000'")
    // carries no position: find the number in the text.
    const std::string problem = jsonProblem(e);
    std::string place;
    const size_t quote = problem.find('\'');
    const size_t end = quote == std::string::npos ? quote : problem.find('\'', quote + 1);
    if (end != std::string::npos) {
      const size_t at = text.find(problem.substr(quote + 1, end - quote - 1));
      if (at != std::string_view::npos) place = " (" + lineAndColumn(text, at) + ")";
    }
    throw FileError(pathForErrors, "not valid JSON" + place + ": " + problem);
  }
}

JsonFields::JsonFields(const json& object, std::string path) : json_(object), path_(std::move(path)) {
  if (!json_.is_object()) throw Error(path_ + ": must be an object");
}

std::string JsonFields::pathOf(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const json* JsonFields::find(std::string_view key) const {
  auto it = json_.find(key);
  return it == json_.end() || it->is_null() ? nullptr : &*it;
}

bool JsonFields::has(std::string_view key) const { return find(key) != nullptr; }

const json& JsonFields::raw(std::string_view key) const {
  const json* value = find(key);
  if (!value) fail(key, "is missing");
  return *value;
}

void JsonFields::fail(std::string_view key, const std::string& problem) const {
  throw Error((key.empty() ? path_ : pathOf(key)) + ": " + problem);
}

void JsonFields::allowOnly(std::initializer_list<std::string_view> known) const {
  for (auto it = json_.begin(); it != json_.end(); ++it) {
    bool isKnown = false;
    for (std::string_view k : known) isKnown = isKnown || it.key() == k;
    if (!isKnown) fail(it.key(), "unknown key");
  }
}

float JsonFields::number(std::string_view key, float fallback, double min, double max) const {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_number()) fail(key, "must be a number");
  const double d = value->get<double>();
  if (!std::isfinite(d) || std::abs(d) > 3.0e38) fail(key, "must be a finite number");
  if (d < min || d > max) {
    if (max >= 3.0e38) fail(key, "must be at least " + shortNumber(min));
    if (min <= -3.0e38) fail(key, "must be at most " + shortNumber(max));
    fail(key, "must be between " + shortNumber(min) + " and " + shortNumber(max));
  }
  return float(d);
}

float JsonFields::positive(std::string_view key, float fallback, double max) const {
  const float f = number(key, fallback, -3.0e38, max);
  if (!(f > 0.0f)) fail(key, "must be positive");
  return f;
}

float JsonFields::nonNegative(std::string_view key, float fallback, double max) const {
  const float f = number(key, fallback, -3.0e38, max);
  if (f < 0.0f) fail(key, "must not be negative");
  return f;
}

long long JsonFields::integer(std::string_view key, long long fallback, long long min, long long max) const {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_number_integer()) fail(key, "must be an integer");
  // Unsigned values above the signed range would wrap: compare as unsigned first.
  if (value->is_number_unsigned() && value->get<unsigned long long>() > static_cast<unsigned long long>(max))
    fail(key, "must be an integer between " + std::to_string(min) + " and " + std::to_string(max));
  const long long i = value->get<long long>();
  if (i < min || i > max)
    fail(key, "must be an integer between " + std::to_string(min) + " and " + std::to_string(max));
  return i;
}

bool JsonFields::boolean(std::string_view key, bool fallback) const {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_boolean()) fail(key, "must be true or false");
  return value->get<bool>();
}

std::string JsonFields::string(std::string_view key, const std::string& fallback) const {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_string()) fail(key, "must be a string");
  return value->get<std::string>();
}

glm::vec3 JsonFields::vec3(std::string_view key, glm::vec3 fallback, float maxAbs) const {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != 3) fail(key, "must be an array of 3 numbers");
  glm::vec3 out;
  for (int c = 0; c < 3; ++c) {
    const json& n = (*value)[c];
    if (!n.is_number()) fail(key, "must be an array of 3 numbers");
    const double d = n.get<double>();
    if (!std::isfinite(d) || std::abs(d) > maxAbs)
      fail(key, "must hold finite numbers of magnitude at most " + shortNumber(maxAbs));
    out[c] = float(d);
  }
  return out;
}

const json& JsonFields::array(std::string_view key) const {
  static const json empty = json::array();
  const json* value = find(key);
  if (!value) return empty;
  if (!value->is_array()) fail(key, "must be an array");
  return *value;
}

JsonFields JsonFields::object(std::string_view key) const { return JsonFields(raw(key), pathOf(key)); }

JsonFields JsonFields::element(std::string_view key, size_t index) const {
  return JsonFields(array(key).at(index), pathOf(key) + "[" + std::to_string(index) + "]");
}

}  // namespace mq
