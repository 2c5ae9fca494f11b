// Modbus TCP framing and the per-connection request handling (issue 27):
// MBAP checks, exact PDU lengths, exception function bytes, per-connection
// ISDU windows, FC 23, and what a client without write rights may do.
#include <gtest/gtest.h>

#include "serve/modbus_frame.hpp"
#include "serve/modbus_handler.hpp"

namespace sreh::serve::modbus {
namespace {

std::vector<uint8_t> mbap(std::vector<uint8_t> pdu, uint16_t protocol = 0, int length = -1) {
  const int len = length < 0 ? static_cast<int>(pdu.size()) + 1 : length;
  std::vector<uint8_t> f(7 + pdu.size());
  f[0] = 0x12;
  f[1] = 0x34;
  f[2] = static_cast<uint8_t>(protocol >> 8);
  f[3] = static_cast<uint8_t>(protocol & 0xFF);
  f[4] = static_cast<uint8_t>(len >> 8);
  f[5] = static_cast<uint8_t>(len & 0xFF);
  f[6] = 0x01;
  std::copy(pdu.begin(), pdu.end(), f.begin() + 7);
  return f;
}

TEST(ModbusFrame, HeaderChecks) {
  const auto read = mbap({3, 0x03, 0xE9, 0, 4});
  EXPECT_EQ(next_frame(read).status, Frame::Status::Ready);
  EXPECT_EQ(next_frame(read).size, read.size());
  EXPECT_EQ(next_frame(std::span(read).first(9)).status, Frame::Status::NeedMore);
  EXPECT_EQ(next_frame(std::span(read).first(3)).status, Frame::Status::NeedMore);
  EXPECT_EQ(next_frame(mbap({3, 0, 0, 0, 1}, 1)).status, Frame::Status::Bad);      // protocol id 1
  EXPECT_EQ(next_frame(mbap({}, 0, 1)).status, Frame::Status::Bad);                // length 1: no function
  EXPECT_EQ(next_frame(mbap({3}, 0, 261)).status, Frame::Status::Bad);             // longer than any ADU
  EXPECT_EQ(next_frame(std::vector<uint8_t>(10240, 0xA5)).status, Frame::Status::Bad); // garbage
}

TEST(ModbusFrame, PduLengthMustMatchItsFields) {
  EXPECT_TRUE(pdu_length_matches(std::vector<uint8_t>{3, 0, 0, 0, 1}));
  EXPECT_FALSE(pdu_length_matches(std::vector<uint8_t>{3, 0, 0, 0, 1, 0}));
  EXPECT_FALSE(pdu_length_matches(std::vector<uint8_t>{6, 0, 0}));
  EXPECT_TRUE(pdu_length_matches(std::vector<uint8_t>{16, 0x03, 0xF2, 0, 1, 2, 0, 1}));
  EXPECT_FALSE(pdu_length_matches(std::vector<uint8_t>{16, 0x03, 0xF2, 0, 1, 4, 0, 1}));
  EXPECT_TRUE(pdu_length_matches(std::vector<uint8_t>{23, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 0}));
  EXPECT_FALSE(pdu_length_matches(std::vector<uint8_t>{23, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0}));
  EXPECT_TRUE(pdu_length_matches(std::vector<uint8_t>{0x2B, 0x0E})); // unknown: answered with exception 01
}

TEST(ModbusFrame, ExceptionFunctionByteIsFcOr0x80) {
  for (uint8_t fc : {uint8_t{0x04}, uint8_t{0x80}, uint8_t{0xFF}}) {
    const auto frame = mbap({fc, 0});
    const auto a = exception_answer(split(frame), kIllegalFunction);
    ASSERT_EQ(a.size(), 9u);
    EXPECT_EQ(a[7], fc | 0x80);
    EXPECT_EQ(a[8], 1);
    EXPECT_EQ(a[0], 0x12); // transaction echoed
    EXPECT_EQ(a[5], 3);    // length: unit + 2
  }
}

struct Handler : ::testing::Test {
  Hub hub{std::vector<TwinConfig>(1), HubOptions{}};
  EventTrackers events = EventTrackers(1);
  Session a{1}, b{1};

