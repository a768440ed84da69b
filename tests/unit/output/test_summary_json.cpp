#include "plyform/output/summary_json.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "scratch_dir.hpp"

namespace plyform::output {
namespace {

using testing::read_text;
using testing::ScratchDir;

// ---- A tiny strict JSON parser (RFC 8259), enough to check what we write -----------------

struct Json;
using JsonObject = std::map<std::string, Json>;
using JsonArray = std::vector<Json>;
struct Json {
  std::variant<std::nullptr_t, bool, double, std::string, JsonArray, JsonObject> value;
};

class JsonParser {
 public:
  explicit JsonParser(std::string_view text) : text_(text) {}

  Json parse_document() {
    Json v = parse_value();
    skip_space();
    if (pos_ != text_.size()) {
      fail("trailing text");
    }
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at " + std::to_string(pos_));
  }
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' ||
                                   text_[pos_] == '\r' || text_[pos_] == '\t')) {
      ++pos_;
    }
  }
  bool take(std::string_view word) {
    if (text_.substr(pos_, word.size()) == word) {
      pos_ += word.size();
      return true;
    }
    return false;
  }
  void expect(char c) {
    skip_space();
    if (pos_ >= text_.size() || text_[pos_] != c) {
      fail(std::string("expected ") + c);
    }
    ++pos_;
  }
  Json parse_value() {
    skip_space();
    if (pos_ >= text_.size()) {
      fail("unexpected end");
    }
    const char c = text_[pos_];
    if (c == '{') {
      ++pos_;
      JsonObject object;
      skip_space();
      if (take("}")) {
        return {object};
      }
      do {
        skip_space();
        std::string key = parse_string();
        expect(':');
        if (!object.emplace(key, parse_value()).second) {
          fail("duplicate key " + key);
        }
        skip_space();
      } while (take(","));
      expect('}');
      return {object};
    }
    if (c == '[') {
      ++pos_;
      JsonArray array;
      skip_space();
      if (take("]")) {
        return {array};
      }
      do {
        array.push_back(parse_value());
        skip_space();
      } while (take(","));
      expect(']');
      return {array};
    }
    if (c == '"') {
      return {parse_string()};
    }
    if (take("null")) {
      return {nullptr};
    }
    if (take("true")) {
      return {true};
    }
    if (take("false")) {
      return {false};
    }
    return {parse_number()};
  }
  double parse_number() {
    const std::size_t start = pos_;
    if (pos_ < text_.size() && text_[pos_] == '-') {
      ++pos_;
    }
    const auto digits = [&] {
      const std::size_t from = pos_;
      while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
        ++pos_;
      }
      if (pos_ == from) {
        fail("digit expected");
      }
    };
    if (take("0")) {
    } else {
      digits();
    }
    if (take(".")) {
      digits();
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) {
        ++pos_;
      }
      digits();
    }
    double value = 0.0;
    std::from_chars(text_.data() + start, text_.data() + pos_, value);
    return value;
  }
  static void append_utf8(std::string& out, unsigned code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }
  std::string parse_string() {
    if (pos_ >= text_.size() || text_[pos_] != '"') {
      fail("string expected");
    }
    ++pos_;
    std::string out;
    while (true) {
      if (pos_ >= text_.size()) {
        fail("unterminated string");
      }
      const char c = text_[pos_++];
      if (c == '"') {
        return out;
      }
      if (static_cast<unsigned char>(c) < 0x20) {
        fail("raw control character in string");
      }
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= text_.size()) {
        fail("unterminated escape");
      }
      const char e = text_[pos_++];
      switch (e) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u': {
          unsigned code = 0;
          const auto hex = text_.substr(pos_, 4);
          if (hex.size() != 4 ||
              std::from_chars(hex.data(), hex.data() + 4, code, 16).ptr != hex.data() + 4) {
            fail("bad \\u escape");
          }
          pos_ += 4;
          append_utf8(out, code);
          break;
        }
        default:
          fail("bad escape");
      }
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

const Json& member(const Json& object, const std::string& key) {
  return std::get<JsonObject>(object.value).at(key);
}

