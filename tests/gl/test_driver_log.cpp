// Translation of driver log lines to GCC-style file:line:column messages (no GL).
#include <gtest/gtest.h>

#include <vector>

#include "prism/gl/driver_log.hpp"

namespace {

using prism::gl::SourceName;
using prism::gl::translateDriverLog;

const std::vector<SourceName> kFiles = {{0, "shaders/phong.frag"}, {1, "modules/lights.glsl"}};

TEST(DriverLog, MesaLinesGetPathLineAndColumn) {
    EXPECT_EQ(translateDriverLog("1:12(3): error: `foo' undeclared", kFiles),
              "modules/lights.glsl:12:3: error: `foo' undeclared");
    EXPECT_EQ(translateDriverLog("0:7(15): warning: unused", kFiles), "shaders/phong.frag:7:15: warning: unused");
}

TEST(DriverLog, OtherVendorsShapes) {
    EXPECT_EQ(translateDriverLog("1(12) : error C1008: undefined variable \"foo\"", kFiles),
              "modules/lights.glsl:12: error C1008: undefined variable \"foo\"");
    EXPECT_EQ(translateDriverLog("ERROR: 0:4: 'x' : undeclared identifier", kFiles),
              "shaders/phong.frag:4: error: 'x' : undeclared identifier");
}

TEST(DriverLog, UnmatchedLinesAndUnknownSourcesAreKept) {
    const std::string log =
        "1:3(1): error: first\n"
        "error: linking failed\n"
        "7:2(1): error: source seven is not in the table\n"
        "\n"
        "0:1(1): error: last";
    EXPECT_EQ(translateDriverLog(log, kFiles),
              "modules/lights.glsl:3:1: error: first\n"
              "error: linking failed\n"
              "7:2(1): error: source seven is not in the table\n"
              "\n"
              "shaders/phong.frag:1:1: error: last");
    EXPECT_EQ(translateDriverLog("", kFiles), "");
    EXPECT_EQ(translateDriverLog("1:x(3): odd", kFiles), "1:x(3): odd");
}

}  // namespace
