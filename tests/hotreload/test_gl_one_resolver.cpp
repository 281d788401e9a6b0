// One resolver at build time and at run time (issue 22): the same mistakes, made in a temp
// copy of modules/ and shader_sources/ (the unicolor shader), fed through each of the four
// entry points on its own: the build step (prism-shaderc), run-time composition over a
// generated catalogue (composeProgram with Prism's kCatalog and the copy's source tree),
// a ModuleLibrary loaded from the copied modules (then composeProgram over it), and hot
// reload (ShaderWatcher). Each must give the same first error, `path:line:col: error:
// message`, or accept the program alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "prism/gl/compose.hpp"
#include "prism/gl/module_library.hpp"
#include "prism/render/program_cache.hpp"
#include "prism/render/shader_watcher.hpp"
#include "prism/shaders.hpp"
#include "prism/test/gl_test.hpp"
#include "prism/test/run_command.hpp"

namespace prism::test {
namespace {
namespace fs = std::filesystem;

struct Edit {
    std::string file;  // under the tree: "shader_sources/unicolor.frag"
    std::string from;  // replaced once; empty: `to` is the file's whole new text
    std::string to;
};

struct Mistake {
    std::string name;
    std::vector<Edit> edits;
    std::string expected;  // the first error with "<root>" for the tree; empty: accepted
    // Made in module files: a generated catalogue holds its modules as they were built (and
    // the build step never writes one with this mistake), so composition over it cannot meet it.
    bool inModules = false;
};

enum class Entry { BuildStep, Composition, ModuleLibrary, HotReload };

std::string entryName(Entry e) {
    switch (e) {
        case Entry::BuildStep: return "BuildStep";
        case Entry::Composition: return "Composition";
        case Entry::ModuleLibrary: return "ModuleLibrary";
        case Entry::HotReload: return "HotReload";
    }
    return "?";
}

struct Case {
    Mistake mistake;
    Entry entry;
};

std::ostream& operator<<(std::ostream& os, const Case& c) {
    return os << c.mistake.name << " through " << entryName(c.entry);
}

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeText(const fs::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
}

// The first `path:line:col: error: ...` line of some diagnostics text.
std::string firstError(const std::string& text) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.find(": error: ") != std::string::npos) return line;
    return text.empty() ? "" : "(no error line in) " + text;
}

std::string firstError(const std::vector<std::string>& diagnostics) {
    std::string all;
    for (const auto& d : diagnostics) all += d + "\n";
    return firstError(all);
}

