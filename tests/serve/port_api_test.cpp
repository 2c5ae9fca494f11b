// The port operations every front shares (issue 18): checked completely
// before they touch the twin; refused ISDU writes carry the device's code
// and change nothing (manual chapter 6, iolink.md).
#include <gtest/gtest.h>

#include "device_logic/isdu.hpp"
#include "serve/port_api.hpp"

namespace sreh::serve {
namespace {

struct PortApi : ::testing::Test {
  Hub hub{std::vector<TwinConfig>(1), HubOptions{}};
  Hub::Port& port = hub.port(1);
};

TEST_F(PortApi, DecodedFieldsKeepWhatIsLeftOut_2_2) {
  apply_pd_out(port, Json{{"motor_on", true}});
  apply_pd_out(port, Json{{"target_deg", 90.0}, {"parameter_set", 1}});
  const Json pd = processdata_json(port);
  EXPECT_TRUE(pd["out"]["motor_on"].get<bool>());
  EXPECT_EQ(pd["out"]["target_raw"], 16384); // 2^16 counts per revolution, manual 2.5
  EXPECT_EQ(pd["out"]["raw"], "000040000101");
}

TEST_F(PortApi, RawFrameOfSixOctetsOnly) {
  apply_pd_out(port, Json{{"raw", "000040000103"}});
  EXPECT_TRUE(port.twin.pd_out().move);
  EXPECT_THROW(apply_pd_out(port, Json{{"raw", "0000400001"}}), RequestError);
  EXPECT_THROW(apply_pd_out(port, Json{{"raw", "00004000010300"}}), RequestError);
  EXPECT_THROW(apply_pd_out(port, Json{{"raw", "00004000010G"}}), RequestError);
}

TEST_F(PortApi, BadFieldChangesNothing) {
  apply_pd_out(port, Json{{"motor_on", true}});
  const ProcessDataOut before = port.twin.pd_out();
  // motor_on would be valid, the unknown key makes the whole request invalid
  EXPECT_THROW(apply_pd_out(port, Json{{"motor_on", false}, {"speed", 3}}), RequestError);
  EXPECT_THROW(apply_pd_out(port, Json{{"motor_on", false}, {"parameter_set", 300}}), RequestError);
  EXPECT_THROW(apply_pd_out(port, Json{{"target_deg", 1}, {"target_raw", 1}}), RequestError);
  EXPECT_EQ(port.twin.pd_out(), before);
}

TEST_F(PortApi, OutputsInvalidFlag_5) {
  apply_pd_out(port, Json{{"valid", false}});
  EXPECT_FALSE(port.outputs_valid);
  EXPECT_FALSE(processdata_json(port)["out"]["valid"].get<bool>());
}

TEST_F(PortApi, ParameterReadGivesRawWireValue_6_2) {
  const Json j = read_parameter(port, 64, 1); // maximum speed of parameter set 0
  EXPECT_EQ(j["value"], 300);
  EXPECT_EQ(j["raw"], "012C");
}

TEST_F(PortApi, RefusedWriteCarriesCodeAndChangesNothing) {
  try {
    write_parameter(port, 64, 1, Json{{"value", 50000}});
    FAIL() << "accepted an out-of-range value";
  } catch (const IsduRefused& e) {
    EXPECT_EQ(e.code, kIsduValueOutOfRange);
    EXPECT_EQ(http_status_for(e.code), 422);
  }
  EXPECT_EQ(read_parameter(port, 64, 1)["value"], 300);
}

TEST_F(PortApi, UnknownIndexIsTheDevicesAnswer) {
  try {
    read_parameter(port, 4242, 0);
    FAIL();
  } catch (const IsduRefused& e) {
    EXPECT_EQ(e.code, kIsduIndexNotAvailable);
    EXPECT_EQ(http_status_for(e.code), 404);
  }
}

TEST_F(PortApi, ValueMustFitItsWireType) {
  EXPECT_THROW(parameter_bytes(64, 1, Json{{"value", 70000}}), RequestError); // uint16
  EXPECT_THROW(parameter_bytes(64, 1, Json{{"value", "fast"}}), RequestError);
  EXPECT_THROW(parameter_bytes(64, 1, Json{{"value", 1}, {"raw", "01"}}), RequestError);
  EXPECT_EQ(parameter_bytes(64, 1, Json{{"raw", "012c"}}), (std::vector<uint8_t>{0x01, 0x2C}));
}

TEST_F(PortApi, FaultsCheckedBeforeAnyIsApplied) {
  EXPECT_THROW(apply_faults(port, Json{{"flange_blocked", true}, {"supply_V", 100}}), RequestError);
  EXPECT_FALSE(port.twin.flange_blocked());
  const Json f = apply_faults(port, Json{{"flange_blocked", true}, {"supply_V", 18.5}});
  EXPECT_TRUE(port.twin.flange_blocked());
  EXPECT_EQ(f["supply_V"], 18.5);
  EXPECT_THROW(apply_faults(port, Json::object()), RequestError);
}

TEST_F(PortApi, MalformedBodies) {
  EXPECT_THROW(parse_body("{"), RequestError);
  EXPECT_THROW(parse_body("[]"), RequestError);
  EXPECT_THROW(parse_body(""), RequestError);
  EXPECT_NO_THROW(parse_body("{\"a\":1}"));
}

} // namespace
} // namespace sreh::serve
