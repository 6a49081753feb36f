#include "core/garment/pattern_dxf_scan.h"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <vector>

#include "core/util/error.h"

namespace mq {
namespace {

constexpr size_t kMaxLine = 2048;  // characters

std::string trimmed(const std::string& text, size_t begin, size_t end) {
  while (begin < end && (text[begin] == ' ' || text[begin] == '\t')) ++begin;
  while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\r')) --end;
  return text.substr(begin, end - begin);
}

// Entities whose counts dxflib sizes arrays by, and the group codes that hold them.
bool isCount(const std::string& entity, long code) {
  static const std::set<std::string> counted = {"LWPOLYLINE", "SPLINE", "HATCH", "LEADER", "MLINE", "MLEADER"};
  return counted.count(entity) && ((code >= 72 && code <= 76) || (code >= 90 && code <= 99));
}

}  // namespace

void checkDxfText(const std::string& text) {
  if (text.rfind("AutoCAD Binary DXF", 0) == 0) throw Error("binary DXF is not read: save the pattern as ASCII DXF");
  std::vector<std::string> lines;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end - start > kMaxLine)
      throw Error("line " + std::to_string(lines.size() + 1) + " is longer than " + std::to_string(kMaxLine) +
                  " characters: not a DXF file");
    lines.push_back(trimmed(text, start, end));
    start = end + 1;
  }
  const size_t pairs = lines.size() / 2;
  bool sawEof = false, sawSection = false;
  std::string entity;
  // To the end, past an EOF marker: dxflib reads on after one.
  for (size_t i = 0; i + 1 < lines.size(); i += 2) {
    char* end = nullptr;
    const long code = std::strtol(lines[i].c_str(), &end, 10);
    if (lines[i].empty() || *end != '\0' || code < 0 || code > 1071)
      throw Error("line " + std::to_string(i + 1) + ": expected a group code, found \"" + lines[i].substr(0, 40) +
                  "\": not an ASCII DXF file");
    const std::string& value = lines[i + 1];
    if (code == 0) {
      entity = value;
      sawSection = sawSection || value == "SECTION";
      sawEof = sawEof || value == "EOF";
    } else if (isCount(entity, code)) {
      const long count = std::strtol(value.c_str(), &end, 10);
      if (count < 0 || size_t(count) > pairs)
        throw Error("line " + std::to_string(i + 2) + ": " + entity + " gives a count of " + value.substr(0, 20) +
                    " (group code " + std::to_string(code) + "), more than the file holds");
    }
  }
  if (!sawSection) throw Error("no SECTION: not a DXF file");
  if (!sawEof) throw Error("the file ends before its EOF marker: it is truncated");
}

}  // namespace mq