class OneResolver : public GlTest, public ::testing::WithParamInterface<Case> {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        if (HasFatalFailure()) return;
        root_ = fs::path(PRISM_HOTRELOAD_TEMP_DIR) /
                ("one_resolver_" + GetParam().mistake.name + "_" + entryName(GetParam().entry));
        fs::remove_all(root_);
        fs::create_directories(root_);
        for (const char* dir : {"modules", "shader_sources"})
            fs::copy(fs::path(PRISM_SOURCE_DIR) / dir, root_ / dir, fs::copy_options::recursive);
    }

    void applyEdits() {
        for (const auto& e : GetParam().mistake.edits) {
            const fs::path file = root_ / e.file;
            std::string text = e.from.empty() ? e.to : readText(file);
            if (!e.from.empty()) {
                const auto at = text.find(e.from);
                ASSERT_NE(at, std::string::npos) << e.file << " has no '" << e.from << "'";
                text.replace(at, e.from.size(), e.to);
            }
            writeText(file, text);
        }
    }

    std::string stage(const char* ext) const {
        return (root_ / "shader_sources" / ("unicolor." + std::string(ext))).string();
    }
    std::string modules() const { return (root_ / "modules").string(); }
    std::string contract() const { return (root_ / "modules" / "contract.json").string(); }
    std::vector<gl::ComposeStage> stages() const {
        return {{catalog::Stage::Vertex, {}, readText(stage("vert")), stage("vert")},
                {catalog::Stage::Fragment, {}, readText(stage("frag")), stage("frag")}};
    }

    // The first error of the entry point under test, after the edits; "" when it accepts.
    std::string firstErrorOfTheEntry() {
        switch (GetParam().entry) {
            case Entry::BuildStep: return edited([&] { return buildStep(); });
            case Entry::Composition: return edited([&] { return composed(); });
            case Entry::ModuleLibrary: return edited([&] { return libraryComposed(); });
            case Entry::HotReload: return watched();
        }
        return "?";
    }

    template <class Run>
    std::string edited(const Run& run) {
        applyEdits();
        return HasFatalFailure() ? "(edits failed)" : run();
    }

    std::string buildStep() const {
        const auto r =
            runCommand({PRISM_SHADERC_EXE, "--base-dir", root_.string(), "-I", modules(), "--contract", contract(),
                        "-o", (root_ / "out" / "catalogue.hpp").string(), stage("vert"), stage("frag")});
        return firstError(r.err);
    }

    // Prism's generated catalogue (its modules are the copy's, unedited) with the source tree
    // prism_add_shaders() would record for the copy, as composeProgram(kCatalog, kSourceTree, ...).
    std::string composed() const {
        const std::string base = root_.string(), dirs[] = {modules()}, contracts[] = {contract()};
        const std::string_view dirViews[] = {dirs[0]}, contractViews[] = {contracts[0]};
        const catalog::SourceTree tree{"prism::shaders", base, dirViews, contractViews, {}};
        return compositionError([&] { gl::composeProgram(shaders::kCatalog, tree, stages(), "unicolor"); });
    }

    // A library loaded from the copy's module files (an include cycle among them is a load
    // error), then composition over it.
    std::string libraryComposed() const {
        std::vector<std::string> files;
        for (const auto& entry : fs::directory_iterator(modules()))
            if (entry.path().extension() == ".glsl") files.push_back(entry.path().string());
        std::sort(files.begin(), files.end());
        const std::string contracts[] = {contract()}, dirs[] = {modules()};
        return compositionError([&] {
            const auto library = gl::ModuleLibrary::fromFiles(files, contracts, "#version 330 core", dirs);
            gl::composeProgram(library, stages(), "unicolor");
        });
    }

    template <class Compose>
    static std::string compositionError(const Compose& compose) {
        try {
            compose();
            return "";
        } catch (const gl::CompositionError& e) {
            return e.diagnostics.empty() ? firstError(std::string(e.what())) : firstError(e.diagnostics);
        }
    }

    // The watcher sees the edit made after it started, as an editor's save.
    std::string watched() {
        render::ProgramCache cache(shaders::kCatalog);
        cache.get("unicolor");  // only variants in use are rebuilt
        render::ShaderWatchOptions options;
        options.sourceRoot = root_.string();
        options.pollInterval = std::chrono::milliseconds(0);
        render::ShaderWatcher watcher(cache, options);
        applyEdits();
        return HasFatalFailure() ? "(edits failed)" : firstError(watcher.pollNow().diagnostics);
    }

    fs::path root_;
};

TEST_P(OneResolver, SameFirstErrorAsEveryEntryPoint) {
    std::string expected = GetParam().mistake.expected;
    for (auto at = expected.find("<root>"); at != std::string::npos; at = expected.find("<root>"))
        expected.replace(at, 6, root_.string());
    EXPECT_EQ(firstErrorOfTheEntry(), expected) << GetParam();
}

const std::string kFrag = "shader_sources/unicolor.frag", kVert = "shader_sources/unicolor.vert";
const std::string kContractNote = " (<root>/modules/contract.json)";

