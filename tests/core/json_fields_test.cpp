// Hand-edited JSON: parse errors give the place, fields give their path.
#include <gtest/gtest.h>

#include <cstdlib>

#include <nlohmann/json.hpp>

#include "core/hair/hairstyle_json.h"
#include "core/io/json_fields.h"
#include "core/util/error.h"
#include "core/util/isolated_run.h"
#include "core/util/utf8.h"

namespace mq {
namespace {

using nlohmann::json;

std::string parseError(const std::string& text) {
  try {
    parseJsonText(text, "doc.json");
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), "doc.json");
    return e.what();
  }
  ADD_FAILURE() << "parsed: " << text;
  return "";
}

std::string fieldError(const std::function<void()>& read) {
  try {
    read();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "read without error";
  return "";
}

TEST(JsonText, SyntaxErrorNamesLineAndColumn) {
  const std::string message = parseError("{\n  \"a\": 1,\n  \"b\": tru\n}");
  EXPECT_NE(message.find("doc.json: not valid JSON (line 3, column 11)"), std::string::npos) << message;
  EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
}

TEST(JsonText, NumberTooLargeForADoubleIsPlaced) {
  const std::string message = parseError("{\n \"length\": 1e3800000\n}");
  EXPECT_NE(message.find("(line 2, column 12): number overflow parsing '1e3800000'"), std::string::npos) << message;
}

TEST(JsonText, TruncatedDocumentSaysWhere) {
  EXPECT_NE(parseError("{\"a\": [1, 2").find("not valid JSON (line 1, column 12)"), std::string::npos);
}

TEST(JsonFields, RangesAndTypesNameThePath) {
  const json j = json::parse(R"({"x": 2.5, "n": -3, "s": 4, "v": [1, 2], "big": 1e300, "u": 18446744073709551615})");
  const JsonFields f(j, "root.part");
  EXPECT_EQ(fieldError([&] { f.number("x", 0, 0, 1); }), "root.part.x: must be between 0 and 1");
  EXPECT_EQ(fieldError([&] { f.integer("n", 0, 0, 10); }), "root.part.n: must be an integer between 0 and 10");
  EXPECT_EQ(fieldError([&] { f.integer("u", 0, 0, 10); }), "root.part.u: must be an integer between 0 and 10");
  EXPECT_EQ(fieldError([&] { f.integer("x", 0, 0, 10); }), "root.part.x: must be an integer");
  EXPECT_EQ(fieldError([&] { f.string("s", ""); }), "root.part.s: must be a string");
  EXPECT_EQ(fieldError([&] { f.vec3("v", {}); }), "root.part.v: must be an array of 3 numbers");
  EXPECT_EQ(fieldError([&] { f.number("big", 0); }), "root.part.big: must be a finite number");
  EXPECT_EQ(fieldError([&] { f.positive("n", 1); }), "root.part.n: must be positive");
  EXPECT_EQ(f.number("missing", 7.0f, 0, 1), 7.0f);
  EXPECT_EQ(f.number("x", 0, 0, 10), 2.5f);
  EXPECT_EQ(fieldError([&] { f.allowOnly({"x", "n", "v", "big", "u"}); }), "root.part.s: unknown key");
}

TEST(JsonFields, ElementsAndObjectsCarryTheirPath) {
  const json j = json::parse(R"({"list": [{"r": 1}, {"r": -1}], "child": 3})");
  const JsonFields f(j, "top");
  EXPECT_EQ(fieldError([&] { f.element("list", 1).positive("r", 1); }), "top.list[1].r: must be positive");
  EXPECT_EQ(fieldError([&] { f.object("child"); }), "top.child: must be an object");
}

// The scene that crashed `simulate` (a length variation of 1e37 gave
// strands of infinite length) and its neighbours are refused where read.
TEST(JsonFields, HairStyleValuesAreRangeChecked) {
  auto errorOf = [](const json& style) { return fieldError([&] { hairSectionFromJson(json{{"style", style}}); }); };
  EXPECT_EQ(errorOf({{"length_variation", 1e37}}), "hair.style.length_variation: must be between 0 and 1");
  EXPECT_EQ(errorOf({{"max_strands", 1e9}}), "hair.style.max_strands: must be an integer");
  EXPECT_EQ(errorOf({{"max_strands", 1000000000}}), "hair.style.max_strands: must be an integer between 0 and 150000");
  EXPECT_EQ(errorOf({{"points_per_strand", 1}}), "hair.style.points_per_strand: must be an integer between 2 and 1024");
  EXPECT_EQ(errorOf({{"sources", {{{"radius", 0}}}}}), "hair.style.sources[0].radius: must be positive");
  EXPECT_EQ(errorOf({{"root_color", {2, 0, 0}}}),
            "hair.style.root_color: must hold finite numbers of magnitude at most 1");
  EXPECT_EQ(errorOf({{"preset", "bob"}, {"length", -1}}), "hair.style.length: must be positive");
  EXPECT_EQ(fieldError([&] {
              hairSectionFromJson(json{{"strands", -5}});
            }),
            "hair.strands: must be an integer between 0 and 150000");
  EXPECT_EQ(fieldError([&] {
              hairSectionFromJson(json{{"scalp", {{"kind", "faces"}, {"faces", {1, -2}}}}});
            }),
            "hair.scalp.faces: must hold face indices (whole numbers from 0)");
}

TEST(Utf8, FindsTheFirstInvalidByte) {
  EXPECT_EQ(firstInvalidUtf8("plain"), std::string::npos);
  EXPECT_EQ(firstInvalidUtf8("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"), std::string::npos);
  EXPECT_EQ(firstInvalidUtf8("ab\xff"), 2u);
  EXPECT_EQ(firstInvalidUtf8("\xc0\xaf"), 0u);       // overlong '/'
  EXPECT_EQ(firstInvalidUtf8("x\xed\xa0\x80"), 1u);  // a surrogate
  EXPECT_EQ(firstInvalidUtf8("\xe2\x82"), 0u);       // cut short
  EXPECT_EQ(repairedUtf8("a\xff"
                         "b"),
            "a\xef\xbf\xbd"
            "b");
  EXPECT_EQ(firstInvalidUtf8(repairedUtf8("\xc0\xaf\xe2\x82")), std::string::npos);
}

TEST(IsolatedRun, ReportsSuccessFailureCrashAndTimeout) {
  EXPECT_TRUE(runIsolated([] { return true; }).ok);
  EXPECT_EQ(runIsolated([] { return false; }).problem, "failed");
  EXPECT_EQ(runIsolated([]() -> bool { throw std::runtime_error("no"); }).problem, "failed");
  const IsolatedOutcome crash = runIsolated([]() -> bool { std::abort(); });
  EXPECT_FALSE(crash.ok);
  EXPECT_NE(crash.problem.find("SIGABRT"), std::string::npos) << crash.problem;
  IsolationLimits quick;
  quick.seconds = 0.2;
  const IsolatedOutcome hang = runIsolated(
      [] {
        for (;;) pause();
        return true;
      },
      quick);
  EXPECT_EQ(hang.problem, "took longer than 0 s");
  // A runtime that stops the process with an exit code of its own (a
  // sanitizer's report) is a crash, not a failure to read.
  EXPECT_EQ(runIsolated([]() -> bool { std::_Exit(1); }).problem, "crashed (exit code 1)");
}

TEST(IsolatedRun, AFailureBringsItsReasonBack) {
  const IsolatedOutcome said = runIsolated([](std::string& reason) {
    reason = "no such node";
    return false;
  });
  EXPECT_EQ(said.problem, "failed");
  EXPECT_EQ(said.reason, "no such node");
  const IsolatedOutcome thrown = runIsolated([](std::string&) -> bool { throw std::runtime_error("bad header"); });
  EXPECT_EQ(thrown.reason, "bad header");
  const std::string longReason(10000, 'x');  // more than a pipe's atomic write: cut, never blocking
  const IsolatedOutcome cut = runIsolated([&](std::string& reason) {
    reason = longReason;
    return false;
  });
  EXPECT_EQ(cut.reason, longReason.substr(0, 4096));
  EXPECT_TRUE(runIsolated([](std::string&) { return true; }).reason.empty());
}

}  // namespace
}  // namespace mq
