// Header writer pieces: chunking under MSVC's 16 KB literal limit, raw-string
// delimiters that cannot clash, and C++-safe identifiers.
#include <gtest/gtest.h>

#include "header_writer.hpp"

using namespace prism::shaderc;

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

TEST(HeaderWriter, FingerprintRoundTrips) {
    CatalogData c;
    c.nameSpace = "ns";
    c.fingerprint = "0123456789abcdef";
    auto text = writeHeader(c);
    EXPECT_EQ(fingerprintOfHeader(text), "0123456789abcdef");
    EXPECT_EQ(fingerprintOfHeader("// no banner\n"), "");
}
