// Validation scheduling of prism-shaderc (issue 10 item 7): programs with the same
// token stream are validated once; a content-addressed cache in the build tree answers
// a re-check, and an edit re-validates only the programs whose token stream changed;
// a result with diagnostics is never cached, so its messages keep their own lines;
// concurrent writers leave a valid cache.
// The counts come from `--stats`.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

// "validated V of N programs (S shared a token stream, C from the cache)" -> {V, N, S, C}.
std::array<int, 4> statsOf(const std::string& output) {
    static const std::regex line(
        R"(validated (\d+) of (\d+) programs \((\d+) shared a token stream, (\d+) from the cache;)");
    std::smatch m;
    if (!std::regex_search(output, m, line)) return {-1, -1, -1, -1};
    return {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])};
}

// "<target>: ... (S shared a token stream, C from the cache" -> C, or -1 without the line.
int targetFromCache(const std::string& output, const std::string& target) {
    const std::regex line(target +
                          R"(: (?:validated|compiled) \d+ programs \(\d+ shared a token stream, (\d+) from the cache)");
    std::smatch m;
    return std::regex_search(output, m, line) ? std::stoi(m[1]) : -1;
}

// Shaders a and b, each including its own module.
void writeTwoShaders(const ScratchDir& dir) {
    dir.write("m/one.glsl", "// Provides: one().\nfloat one() { return 1.0; }\n");
    dir.write("m/two.glsl", "// Provides: two().\nfloat two() { return 2.0; }\n");
    for (std::string s : {"a", "b"}) {
        dir.write("s/" + s + ".vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
        dir.write("s/" + s + ".frag", "#version 330 core\n#include \"" + std::string(s == "a" ? "one" : "two") +
                                          ".glsl\"\nout vec4 o;\nvoid main() { o = vec4(" + (s == "a" ? "one" : "two") +
                                          "()); }\n");
    }
}

std::size_t filesUnder(const fs::path& dir, const std::string& containing) {
    std::size_t n = 0;
    std::error_code ec;
    if (!fs::exists(dir)) return 0;
    for (const auto& e : fs::recursive_directory_iterator(dir, ec))
        if (e.is_regular_file() && e.path().filename().string().find(containing) != std::string::npos) ++n;
    return n;
}

}  // namespace