RunSummary example_summary() {
  RunSummary s;
  s.deck = "decks/two \"plies\".k";
  s.version = "0.1.0";
  s.cycles = 123456;
  s.final_time = 0.005;
  s.end_time = 0.005;
  s.wall_seconds = 12.5;
  s.element_cycles_per_second = 2.5e7;
  s.energy_ratio = 1.0012;
  s.dt_initial = 1.2e-7;
  s.dt_final = 1.1e-7;
  s.added_mass = 0.0;
  s.added_mass_ratio = 0.0;
  s.nodes = 1000;
  s.elements = 800;
  s.deformable_elements = 700;
  s.threads = 2;
  s.ranks = 3;
  s.warnings = {"line one\nline \"two\"", "tab\there, back\\slash, bell\x07"};
  s.loop_seconds = 12.0;
  s.timing = {{"elements", "shells ELFORM 2 (Belytschko-Tsay), *MAT_ELASTIC", 9.0},
              {"other", "the loop's own checks, between the passes", 3.0}};
  s.rank_timing = {{0, 12.0, {{"elements", 9.0}, {"ranks", 1.5}}},
                   {1, 11.5, {{"elements", 10.0}, {"ranks", 0.25}}}};
  s.rebalancing = {2, {0.375, 0.625}, 1.25, 1.0};
  s.moved_nodes = {520, 530, 515};
  return s;
}

TEST(SummaryJson, ExpectedText) {
  const std::string expected = R"({
  "status": "normal termination",
  "deck": "decks/two \"plies\".k",
  "version": "0.1.0",
  "cycles": 123456,
  "final_time": 0.005,
  "end_time": 0.005,
  "wall_seconds": 12.5,
  "element_cycles_per_second": 25000000,
  "energy_ratio": 1.0012,
  "dt_initial": 1.2e-07,
  "dt_final": 1.1e-07,
  "added_mass": 0,
  "added_mass_ratio": 0,
  "nodes": 1000,
  "elements": 800,
  "deformable_elements": 700,
  "threads": 2,
  "ranks": 3,
  "rebalancing": {"splits": 2, "shares": [0.375, 0.625], "first_imbalance": 1.25, "last_imbalance": 1},
  "moved_nodes": [520, 530, 515],
  "restarted_at": null,
  "checkpoint": "",
  "thermal_steps": 0,
  "thermal_iterations": 0,
  "heat_stored": 0,
  "heat_entered": 0,
  "warnings": [
    "line one\nline \"two\"",
    "tab\there, back\\slash, bell\u0007"
  ],
  "distrust": [],
  "timing": {"loop_seconds": 12, "passes": [
    {"group": "elements", "pass": "shells ELFORM 2 (Belytschko-Tsay), *MAT_ELASTIC", "seconds": 9, "share": 0.75},
    {"group": "other", "pass": "the loop's own checks, between the passes", "seconds": 3, "share": 0.25}
  ]},
  "rank_timing": [
    {"rank": 0, "loop_seconds": 12, "groups": {"elements": 9, "ranks": 1.5}},
    {"rank": 1, "loop_seconds": 11.5, "groups": {"elements": 10, "ranks": 0.25}}
  ]
}
)";
  EXPECT_EQ(summary_json_text(example_summary()), expected);
}

TEST(SummaryJson, ParsesBackToTheSameValues) {
  const RunSummary s = example_summary();
  const Json doc = JsonParser(summary_json_text(s)).parse_document();
  EXPECT_EQ(std::get<std::string>(member(doc, "status").value), s.status);
  EXPECT_EQ(std::get<std::string>(member(doc, "deck").value), s.deck);
  EXPECT_EQ(std::get<double>(member(doc, "cycles").value), 123456.0);
  EXPECT_EQ(std::get<double>(member(doc, "dt_initial").value), s.dt_initial);
  EXPECT_EQ(std::get<double>(member(doc, "energy_ratio").value), s.energy_ratio);
  const auto& warnings = std::get<JsonArray>(member(doc, "warnings").value);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(std::get<std::string>(warnings[0].value), s.warnings[0]);
  EXPECT_EQ(std::get<std::string>(warnings[1].value), s.warnings[1]);
  const Json& timing = member(doc, "timing");
  EXPECT_EQ(std::get<double>(member(timing, "loop_seconds").value), 12.0);
  const auto& passes = std::get<JsonArray>(member(timing, "passes").value);
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_EQ(std::get<std::string>(member(passes[1], "group").value), "other");
  EXPECT_EQ(std::get<double>(member(passes[0], "share").value), 0.75);
  const auto& ranks = std::get<JsonArray>(member(doc, "rank_timing").value);
  ASSERT_EQ(ranks.size(), 2u);
  EXPECT_EQ(std::get<double>(member(ranks[1], "loop_seconds").value), 11.5);
  EXPECT_EQ(std::get<double>(member(member(ranks[1], "groups"), "ranks").value), 0.25);
  const auto& rebalancing = member(doc, "rebalancing");
  EXPECT_EQ(std::get<double>(member(rebalancing, "splits").value), 2.0);
  EXPECT_EQ(std::get<double>(member(rebalancing, "first_imbalance").value), 1.25);
  const auto& moved = std::get<JsonArray>(member(doc, "moved_nodes").value);
  ASSERT_EQ(moved.size(), 3u);
  EXPECT_EQ(std::get<double>(moved[1].value), 530.0);
}

