// The checkpoint's records and file: what visit_state saves comes back bit for bit, and a file
// that is not the one written is refused with the reason.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "plyform/core/state_archive.hpp"
#include "plyform/engine/checkpoint_file.hpp"

namespace plyform {
namespace {

// Something with state, saved and restored by one function as the engine's owners do.
struct Owner {
  double t = 0.0;
  long cycle = 0;
  std::array<double, 3> centre{};
  std::vector<double> field;    // length fixed by the model
  std::vector<int> candidates;  // length is state
  std::vector<std::string> notes;
  void visit_state(core::StateArchive& a) {
    const auto scope = a.scope("owner");
    a.value("t", t);
    a.value("cycle", cycle);
    a.value("centre", centre);
    a.fixed("field", std::span<double>(field));
    a.array("candidates", candidates);
    a.strings("notes", notes);
  }
};

Owner example_owner() {
  Owner o;
  o.t = 1.0 / 3.0;
  o.cycle = 123456789012L;
  o.centre = {-0.0, std::numeric_limits<double>::denorm_min(), 1e300};
  o.field = {1.5, std::nan(""), -2.25};
  o.candidates = {7, 3, 9, 9};
  o.notes = {"first, with a comma", "", "a\nnew line"};
  return o;
}

core::StateArchive::Records saved(Owner o) {
  auto a = core::StateArchive::for_saving();
  o.visit_state(a);
  return a.take_records();
}

TEST(StateArchive, RestoresEveryFieldBitForBit) {
  const core::StateArchive::Records records = saved(example_owner());
  EXPECT_TRUE(records.count("owner/t"));
  EXPECT_TRUE(records.count("owner/field"));
  Owner back;
  back.field.assign(3, 0.0);
  auto a = core::StateArchive::for_loading(records);
  back.visit_state(a);
  const Owner o = example_owner();
  EXPECT_EQ(back.t, o.t);
  EXPECT_EQ(back.cycle, o.cycle);
  EXPECT_TRUE(std::signbit(back.centre[0]));
  EXPECT_EQ(back.centre[1], o.centre[1]);
  EXPECT_EQ(back.centre[2], o.centre[2]);
  EXPECT_EQ(back.field[0], 1.5);
  EXPECT_TRUE(std::isnan(back.field[1]));
  EXPECT_EQ(back.candidates, o.candidates);
  EXPECT_EQ(back.notes, o.notes);
}

TEST(StateArchive, ARecordThatDoesNotFitTheModelIsNamed) {
  const core::StateArchive::Records records = saved(example_owner());
  Owner other;
  other.field.assign(4, 0.0);  // the model has another length
  auto a = core::StateArchive::for_loading(records);
  try {
    other.visit_state(a);
    FAIL() << "no error";
  } catch (const core::StateError& e) {
    EXPECT_NE(std::string(e.what()).find("'owner/field' holds 3 values where the model has 4"),
              std::string::npos)
        << e.what();
  }
  core::StateArchive::Records missing = records;
  missing.erase("owner/cycle");
  auto b = core::StateArchive::for_loading(missing);
  Owner o;
  o.field.assign(3, 0.0);
  EXPECT_THROW(o.visit_state(b), core::StateError);
}

class CheckpointFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("plyform_checkpoint_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    file_ = dir_ / "d3dump";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string bytes() const {
    std::ifstream in(file_, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  void put(const std::string& b) const {
    std::ofstream out(file_, std::ios::binary | std::ios::trunc);
    out << b;
  }
  std::string refusal(std::uint64_t fingerprint) const {
    try {
      (void)engine::read_checkpoint(file_, fingerprint);
    } catch (const engine::CheckpointError& e) {
      return e.what();
    }
    return "accepted";
  }
  std::filesystem::path dir_, file_;
};

constexpr std::uint64_t kDeck = 0x1234abcd5678ef90ull;

TEST_F(CheckpointFile, ReadsBackWhatWasWritten) {
  const core::StateArchive::Records records = saved(example_owner());
  engine::write_checkpoint(file_, kDeck, records);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "d3dump.tmp"));
  EXPECT_EQ(engine::read_checkpoint(file_, kDeck), records);
}

TEST_F(CheckpointFile, ReplacesThePreviousOneWhole) {
  engine::write_checkpoint(file_, kDeck, saved(example_owner()));
  Owner later = example_owner();
  later.t = 2.0;
  const core::StateArchive::Records second = saved(later);
  engine::write_checkpoint(file_, kDeck, second);
  EXPECT_EQ(engine::read_checkpoint(file_, kDeck), second);
}

TEST_F(CheckpointFile, RefusesWhatIsNotTheCheckpointOfThisDeck) {
  EXPECT_NE(refusal(kDeck).find("no checkpoint"), std::string::npos);
  engine::write_checkpoint(file_, kDeck, saved(example_owner()));
  const std::string good = bytes();
  EXPECT_NE(refusal(kDeck + 1).find("belongs to another deck"), std::string::npos);

  put(good.substr(0, good.size() - 1));
  EXPECT_NE(refusal(kDeck).find("truncated"), std::string::npos) << refusal(kDeck);
  put(good.substr(0, 20));
  EXPECT_NE(refusal(kDeck).find("truncated"), std::string::npos) << refusal(kDeck);

  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x01);
  put(flipped);
  EXPECT_NE(refusal(kDeck).find("corrupted"), std::string::npos) << refusal(kDeck);

  std::string version = good;
  version[8] = static_cast<char>(version[8] + 1);  // the format version follows the magic
  put(version);
  EXPECT_NE(refusal(kDeck).find("format version " + std::to_string(engine::kCheckpointVersion + 1)),
            std::string::npos)
      << refusal(kDeck);

  put("*KEYWORD\n");
  EXPECT_NE(refusal(kDeck).find("not a plyform checkpoint"), std::string::npos);
}

}  // namespace
}  // namespace plyform
