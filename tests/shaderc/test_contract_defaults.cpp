// prism-shaderc's contract defaults as a program (issue 22, item 4): with no --contract it
// still knows Prism's contract, so a misspelled a_positon is a GCC-style warning at the
// stage's line; with Prism's contract a lygia-style program's own uniforms (u_time,
// u_resolution: fixtures of our own, not lygia's files) build without a word.
#include <gtest/gtest.h>

#include <string>

#include "tool_runner.hpp"

using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

const std::string kSource = PRISM_SOURCE_DIR;

// A toon shader in lygia's style: its own uniforms beside Prism's attribute names.
void writeToon(const ScratchDir& dir, const std::string& positionName) {
    dir.write("shaders/toon.vert", "#version 330 core\nin vec3 " + positionName +
                                       ";\nuniform float u_time;\n"
                                       "void main() { gl_Position = vec4(" +
                                       positionName + " * u_time, 1.0); }\n");
    dir.write("shaders/toon.frag",
              "#version 330 core\nuniform vec2 u_resolution;\nuniform float u_time;\n"
              "out vec4 frag;\n"
              "void main() { frag = vec4(gl_FragCoord.xy / u_resolution, sin(u_time), 1.0); }\n");
}

}  // namespace

TEST(ContractDefaults, WithoutContractAMisspelledAttributeIsAWarningAtItsLine) {
    ScratchDir dir("contract-defaults-warning");
    writeToon(dir, "a_positon");
    const auto run = runShaderc("-o gen/toon_shaders.hpp --base-dir . shaders", dir.str());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("shaders/toon.vert:2:9: warning: vertex attribute 'a_positon' is not in the binding "
                              "contract (Prism's contract, built into prism-shaderc), so the runtime would never feed "
                              "it (did you mean 'a_position'?)"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("u_time"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("u_resolution"), std::string::npos) << run.output;
    // The catalogue carries Prism's attribute locations, so the runtime's meshes can feed it.
    EXPECT_NE(readFile(dir.path() / "gen/toon_shaders.cpp").find("{\"a_position\", 0x8B51, 0}"), std::string::npos);
}

TEST(ContractDefaults, PrismsContractAcceptsALygiaStyleProgramsOwnUniforms) {
    ScratchDir dir("contract-defaults-lygia");
    writeToon(dir, "a_position");
    const auto run = runShaderc(
        "-o gen/toon_shaders.hpp --base-dir . --contract " + kSource + "/modules/contract.json shaders", dir.str());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("error"), std::string::npos) << run.output;
}
