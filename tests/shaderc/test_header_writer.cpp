// Header and data writer pieces: chunking under MSVC's 16 KB literal limit, raw-string
// delimiters that cannot clash, C++-safe identifiers, the header/data split and the
// text pool that stores each module body once.
#include <gtest/gtest.h>

#include "data_writer.hpp"
#include "generated_format.hpp"
#include "header_writer.hpp"
#include "module_naming.hpp"
#include "tool_runner.hpp"

using namespace prism::shaderc;
using prism::test::occurrences;

TEST(HeaderWriter, ChunksStayUnderTheLimitAndSplitAtLineEnds) {
    std::string text;
    for (int i = 0; i < 3000; ++i) text += "float value" + std::to_string(i) + " = 1.0;\n";
    auto chunks = splitIntoChunks(text);
    ASSERT_GT(chunks.size(), 3u);
    std::string joined;
    for (const auto& c : chunks) {
        EXPECT_LE(c.size(), kMaxChunkBytes);
        EXPECT_EQ(c.back(), '\n');
        joined += c;
    }
    EXPECT_EQ(joined, text);
}

TEST(HeaderWriter, OverlongLineIsCutNotLost) {
    std::string text(40000, 'x');
    auto chunks = splitIntoChunks(text, 16000);
    ASSERT_EQ(chunks.size(), 3u);
    EXPECT_EQ(chunks[0].size() + chunks[1].size() + chunks[2].size(), text.size());
}

TEST(HeaderWriter, RawStringDelimiterAvoidsTheText) {
    EXPECT_EQ(rawStringLiteral("abc"), "R\"prism(abc)prism\"");
    auto lit = rawStringLiteral("evil )prism\" text");
    EXPECT_EQ(lit.rfind("R\"prism0(", 0), 0u) << lit;
}

TEST(HeaderWriter, IdentifiersAreSafe) {
    EXPECT_EQ(cppIdentifier("phong"), "phong");
    EXPECT_EQ(cppIdentifier("float"), "float_");
    EXPECT_EQ(cppIdentifier("lighting/phong-v2"), "lighting_phong_v2");
    EXPECT_EQ(cppIdentifier("2d"), "_2d");
}

TEST(HeaderWriter, FingerprintRoundTripsThroughTheDataFile) {
    CatalogData c;
    c.nameSpace = "ns";
    c.fingerprint = "0123456789abcdef";
    EXPECT_EQ(recordedFingerprint(writeData(c, "x.hpp", "h")), "0123456789abcdef");
    EXPECT_EQ(recordedFingerprint(writeHeader(c, "x.cpp")), "") << "the header must not change with the data";
    EXPECT_EQ(recordedFingerprint("// no banner\n"), "");
}

TEST(HeaderWriter, DataFileSitsBesideTheHeader) {
    EXPECT_EQ(dataPathFor("gen/prism/shaders.hpp"), "gen/prism/shaders.cpp");
    EXPECT_EQ(dataPathFor("out.h"), "out.cpp");
}

namespace {

// A catalogue of two variants whose stages include the same module, as the resolver
// flattens them: #version, the variant's #defines, #line directives, module bodies.
CatalogData twoVariantCatalogue(const std::string& moduleBody) {
    CatalogData c;
    c.nameSpace = "ns";
    c.versionDirective = "#version 330 core";
    CatalogShader s;
    s.name = "lit";
    for (int v = 0; v < 2; ++v) {
        CatalogVariant variant;
        variant.name = "N=" + std::to_string(v);
        variant.defines = {{"N", std::to_string(v)}};
        variant.stages.push_back({prism::catalog::Stage::Fragment,
                                  "#version 330 core\n#define N " + std::to_string(v) + "\n#line 1 0\n" +
                                      "// the stage\n#line 1 1\n" + moduleBody + "#line 3 0\nvoid main() {}\n",
                                  {{"lit.frag"}, {"modules/shade.glsl"}}});
        s.variants.push_back(variant);
    }
    c.shaders.push_back(s);
    CatalogModule m;
    m.identifier = "shade";
    m.path = "modules/shade.glsl";
    m.text = moduleBody;
    c.modules.push_back(m);
    return c;
}

}  // namespace

// Item 2 of issue 10: a module body used by several variants and by the module table is
// stored once; the header holds no GLSL at all.
TEST(DataWriter, ModuleTextIsStoredOnce) {
    const std::string body =
        "// Provides: shade(), a distinctive module body of some length.\n"
        "vec3 shade(vec3 c) { return c * 0.5; }\n";
    auto c = twoVariantCatalogue(body);
    const auto data = writeData(c, "x.hpp", "h");
    EXPECT_EQ(occurrences(data, "vec3 shade(vec3 c)"), 1u) << data;
    EXPECT_EQ(occurrences(writeHeader(c, "x.cpp"), "vec3 shade"), 0u);
    EXPECT_NE(data.find("#include \"x.hpp\""), std::string::npos);
    EXPECT_NE(data.find("constinit const prism::catalog::Catalog kCatalog{"), std::string::npos);
}

// The header declares; it does not change when only texts change.
TEST(HeaderWriter, HeaderIgnoresTextEdits) {
    auto a = twoVariantCatalogue("// Provides: one.\nfloat f() { return 1.0; }\n");
    auto b = twoVariantCatalogue("// Provides: one, edited.\nfloat f() { return 2.0; }\n");
    b.fingerprint = "changed";
    EXPECT_EQ(writeHeader(a, "x.cpp"), writeHeader(b, "x.cpp"));
    EXPECT_NE(writeData(a, "x.hpp", "h"), writeData(b, "x.hpp", "h"));
    b.modules[0].identifier = "shade2";
    EXPECT_NE(writeHeader(a, "x.cpp"), writeHeader(b, "x.cpp")) << "a renamed module changes a declaration";
}

// The data file records the header's hash: a run can tell a header that is stale, edited
// or from another run (then it rewrites it instead of stopping at the no-op).
TEST(DataWriter, RecordsTheHeadersHash) {
    auto c = twoVariantCatalogue("// Provides: one.\nfloat f() { return 1.0; }\n");
    c.sourcesBlock =
        std::string(format::kSourcesRecordStart) + "0123\n" + std::string(format::kSourcesRecordFile) + "a.glsl\n";
    const auto header = writeHeader(c, "x.cpp");
    const auto data = writeData(c, "x.hpp", header);
    EXPECT_TRUE(headerMatchesData(header, data));
    EXPECT_FALSE(headerMatchesData(header + "// edited\n", data));
    EXPECT_FALSE(headerMatchesData("", data)) << "a missing header";
    EXPECT_FALSE(headerMatchesData(header, "// no record\n"));
    EXPECT_TRUE(headerMatchesData(header, data.substr(data.size() - 200))) << "the tail holds the hash";
}
