// Unit tests of the one content hash (prism/hash/content_hash.hpp): it is xxHash's XXH3
// (the published value of the empty input), parts' boundaries count, and equal inputs
// give equal hashes whether added at once or in pieces.
#include <gtest/gtest.h>

#include <string>

#include "prism/hash/content_hash.hpp"

namespace {

using prism::hash::ContentHash;

TEST(ContentHash, Hash64IsXxh3) {
    EXPECT_EQ(prism::hash::hash64(""), 0x2d06800538d394c2ull);  // XXH3_64bits of no bytes
    EXPECT_EQ(prism::hash::hash64("abc"), 0x78af5f94892f3950ull);
}

TEST(ContentHash, PartsBoundariesCount) {
    ContentHash a, b;
    a.add("ab").add("c");
    b.add("a").add("bc");
    EXPECT_NE(a.hex(), b.hex());
    EXPECT_NE(a.hex64(), b.hex64());
}

TEST(ContentHash, EqualInputsGiveEqualHashes) {
    ContentHash a, b, c;
    a.add("void main() {}").add("shaders/a.frag");
    b.add("void main() {}").add("shaders/a.frag");
    c.addBytes("void main").addBytes("() {}");
    EXPECT_EQ(a.hex(), b.hex());
    EXPECT_EQ(c.hex(), ContentHash().addBytes("void main() {}").hex());
    EXPECT_EQ(a.hex().size(), 32u);
    EXPECT_EQ(a.hex64().size(), 16u);
    EXPECT_EQ(a.hex().substr(16), a.hex64()) << "hex64() is the low half of hex()";
}

}  // namespace