TEST(SummaryJson, ErrorStatusNonFiniteNumbersAndNoWarnings) {
  RunSummary s;
  s.status = "error: negative Jacobian in element 17";
  s.energy_ratio = std::numeric_limits<double>::quiet_NaN();
  s.wall_seconds = std::numeric_limits<double>::infinity();
  const std::string text = summary_json_text(s);
  const Json doc = JsonParser(text).parse_document();
  EXPECT_EQ(std::get<std::string>(member(doc, "status").value), s.status);
  EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(member(doc, "energy_ratio").value));
  EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(member(doc, "wall_seconds").value));
  EXPECT_TRUE(std::get<JsonArray>(member(doc, "warnings").value).empty());
  EXPECT_NE(text.find("\"warnings\": [],\n"), std::string::npos);
}

TEST(SummaryJson, DistrustedBooksWithTheirTimes) {
  RunSummary s;
  s.status = "completed, results not to be trusted";
  s.distrust = {{"hourglass energy 19 % of the largest internal energy", 4.7e-4},
                {"contact 3 energy -2 \"negative\"", 1e-3}};
  const Json doc = JsonParser(summary_json_text(s)).parse_document();
  EXPECT_EQ(std::get<std::string>(member(doc, "status").value), s.status);
  const auto& d = std::get<JsonArray>(member(doc, "distrust").value);
  ASSERT_EQ(d.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(std::get<std::string>(member(d[k], "reason").value), s.distrust[k].reason);
    EXPECT_EQ(std::get<double>(member(d[k], "time").value), s.distrust[k].time);
  }
}

TEST(SummaryJson, Utf8KeptAndInvalidBytesReplaced) {
  EXPECT_EQ(json_string("25 \xC2\xB0"
                        "C \xE2\x80\x94 ok"),
            "\"25 \xC2\xB0"
            "C \xE2\x80\x94 ok\"");
  EXPECT_EQ(json_string("bad \xFF byte"), "\"bad \\ufffd byte\"");
  EXPECT_EQ(json_string("cut \xE2\x80"), "\"cut \\ufffd\\ufffd\"");
  EXPECT_EQ(json_string("overlong \xC0\xAF"), "\"overlong \\ufffd\\ufffd\"");
  EXPECT_EQ(json_string(std::string_view("nul\0x", 5)), "\"nul\\u0000x\"");
  EXPECT_NO_THROW(JsonParser(json_string("bad \xFF\x80\xC3")).parse_document());
}

TEST(SummaryJson, WrittenAtomically) {
  ScratchDir dir;
  const auto file = dir / "summary.json";
  write_summary_json(file, example_summary());
  EXPECT_EQ(read_text(file), summary_json_text(example_summary()));
  RunSummary second;
  second.status = "error: stopped";
  write_summary_json(file, second);  // replaces the first
  EXPECT_EQ(read_text(file), summary_json_text(second));
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"summary.json"});
}

TEST(SummaryJson, FailureNamesTheFile) {
  ScratchDir dir;
  const auto file = dir / "no_such_folder" / "summary.json";
  try {
    write_summary_json(file, RunSummary{});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("summary.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plyform::output
