// One reader of process data out fields (scenarios/pd_out_fields.hpp) for
// scenario pd: steps and serve's PUT .../processdata/out, driven by the
// layout table kPdOutFields (manual 2.2, 2.5).
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>

#include "scenarios/pd_out_fields.hpp"

namespace sreh {
namespace {

// A request as key -> number (booleans as 0/1); errors as std::runtime_error.
class MapSource final : public PdFieldSource {
 public:
  explicit MapSource(std::map<std::string, double> values) : v_(std::move(values)) {}
  bool has(std::string_view key) const override { return v_.count(std::string(key)) != 0; }
  double number(std::string_view key, double lo, double hi) const override {
    const double x = v_.at(std::string(key));
    if (x < lo || x > hi) fail(key, std::string(key) + " out of range");
    return x;
  }
  int64_t integer(std::string_view key, int64_t lo, int64_t hi) const override {
    return static_cast<int64_t>(number(key, static_cast<double>(lo), static_cast<double>(hi)));
  }
  bool boolean(std::string_view key) const override { return v_.at(std::string(key)) != 0; }
  [[noreturn]] void fail(std::string_view, const std::string& message) const override { throw std::runtime_error(message); }

 private:
  std::map<std::string, double> v_;
};

TEST(PdOutFields, KeysAreTheTableNamesPlusTargetDeg) {
  const auto& keys = pd_out_keys();
  ASSERT_EQ(keys.size(), kPdOutFields.size() + 1);
  EXPECT_EQ(keys.front(), "target_deg");
  for (std::size_t i = 0; i < kPdOutFields.size(); ++i) EXPECT_EQ(keys[i + 1], kPdOutFields[i].name);
}

// Every field of the table is read and lands in its own bit of the frame:
// setting each one alone changes exactly the bits the table gives it.
TEST(PdOutFields, EveryTableFieldReachesItsBitsOfTheFrame) {
  for (const PdField& f : kPdOutFields) {
    ProcessDataOut out;
    const double value = f.type == PdFieldType::Bool ? 1 : f.type == PdFieldType::UInt8 ? 5 : -3;
    apply_pd_out(read_pd_out(MapSource({{std::string(f.name), value}}), "pd"), out);
    const PdOutFrame frame = encode(out);
    uint64_t bits = 0;
    for (uint8_t b : frame) bits = (bits << 8) | b;
    const uint64_t mask = ((uint64_t{1} << f.bit_length) - 1) << f.bit_offset;
    EXPECT_NE(bits & mask, 0u) << f.name;
    EXPECT_EQ(bits & ~mask, 0u) << f.name;
  }
}

TEST(PdOutFields, LeftOutFieldsKeepTheirValue) {
  ProcessDataOut out;
  out.motor_on = true;
  out.parameter_set = 3;
  apply_pd_out(read_pd_out(MapSource({{"move", 1}}), "pd"), out);
  EXPECT_TRUE(out.motor_on);
  EXPECT_TRUE(out.move);
  EXPECT_EQ(out.parameter_set, 3);
}

TEST(PdOutFields, TargetInDegreesBecomesWireCounts) { // manual 2.5: 2^16 counts per revolution
  EXPECT_EQ(*read_pd_out(MapSource({{"target_deg", 90}}), "pd").target_raw, 16384);
  EXPECT_EQ(*read_pd_out(MapSource({{"target_raw", -7}}), "pd").target_raw, -7);
}

TEST(PdOutFields, RefusesBothTargetsAndTargetsBeyondTheInt32Wire) {
  try {
    read_pd_out(MapSource({{"target_deg", 1}, {"target_raw", 2}}), "3.pd");
    FAIL() << "both targets accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "3.pd: give target_deg or target_raw, not both");
  }
  // +2^15 revolutions is 2^31 counts: one past int32 (manual 2.5).
  EXPECT_THROW(read_pd_out(MapSource({{"target_deg", kWireLimitDeg}}), "pd"), std::runtime_error);
  EXPECT_NO_THROW(read_pd_out(MapSource({{"target_deg", -kWireLimitDeg}}), "pd"));
  EXPECT_THROW(read_pd_out(MapSource({{"parameter_set", 256}}), "pd"), std::runtime_error);
}

} // namespace
} // namespace sreh