TEST(ValidationSchedule, SameTokenStreamIsValidatedOnce) {
    ScratchDir dir("sched-dedupe");
    // UNUSED is an axis no line tests: both variants are one token stream.
    dir.write("s/a.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag",
              "#version 330 core\n#pragma prism variant UNUSED\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    auto run = runShaderc("--check --revalidate --stats s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(statsOf(run.output), (std::array<int, 4>{1, 2, 1, 0})) << run.output;
    // An axis a line tests makes two token streams.
    dir.write("s/a.frag",
              "#version 330 core\n#pragma prism variant USED\nout vec4 o;\n"
              "void main() { o = vec4(USED == 1 ? 1.0 : 0.5); }\n");
    auto used = runShaderc("--check --revalidate --stats s", dir.str());
    ASSERT_EQ(used.exitCode, 0) << used.output;
    EXPECT_EQ(statsOf(used.output), (std::array<int, 4>{2, 2, 0, 0})) << used.output;
}

TEST(ValidationSchedule, CacheAnswersARecheckAndAnEditRevalidatesOnlyItsPrograms) {
    ScratchDir dir("sched-cache");
    writeTwoShaders(dir);
    const std::string args = "--check --revalidate --stats --cache-dir build/cache -I m s";
    auto first = runShaderc(args, dir.str());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_EQ(statsOf(first.output), (std::array<int, 4>{2, 2, 0, 0})) << first.output;
    EXPECT_EQ(filesUnder(dir.path() / "build/cache", ".json"), 1u);  // one pack for the catalogue

    auto again = runShaderc(args, dir.str());
    EXPECT_EQ(statsOf(again.output), (std::array<int, 4>{0, 2, 0, 2})) << again.output;

    // Another catalogue sharing the directory keeps its own pack.
    dir.write("t/c.vert", "#version 330 core\nvoid main() { gl_Position = vec4(1.0); }\n");
    dir.write("t/c.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    auto other = runShaderc("--check --revalidate --stats --cache-dir build/cache t", dir.str());
    EXPECT_EQ(statsOf(other.output), (std::array<int, 4>{1, 1, 0, 0})) << other.output;
    EXPECT_EQ(statsOf(runShaderc(args, dir.str()).output), (std::array<int, 4>{0, 2, 0, 2}));

    // A code edit of one.glsl: only shader a is validated again.
    dir.write("m/one.glsl", "// Provides: one().\nfloat one() { return 1.0 + 0.0; }\n");
    auto edited = runShaderc(args, dir.str());
    ASSERT_EQ(edited.exitCode, 0) << edited.output;
    EXPECT_EQ(statsOf(edited.output), (std::array<int, 4>{1, 2, 0, 1})) << edited.output;

    // A comment-only edit of two.glsl changes no token: nothing is validated.
    dir.write("m/two.glsl", "// Provides: two().\n// (a note)\nfloat two() { return 2.0; } // two\n");
    auto comment = runShaderc(args, dir.str());
    ASSERT_EQ(comment.exitCode, 0) << comment.output;
    EXPECT_EQ(statsOf(comment.output), (std::array<int, 4>{0, 2, 0, 2})) << comment.output;
}

// Only clean results are cached (target_scheduler.hpp): the broken program runs again on
// every check and its message keeps its lines; the clean one comes from the cache.
TEST(ValidationSchedule, DiagnosticsAreNeverCachedAndKeepTheirOwnLines) {
    ScratchDir dir("sched-diag");
    writeTwoShaders(dir);
    dir.write("m/one.glsl", "// Provides: one(), broken.\nfloat one() {\n    return missingValue;\n}\n");
    const std::string args = "--check --revalidate --stats --cache-dir build/cache -I m s";
    auto first = runShaderc(args, dir.str());
    EXPECT_EQ(first.exitCode, 1) << first.output;
    EXPECT_NE(first.output.find("m/one.glsl:3:12: error: 'missingValue'"), std::string::npos) << first.output;
    auto again = runShaderc(args, dir.str());
    EXPECT_EQ(again.exitCode, 1) << again.output;
    EXPECT_NE(again.output.find("m/one.glsl:3:12: error: 'missingValue'"), std::string::npos) << again.output;
    EXPECT_EQ(statsOf(again.output), (std::array<int, 4>{1, 2, 0, 1})) << again.output;  // b from the cache

    // Same tokens, lines moved down by a comment: the message must move with them.
    dir.write("m/one.glsl", "// Provides: one(), broken.\n// moved\nfloat one() {\n    return missingValue;\n}\n");
    auto moved = runShaderc(args, dir.str());
    EXPECT_EQ(moved.exitCode, 1) << moved.output;
    EXPECT_NE(moved.output.find("m/one.glsl:4:12: error: 'missingValue'"), std::string::npos) << moved.output;
    EXPECT_EQ(moved.output.find("m/one.glsl:3:12"), std::string::npos) << moved.output;
}

TEST(ValidationSchedule, DefaultCacheLivesNextToTheStampNeverInTheWorkingDirectory) {
    ScratchDir dir("sched-where");
    writeTwoShaders(dir);
    auto plain = runShaderc("--check --revalidate --stats -I m s", dir.str());
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_EQ(filesUnder(dir.path(), ".json"), 0u) << "a plain --check wrote a cache into the working directory";

    auto stamped = runShaderc("--check --revalidate --stats --stamp build/shaders.stamp -I m s", dir.str());
    ASSERT_EQ(stamped.exitCode, 0) << stamped.output;
    EXPECT_EQ(filesUnder(dir.path() / "build/prism-shaderc-cache", ".json"), 1u);
    auto restamped = runShaderc("--check --revalidate --stats --stamp build/shaders.stamp -I m s", dir.str());
    EXPECT_EQ(statsOf(restamped.output)[3], 2) << restamped.output;

    auto off =
        runShaderc("--check --revalidate --stats --cache-dir none --stamp other/shaders.stamp -I m s", dir.str());
    ASSERT_EQ(off.exitCode, 0) << off.output;
    EXPECT_FALSE(fs::exists(dir.path() / "other/prism-shaderc-cache"));
}

TEST(ValidationSchedule, ConcurrentWritersAndTornEntriesLeaveAValidCache) {
    ScratchDir dir("sched-concurrent");
    writeTwoShaders(dir);
    for (int shader = 0; shader < 6; ++shader)  // more programs to race on
        for (std::string stage : {"vert", "frag"})
            dir.write(
                "s/c" + std::to_string(shader) + "." + stage,
                stage == "vert"
                    ? "#version 330 core\nvoid main() { gl_Position = vec4(" + std::to_string(shader) + ".0); }\n"
                    : "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(" + std::to_string(shader) + ".0); }\n");
    const std::string exe = PRISM_SHADERC_EXE;
    std::string parallel = "cd '" + dir.str() + "' && (";
    for (int i = 0; i < 4; ++i)
        parallel += "'" + exe + "' --check --revalidate --stats -j 2 --cache-dir build/cache -I m s > run" +
                    std::to_string(i) + ".log 2>&1 & ";
    parallel += "wait)";
    ASSERT_EQ(std::system(parallel.c_str()), 0);
    for (int i = 0; i < 4; ++i) {
        const std::string log = prism::test::readFile(dir.path() / ("run" + std::to_string(i) + ".log"));
        EXPECT_EQ(statsOf(log)[1], 8) << "run " << i << ": " << log;  // it ran, on this catalogue
        EXPECT_EQ(log.find("error"), std::string::npos) << "run " << i << ": " << log;
    }
    EXPECT_EQ(filesUnder(dir.path() / "build/cache", ".tmp"), 0u);
    auto after = runShaderc("--check --revalidate --stats --cache-dir build/cache -I m s", dir.str());
    EXPECT_EQ(statsOf(after.output), (std::array<int, 4>{0, 8, 0, 8})) << after.output;

    // A torn or foreign entry is a miss, never a wrong answer.
    for (const auto& e : fs::recursive_directory_iterator(dir.path() / "build/cache"))
        if (e.is_regular_file()) prism::test::writeFile(e.path(), "{\"format\": 1, \"tokens\": ");
    auto torn = runShaderc("--check --revalidate --stats --cache-dir build/cache -I m s", dir.str());
    ASSERT_EQ(torn.exitCode, 0) << torn.output;
    EXPECT_EQ(statsOf(torn.output), (std::array<int, 4>{8, 8, 0, 0})) << torn.output;
}

// Results of another build of the tool (here: a copy of the executable, another file
// time) are not trusted: the cache key names the tool's build.
TEST(ValidationSchedule, AnotherBuildOfTheToolDoesNotReuseResults) {
    ScratchDir dir("sched-build");
    writeTwoShaders(dir);
    const std::string args = "--check --revalidate --stats --cache-dir build/cache -I m s";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    fs::create_directories(dir.path() / "bin");
    fs::copy_file(PRISM_SHADERC_EXE, dir.path() / "bin/prism-shaderc");
    fs::last_write_time(dir.path() / "bin/prism-shaderc",
                        fs::last_write_time(PRISM_SHADERC_EXE) + std::chrono::seconds(10));
    const std::string copy = (dir.path() / "bin/prism-shaderc").string();
    std::string cmd = "cd '" + dir.str() + "' && '" + copy + "' " + args + " > copy.log 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string log = prism::test::readFile(dir.path() / "copy.log");
    EXPECT_EQ(statsOf(log), (std::array<int, 4>{2, 2, 0, 0})) << log;
    auto same = runShaderc(args, dir.str());  // the original build still finds its own
    EXPECT_EQ(statsOf(same.output), (std::array<int, 4>{0, 2, 0, 2})) << same.output;
}

// Reflection served by shared stages and by the cache gives the same header and data bytes
// as a cold run and as a run without a cache (the project catalogue, light counts pinned),
// for all three targets. The data file holds the reflection, the es300 verdicts and the
// SPIR-V words, so it is the one that would differ.
TEST(ValidationSchedule, HeaderFromTheCacheIsByteIdenticalToACold) {
    ScratchDir dir("sched-header");
    const std::string source = PRISM_SOURCE_DIR;
    const std::string inputs = " --base-dir " + source + " --variant '*:DIRECTIONAL_LIGHTS=2,POINT_LIGHTS=1' -I " +
                               source + "/modules --contract " + source + "/modules/contract.json " + source +
                               "/shader_sources";
    const std::string args = "-o h.hpp --stats --cache-dir " + dir.str() + "/cache" + inputs;
    const std::string targets = " --target gl,es300,spirv";
    for (const char* sub : {"cold", "warm", "uncached"}) fs::create_directories(dir.path() / sub);
    auto cold = runShaderc(args + targets, (dir.path() / "cold").string());
    ASSERT_EQ(cold.exitCode, 0) << cold.output;
    EXPECT_EQ(statsOf(cold.output)[3], 0) << cold.output;
    EXPECT_EQ(targetFromCache(cold.output, "es300"), 0) << cold.output;
    EXPECT_EQ(targetFromCache(cold.output, "spirv"), 0) << cold.output;
    auto warm = runShaderc(args + targets, (dir.path() / "warm").string());
    ASSERT_EQ(warm.exitCode, 0) << warm.output;
    EXPECT_EQ(statsOf(warm.output)[0], 0) << warm.output;  // nothing validated: all from the cache
    EXPECT_GT(targetFromCache(warm.output, "es300"), 0) << warm.output;
    EXPECT_GT(targetFromCache(warm.output, "spirv"), 0) << warm.output;
    EXPECT_NE(warm.output.find("SPIRV-Tools validated 0 modules"), std::string::npos) << warm.output;
    auto uncached = runShaderc("-o h.hpp --cache-dir none" + inputs + targets, (dir.path() / "uncached").string());
    ASSERT_EQ(uncached.exitCode, 0) << uncached.output;
    for (const char* file : {"h.hpp", "h.cpp"}) {
        const std::string a = prism::test::readFile(dir.path() / "cold" / file);
        EXPECT_GT(a.size(), 1000u) << file;
        EXPECT_TRUE(a == prism::test::readFile(dir.path() / "warm" / file)) << file << ": cached vs cold";
        EXPECT_TRUE(a == prism::test::readFile(dir.path() / "uncached" / file)) << file << ": cold vs no cache";
    }
}

// The es300 and spirv targets keep their clean results in their own packs beside the gl
// one: a re-check validates nothing again, and an edit of one module re-validates, for
// every target, only the programs that include it.
TEST(ValidationSchedule, Es300AndSpirvResultsComeFromTheirOwnPacks) {
    ScratchDir dir("sched-targets");
    writeTwoShaders(dir);
    const std::string args = "--check --revalidate --stats --target gl,es300,spirv --cache-dir build/cache -I m s";
    auto first = runShaderc(args, dir.str());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_EQ(targetFromCache(first.output, "es300"), 0) << first.output;
    EXPECT_EQ(targetFromCache(first.output, "spirv"), 0) << first.output;
    EXPECT_EQ(filesUnder(dir.path() / "build/cache", "-es300.json"), 1u);
    EXPECT_EQ(filesUnder(dir.path() / "build/cache", "-spirv.json"), 1u);
    EXPECT_EQ(filesUnder(dir.path() / "build/cache", "-spirv.words"), 1u);  // its modules' words

    auto again = runShaderc(args, dir.str());
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(targetFromCache(again.output, "es300"), 2) << again.output;
    EXPECT_EQ(targetFromCache(again.output, "spirv"), 2) << again.output;
    EXPECT_NE(again.output.find("SPIRV-Tools validated 0 modules"), std::string::npos) << again.output;

    dir.write("m/one.glsl", "// Provides: one().\nfloat one() { return 1.0 + 0.0; }\n");
    auto edited = runShaderc(args, dir.str());
    ASSERT_EQ(edited.exitCode, 0) << edited.output;
    EXPECT_EQ(targetFromCache(edited.output, "es300"), 1) << edited.output;
    EXPECT_EQ(targetFromCache(edited.output, "spirv"), 1) << edited.output;
}

// A target's result with a message is never cached: its program runs again on every check,
// so an es300 error keeps its lines, and a warning (the ES 3.00 limits) is not dropped by a
// re-check that would otherwise find the program's verdict in the cache.
TEST(ValidationSchedule, TargetMessagesAreNeverServedFromTheCache) {
    ScratchDir dir("sched-target-diag");
    writeTwoShaders(dir);
    dir.write("s/a.vert", "#version 330 core\nout int v_id;\nvoid main() { v_id = 1; gl_Position = vec4(0.0); }\n");
    std::string samplers, taps;
    for (int i = 0; i < 17; ++i) {
        samplers += "uniform sampler2D u_t" + std::to_string(i) + ";\n";
        taps += " + texture(u_t" + std::to_string(i) + ", vec2(0.5))";
    }
    dir.write("s/b.frag",
              "#version 330 core\n" + samplers + "out vec4 o;\nvoid main() { o = vec4(0.0)" + taps + "; }\n");
    const std::string args = "--check --revalidate --stats --target gl,es300 --cache-dir build/cache -I m s";
    for (int run = 0; run < 2; ++run) {
        auto result = runShaderc(args, dir.str());
        EXPECT_EQ(result.exitCode, 1) << "run " << run << ": " << result.output;
        EXPECT_NE(result.output.find("s/a.vert:2:5: error: 'int': must be qualified as flat"), std::string::npos)
            << "run " << run << ": " << result.output;
        EXPECT_NE(result.output.find("s/b.frag: warning: es300: program 'b' uses 17 fragment texture units"),
                  std::string::npos)
            << "run " << run << ": " << result.output;
        EXPECT_EQ(targetFromCache(result.output, "es300"), 0) << "run " << run << ": " << result.output;
    }
}

// A spirv pack keeps its modules' words in a file beside it, with their size and hash in the
// pack. A words file that is torn (a flipped byte, cut short) or gone, or a pack whose count
// is absurd, is a miss, never wrong words: the run compiles again and gives the same data file.
TEST(ValidationSchedule, TornSpirvWordsFileIsAMiss) {
    ScratchDir dir("sched-spirv-torn");
    writeTwoShaders(dir);
    const std::string args = "-o c.hpp --stats --target gl,spirv --cache-dir build/cache -I m s";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const std::string cold = prism::test::readFile(dir.path() / "c.cpp");
    fs::path words;
    for (const auto& e : fs::directory_iterator(dir.path() / "build/cache"))
        if (e.path().string().ends_with("-spirv.words")) words = e.path();
    ASSERT_FALSE(words.empty());
    const std::string intact = prism::test::readFile(words);
    ASSERT_GT(intact.size(), 100u);
    std::string flipped = intact;
    flipped[40] = static_cast<char>(flipped[40] ^ 1);
    for (const auto& [tear, text] : std::vector<std::pair<std::string, std::string>>{
             {"flipped", flipped}, {"cut", intact.substr(0, intact.size() - 4)}, {"gone", ""}}) {
        if (tear == "gone")
            fs::remove(words);
        else
            prism::test::writeFile(words, text);
        fs::remove(dir.path() / "c.cpp");
        auto run = runShaderc(args, dir.str());
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_EQ(targetFromCache(run.output, "spirv"), 0) << tear << ": " << run.output;
        EXPECT_TRUE(prism::test::readFile(dir.path() / "c.cpp") == cold) << tear;
        fs::remove(dir.path() / "c.cpp");
        auto again = runShaderc(args, dir.str());  // the run wrote a good pack again
        EXPECT_EQ(targetFromCache(again.output, "spirv"), 2) << tear << ": " << again.output;
        EXPECT_TRUE(prism::test::readFile(dir.path() / "c.cpp") == cold) << tear;
    }
    // A pack whose recorded count is absurd (2^62 words, -1) is a miss too, not a crash.
    fs::path pack = words;
    pack.replace_extension(".json");
    const std::string good = prism::test::readFile(pack);
    const auto at = good.find("\"count\":");
    ASSERT_NE(at, std::string::npos) << good.substr(0, 200);
    const auto end = good.find_first_of(",}", at);
    for (const std::string count : {"4611686018427387904", "-1"}) {
        prism::test::writeFile(pack, good.substr(0, at) + "\"count\":" + count + good.substr(end));
        fs::remove(dir.path() / "c.cpp");
        auto run = runShaderc(args, dir.str());
        ASSERT_EQ(run.exitCode, 0) << count << ": " << run.output;
        EXPECT_EQ(targetFromCache(run.output, "spirv"), 0) << count << ": " << run.output;
        EXPECT_TRUE(prism::test::readFile(dir.path() / "c.cpp") == cold) << count;
    }
}
