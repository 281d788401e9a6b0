// Diagnostics: GCC and MSVC formats, the "included from" chain, and de-duplication.
#include <gtest/gtest.h>

#include <sstream>

#include "diagnostics.hpp"

using namespace prism::shaderc;

TEST(Diagnostics, GccFormatWithIncludeChain) {
    Diagnostic d = makeError("modules/lights.glsl", 12, 5, "'x': undeclared identifier");
    d.includedFrom = {{"modules/lighting.glsl", 4}, {"shader_sources/phong.frag", 3}};
    EXPECT_EQ(formatDiagnostic(d, ErrorFormat::Gcc),
              "modules/lights.glsl:12:5: error: 'x': undeclared identifier\n"
              "  included from modules/lighting.glsl:4\n"
              "  included from shader_sources/phong.frag:3\n");
}

TEST(Diagnostics, MsvcFormat) {
    Diagnostic d = makeError("a.glsl", 3, 0, "boom");
    EXPECT_EQ(formatDiagnostic(d, ErrorFormat::Msvc), "a.glsl(3,1): error: boom\n");
}

TEST(Diagnostics, FileWithoutLineAndNoFile) {
    EXPECT_EQ(formatDiagnostic(makeError("x.vert", 0, 0, "missing"), ErrorFormat::Gcc), "x.vert: error: missing\n");
    EXPECT_EQ(formatDiagnostic(makeError("", 0, 0, "usage"), ErrorFormat::Gcc), "prism-shaderc: error: usage\n");
}

TEST(Diagnostics, NotesFollowTheirError) {
    Diagnostic d = makeError("a.frag", 2, 1, "mismatch");
    d.notes.push_back({Severity::Note, "a.vert", 7, 3, "declared here", {}, {}});
    EXPECT_EQ(formatDiagnostic(d, ErrorFormat::Gcc), "a.frag:2:1: error: mismatch\na.vert:7:3: note: declared here\n");
}

TEST(Diagnostics, SinkDropsRepeatsFromOtherShaders) {
    DiagnosticSink sink;
    Diagnostic fromPhong = makeError("m.glsl", 3, 1, "bad");
    fromPhong.includedFrom = {{"phong.frag", 1}};
    Diagnostic fromGouraud = makeError("m.glsl", 3, 1, "bad");
    fromGouraud.includedFrom = {{"gouraud.vert", 2}};
    EXPECT_TRUE(sink.report(fromPhong));
    EXPECT_FALSE(sink.report(fromGouraud));
    EXPECT_TRUE(sink.report(makeError("m.glsl", 4, 1, "bad")));
    EXPECT_EQ(sink.errorCount(), 2);
    std::ostringstream out;
    sink.print(out, ErrorFormat::Gcc);
    EXPECT_EQ(out.str(), "m.glsl:3:1: error: bad\n  included from phong.frag:1\nm.glsl:4:1: error: bad\n");
}

TEST(Diagnostics, WarningsDoNotCountAsErrors) {
    DiagnosticSink sink;
    Diagnostic w = makeError("a", 1, 1, "hm");
    w.severity = Severity::Warning;
    sink.report(w);
    EXPECT_EQ(sink.errorCount(), 0);
    EXPECT_EQ(formatDiagnostic(w, ErrorFormat::Gcc), "a:1:1: warning: hm\n");
}
