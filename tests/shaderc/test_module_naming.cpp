// Module identifiers from paths (issue 17): readable for ordinary paths, and
// collision-free, shown by decoding every identifier back to its path.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

#include "module_naming.hpp"

namespace prism::shaderc {
namespace {

TEST(ModuleNaming, OrdinaryPaths) {
    EXPECT_EQ(mangleModulePath("color/space/rgb2hsv.glsl"), "color__space__rgb2hsv");
    EXPECT_EQ(mangleModulePath("fragment_output.glsl"), "fragment_output");
    EXPECT_EQ(mangleModulePath("lighting/pbr/specular.glsl"), "lighting__pbr__specular");
    EXPECT_EQ(mangleModulePath("sample/2D.glsl"), "sample__2D");
    EXPECT_EQ(mangleModulePath("new.glsl"), "new_");  // a C++ keyword
}

TEST(ModuleNaming, TheCollisionsOfPlainJoiningDiffer) {
    EXPECT_NE(mangleModulePath("a_b/c.glsl"), mangleModulePath("a/b_c.glsl"));
    EXPECT_NE(mangleModulePath("a/b/c.glsl"), mangleModulePath("a/b_c.glsl"));
    EXPECT_NE(mangleModulePath("a/util.glsl"), mangleModulePath("b/util.glsl"));
    EXPECT_NE(mangleModulePath("x.glsl"), mangleModulePath("x"));
    EXPECT_NE(mangleModulePath("a__b.glsl"), mangleModulePath("a/b.glsl"));
    EXPECT_NE(mangleModulePath("new.glsl"), mangleModulePath("new_.glsl"));
}

TEST(ModuleNaming, UnusualComponentsAreHexAndStillIdentifiers) {
    EXPECT_EQ(mangleModulePath("my-lib/x.glsl"), "_6d792d6c6962__x");
    EXPECT_EQ(mangleModulePath("lib/common.h"), "lib___636f6d6d6f6e2e68");
    EXPECT_EQ(mangleModulePath("2d/x.glsl"), "_3264__x");  // an identifier cannot start with a digit
    EXPECT_EQ(mangleModulePath("../x.glsl"), "_2e2e__x");
    for (const char* path : {"my-lib/x.glsl", "a b/c.d.glsl", "_x/y_.glsl", "a__b/c"}) {
        const std::string id = mangleModulePath(path);
        EXPECT_TRUE(std::isalpha(static_cast<unsigned char>(id[0])) || id[0] == '_') << id;
        for (char c : id) EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_') << id;
    }
}

// Every identifier decodes to the path it came from, so no two paths share one.
TEST(ModuleNaming, RandomPathsRoundTripAndNeverCollide) {
    std::mt19937 random(17);
    const std::string alphabet = "ab_1.-";  // the characters that make collisions likely
    std::map<std::string, std::string> pathOf;
    for (int n = 0; n < 20000; ++n) {
        std::string path;
        const int components = 1 + static_cast<int>(random() % 3);
        for (int c = 0; c < components; ++c) {
            if (c) path += '/';
            const int length = 1 + static_cast<int>(random() % 4);
            for (int i = 0; i < length; ++i) path += alphabet[random() % alphabet.size()];
        }
        if (random() % 2) path += ".glsl";
        if (path.find("/./") != std::string::npos || path == ".") continue;
        const std::string id = mangleModulePath(path);
        EXPECT_EQ(demangleModuleIdentifier(id), path) << id;
        const auto [it, fresh] = pathOf.emplace(id, path);
        EXPECT_TRUE(fresh || it->second == path) << id << " from both " << it->second << " and " << path;
    }
}

TEST(ModuleNaming, OnlyWhatManglingWritesDecodes) {
    EXPECT_FALSE(demangleModuleIdentifier("a___b"));          // '_' + "b" is not hex
    EXPECT_FALSE(demangleModuleIdentifier("_612e676c736c"));  // "a.glsl" is written "a"
    EXPECT_EQ(demangleModuleIdentifier("_61"), "a");          // a file "a" without .glsl
    EXPECT_FALSE(demangleModuleIdentifier("x_"));             // not a keyword
    EXPECT_EQ(demangleModuleIdentifier("color__space__rgb2hsv"), "color/space/rgb2hsv.glsl");
}

// Program names (issue 24): identifiers stay as they are, any other text is mangled like
// one folder of a module path, and demangleName() gives the text back.
TEST(ProgramNaming, IdentifiersStayOtherNamesAreMangledReversibly) {
    EXPECT_EQ(mangleName("phong"), "phong");
    EXPECT_EQ(mangleName("rain_streaks"), "rain_streaks");
    EXPECT_EQ(mangleName("float"), "float_");
    EXPECT_EQ(mangleName("blur-h"), "_626c75722d68");
    EXPECT_EQ(mangleName("16bit_storage"), "_31366269745f73746f72616765");
    for (const std::string name : {"phong", "float", "blur-h", "16bit_storage", "a__b", "_x", "x_", "ü"})
        EXPECT_EQ(demangleName(mangleName(name)), name) << name;
    EXPECT_FALSE(demangleName("_zz"));    // not hex
    EXPECT_FALSE(demangleName("_7068"));  // "ph" is written "ph"
    EXPECT_FALSE(demangleName("x_"));     // not a keyword
}

TEST(ProgramNaming, NoTwoNamesShareAnIdentifier) {
    std::mt19937 random(24);
    const std::string alphabet = "ab_1-.";
    std::map<std::string, std::string> nameOf;
    for (int n = 0; n < 20000; ++n) {
        std::string name;
        const int length = 1 + static_cast<int>(random() % 5);
        for (int i = 0; i < length; ++i) name += alphabet[random() % alphabet.size()];
        const std::string id = mangleName(name);
        EXPECT_EQ(demangleName(id), name) << id;
        const auto [it, fresh] = nameOf.emplace(id, name);
        EXPECT_TRUE(fresh || it->second == name) << id << " from both " << it->second << " and " << name;
    }
}

}  // namespace
}  // namespace prism::shaderc