  std::vector<uint8_t> run(Session& s, std::vector<uint8_t> pdu) {
    EXPECT_TRUE(pdu_length_matches(pdu));
    return handle(hub, s, events, pdu).pdu;
  }
  static std::vector<uint8_t> write_multiple(int addr, std::vector<uint16_t> values) {
    std::vector<uint8_t> pdu{16, static_cast<uint8_t>(addr >> 8), static_cast<uint8_t>(addr & 0xFF), 0,
                             static_cast<uint8_t>(values.size()), static_cast<uint8_t>(2 * values.size())};
    for (uint16_t v : values) {
      pdu.push_back(static_cast<uint8_t>(v >> 8));
      pdu.push_back(static_cast<uint8_t>(v & 0xFF));
    }
    return pdu;
  }
  static std::vector<uint8_t> read(int addr, int count) {
    return {3, static_cast<uint8_t>(addr >> 8), static_cast<uint8_t>(addr & 0xFF), 0, static_cast<uint8_t>(count)};
  }
  static uint16_t reg(const std::vector<uint8_t>& answer, int i) {
    return be16(&answer[static_cast<std::size_t>(2 + 2 * i)]);
  }
};

TEST_F(Handler, IsduWindowIsPerConnection) {
  run(a, write_multiple(1100, {1, 64, 1, 0}));     // a reads 64.1 (300)
  run(b, write_multiple(1100, {2, 64, 1, 2, 5}));  // b writes 5 to 64.1: refused or not, its own answer
  const auto ra = run(a, read(1300, 5));
  EXPECT_EQ(reg(ra, 0), 1);      // a's sequence: its one request
  EXPECT_EQ(reg(ra, 1), 1);      // ok
  EXPECT_EQ(reg(ra, 4), 300);    // a's answer, not b's
  const auto rb = run(b, read(1100, 2));
  EXPECT_EQ(reg(rb, 0), 2);      // b's request window
  EXPECT_EQ(reg(rb, 1), 64);
  Session one_shot{1};           // never wrote a request: sees the port's last one (mbpoll's way)
  EXPECT_EQ(reg(run(one_shot, read(1100, 1)), 0), 2);
}

TEST_F(Handler, Fc23WritesTheRequestAndReadsTheAnswerInOneGo) {
  // FC 23: read 1300..1304 after writing the ISDU read request of 65.1 at 1100.
  std::vector<uint8_t> pdu{23, 0x05, 0x14, 0, 5, 0x04, 0x4C, 0, 4, 8, 0, 1, 0, 65, 0, 1, 0, 0};
  const auto r = run(a, pdu);
  ASSERT_EQ(r[0], 23);
  ASSERT_EQ(r[1], 10);
  EXPECT_EQ(reg(r, 0), 1);       // sequence
  EXPECT_EQ(reg(r, 1), 1);       // ok
  EXPECT_EQ(reg(r, 3), 2);       // two octets
}

TEST_F(Handler, WithoutWriteRightsIsduReadsWorkWritesDoNot) {
  a.may_write = false;
  EXPECT_EQ(run(a, write_multiple(1100, {1, 64, 1, 0}))[0], 16);   // an ISDU read request: allowed
  EXPECT_EQ(reg(run(a, read(1304, 1)), 0), 300);
  const auto w = run(a, write_multiple(1100, {2, 64, 1, 2, 400}));  // an ISDU write: refused
  EXPECT_EQ(w, (std::vector<uint8_t>{0x90, kIllegalFunction}));
  EXPECT_EQ(run(a, std::vector<uint8_t>{6, 0x03, 0xF4, 0, 1}), (std::vector<uint8_t>{0x86, kIllegalFunction})); // PD out
  EXPECT_EQ(hub.port(1).twin.isdu_read(64, 1).data, (std::vector<uint8_t>{0x01, 0x2C}));
  EXPECT_FALSE(hub.port(1).twin.pd_out().motor_on);
}

TEST_F(Handler, AddressesOutsideTheMapAreException02) {
  EXPECT_EQ(run(a, read(1990, 20)), (std::vector<uint8_t>{0x83, kIllegalAddress}));
  EXPECT_EQ(run(a, read(0, 0)), (std::vector<uint8_t>{0x83, kIllegalValue}));
  const auto g = run(a, read(0, 10)); // the global block: listed registers, then 0
  EXPECT_EQ(reg(g, 0), 1);
  EXPECT_EQ(reg(g, 1), 1);
  EXPECT_EQ(reg(g, 5), 0);
  EXPECT_EQ(run(a, std::vector<uint8_t>{6, 0x03, 0xE9, 0, 1}), (std::vector<uint8_t>{0x86, kIllegalAddress}));
}

} // namespace
} // namespace sreh::serve::modbus