std::vector<Mistake> mistakes() {
    return {
        Mistake{"misspelled_attribute",
                {{kVert, "in vec3 a_position;", "in vec3 a_positon;"}, {kVert, "(a_position)", "(a_positon)"}},
                "<root>/" + kVert + ":6:9: error: vertex attribute 'a_positon' is not in the binding contract" +
                    kContractNote +
                    ", so the runtime would never feed it (did you mean 'a_position'?); fix the name or add it to "
                    "the contract"},
        Mistake{"varying_vec3_vec4",
                {{kVert, "in vec3 a_position;", "in vec3 a_position;\nout vec3 v_tint;"},
                 {kVert, "passFogDistance(eye);", "passFogDistance(eye);\n    v_tint = vec3(1.0);"},
                 {kFrag, "void main() {\n", "in vec4 v_tint;\nvoid main() {\n"},
                 {kFrag, "frag = vec4(fogged(u_color.rgb), 1.0);", "frag = v_tint * vec4(fogged(u_color.rgb), 1.0);"}},
                "<root>/" + kFrag +
                    ":7:9: error: frag input 'v_tint' is `smooth vec4` but the vert output is `smooth vec3` (type "
                    "mismatch); make both declarations agree"},
        Mistake{"unknown_uniform",
                {{kFrag, "void main() {\n", "uniform mat4 u_wrold;\nvoid main() {\n"},
                 {kFrag, "vec4(fogged(u_color.rgb), 1.0)", "u_wrold * vec4(fogged(u_color.rgb), 1.0)"}},
                "<root>/" + kFrag + ":7:14: error: uniform 'u_wrold' is not in the binding contract" + kContractNote +
                    ", so the runtime never sets it (did you mean 'u_world'?); fix the name or add it to the "
                    "contract"},
        Mistake{"missing_include",
                {{kFrag, "#include <material.glsl>", "#include <no_such_module.glsl>"}},
                "<root>/" + kFrag +
                    ":3:10: error: cannot find include <no_such_module.glsl>; searched: <root>/modules (-I); add a "
                    "-I directory or fix the path"},
        // A cycle every entry point can meet: the stage includes itself.
        Mistake{"stage_include_cycle",
                {{kFrag, "#include <material.glsl>", "#include <material.glsl>\n#include \"unicolor.frag\""}},
                "<root>/" + kFrag + ":4:10: error: include cycle: <root>/" + kFrag + " -> <root>/" + kFrag +
                    "; add an include guard or #pragma once, or break the cycle"},
        Mistake{"module_include_cycle",
                {{"modules/cyc_a.glsl", "", "// a\n#include \"cyc_b.glsl\"\n"},
                 {"modules/cyc_b.glsl", "", "// b\n#include \"cyc_a.glsl\"\n"},
                 {kFrag, "#include <material.glsl>", "#include <material.glsl>\n#include <cyc_a.glsl>"}},
                "<root>/modules/cyc_b.glsl:2:10: error: include cycle: <root>/modules/cyc_a.glsl -> "
                "<root>/modules/cyc_b.glsl -> <root>/modules/cyc_a.glsl; add an include guard or #pragma once, or "
                "break the cycle",
                true},
        // Accepted everywhere: composition once replaced the #version with 330, and the
        // result was "'bitfieldReverse': no matching overloaded function found".
        Mistake{"needs_version_450",
                {{kFrag, "#include <version.glsl>", "#version 450 core"},
                 {kFrag, "vec4(fogged(u_color.rgb), 1.0)", "vec4(fogged(u_color.rgb), float(bitfieldReverse(1u)))"}},
                ""},
        // ... but a module that asks for another #version is a conflict, wherever it is met.
        Mistake{"version_conflict",
                {{kFrag, "#include <version.glsl>", "#version 450 core\n#include <version.glsl>"}},
                "<root>/modules/version.glsl:2:1: error: #version 330 core conflicts with #version 450 core at "
                "<root>/" +
                    kFrag + ":2; all files of a stage must ask for the same version"},
    };
}

std::vector<Case> cases() {
    std::vector<Case> out;
    for (const auto& m : mistakes())
        for (Entry e : {Entry::BuildStep, Entry::Composition, Entry::ModuleLibrary, Entry::HotReload})
            if (!(m.inModules && e == Entry::Composition)) out.push_back({m, e});
    return out;
}

INSTANTIATE_TEST_SUITE_P(Issue22, OneResolver, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return info.param.mistake.name + "_" + entryName(info.param.entry);
                         });

}  // namespace
}  // namespace prism::test
