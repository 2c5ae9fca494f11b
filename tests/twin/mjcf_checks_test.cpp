// MJCF load checks (issue 12): includes relative to the including file;
// negative, zero, infinite, NaN and subnormal masses / inertias refused
// with the file, line and body.
#include <gtest/gtest.h>

#include <string>

#include "twin/load_builder.hpp"
#include "twin/mjcf_checks.hpp"

namespace sreh {
namespace {

std::string error_of(const std::string& xml) {
  try {
    check_mjcf_inertials(xml, "load.xml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MjcfChecks, RefusesBadMassesNamingLineAndBody) {
  const std::string head = "<body name=\"arm\">\n";
  EXPECT_EQ(error_of(head + "<inertial mass=\"-1\" diaginertia=\"1 1 1\"/></body>"),
            "load.xml:2: body 'arm': <inertial mass> -1 is negative");
  EXPECT_NE(error_of(head + "<inertial mass=\"nan\" diaginertia=\"1 1 1\"/></body>").find("not finite"), std::string::npos);
  EXPECT_NE(error_of(head + "<geom mass=\"inf\"/></body>").find("not finite"), std::string::npos);
  EXPECT_NE(error_of(head + "<inertial mass=\"1\" diaginertia=\"1 1 1e-320\"/></body>").find("subnormal"), std::string::npos);
  EXPECT_NE(error_of(head + "<inertial mass=\"1e-400\" diaginertia=\"1 1 1\"/></body>").find("too small"), std::string::npos);
  EXPECT_NE(error_of(head + "<inertial mass=\"0\" diaginertia=\"1 1 1\"/></body>").find("above 0"), std::string::npos);
  EXPECT_NE(error_of(head + "<geom density=\"-7800\"/></body>").find("negative"), std::string::npos);
}

TEST(MjcfChecks, AcceptsOrdinaryLoads) {
  EXPECT_EQ(error_of("<body name=\"load\"><inertial mass=\"0.2\" diaginertia=\"1e-4 1e-4 2e-4\"/>"
                     "<geom mass=\"0\" type=\"box\" size=\"0.1 0.1 0.1\"/>"
                     "<inertial mass=\"1\" fullinertia=\"1 1 1 -0.1 0 0\"/></body>"),
            "");
}

TEST(InertiaLoad, SubnormalInertiaIsRefusedNotANaN) {
  // 1e-320 g cm^2 used to give a NaN mass reported as "XML contains a NaN".
  try {
    compose_model_xml(InertiaLoad{1e-320}, {});
    FAIL() << "not refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("too small to model"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace sreh
