// Depfile: Make escaping of space, $ and #, and a stable, de-duplicated list.
#include <gtest/gtest.h>

#include "depfile.hpp"

using namespace prism::shaderc;

TEST(Depfile, EscapesSpaceDollarAndHash) {
    EXPECT_EQ(escapeDepfilePath("/a b/c$d/#e.glsl"), "/a\\ b/c$$d/\\#e.glsl");
    EXPECT_EQ(escapeDepfilePath("plain/path.glsl"), "plain/path.glsl");
}

TEST(Depfile, TargetAndSortedUniqueDependencies) {
    auto text = makeDepfile("/out/my header.stamp", {"/z.glsl", "/a b.glsl", "/z.glsl"});
    EXPECT_EQ(text, "/out/my\\ header.stamp: \\\n  /a\\ b.glsl \\\n  /z.glsl\n");
}

TEST(Depfile, NoDependencies) {
    EXPECT_EQ(makeDepfile("t", {}), "t:\n");
}
