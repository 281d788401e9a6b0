// Hot reload (prism/render/shader_watcher.hpp) on a temp copy of modules/ and
// shader_sources/: a module edit is rebuilt in process and drawn, a broken edit keeps the
// last good program and names the module's file and line, fixing it recovers, and the
// time from the file write to the new program drawing is measured (under 1 s, issue 9).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "prism/test/gl_test.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/render/shader_watcher.hpp"
#include "prism/shaders.hpp"

namespace prism::test {
namespace {
namespace fs = std::filesystem;

// material.glsl's own text ends at line 5 (`uniform float u_specular;`); the edits append line 6.
const std::string kSwapRedAndBlue = "#define u_color u_color.bgra\n";  // unicolor then draws (b, g, r)
const std::string kSyntaxError = "vec3 broken = ;\n";
const std::string kMissingInclude = "#include <no_such_module.glsl>\n";
// A misspelled uniform: the driver links it (and draws black), the contract check rejects it.
const std::string kUniformOutsideContract = "uniform vec4 u_colour;\n#define u_color u_colour\n";

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeFile(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out << text;
}

class HotReload : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        if (HasFatalFailure()) return;
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::path(PRISM_HOTRELOAD_TEMP_DIR) / info->name();
        fs::remove_all(root_);
        fs::create_directories(root_);
        for (const char* dir : {"modules", "shader_sources"})
            fs::copy(fs::path(PRISM_SOURCE_DIR) / dir, root_ / dir, fs::copy_options::recursive);
        material_ = root_ / "modules" / "material.glsl";
        originalMaterial_ = readFile(material_);
        cache_ = std::make_unique<render::ProgramCache>(shaders::kCatalog);
        job_.shader = "unicolor";
        job_.mesh = render::meshForShader("unicolor", render::namedMesh("cube", 1));
        job_.material.color = {1.0f, 0.0f, 0.0f, 1.0f};  // red
        job_.width = job_.height = 32;
    }
    void TearDown() override {
        watcher_.reset();
        cache_.reset();
    }

    render::ShaderWatcher& watcher(std::chrono::milliseconds interval = std::chrono::milliseconds(0)) {
        render::ShaderWatchOptions options;
        options.sourceRoot = root_.string();
        options.pollInterval = interval;
        options.mechanism = mechanism_;
        watcher_ = std::make_unique<render::ShaderWatcher>(*cache_, options);
        return *watcher_;
    }
    // The centre pixel: the cube covers it.
    image::Rgba8 centre() {
        auto image = render::renderImage8(*cache_, job_);
        return image.at(image.width / 2, image.height / 2);
    }
    void editMaterial(const std::string& line6) { writeFile(material_, originalMaterial_ + line6); }

    fs::path root_, material_;
    std::string originalMaterial_;
    render::WatchMechanism mechanism_ = render::WatchMechanism::Automatic;
    std::unique_ptr<render::ProgramCache> cache_;
    std::unique_ptr<render::ShaderWatcher> watcher_;
    render::RenderJob job_;
};

// The tests of change detection run once per mechanism: inotify, and the polling that
// platforms without it use.
class HotReloadBy : public HotReload, public ::testing::WithParamInterface<render::WatchMechanism> {
  protected:
    void SetUp() override {
        mechanism_ = GetParam();
        HotReload::SetUp();
    }
};

std::string mechanismName(const ::testing::TestParamInfo<render::WatchMechanism>& info) {
    return info.param == render::WatchMechanism::Inotify ? "Inotify" : "Polling";
}

INSTANTIATE_TEST_SUITE_P(Mechanisms, HotReloadBy,
                         ::testing::Values(render::WatchMechanism::Inotify, render::WatchMechanism::Polling),
                         mechanismName);

const image::Rgba8 kRed{255, 0, 0, 255}, kBlue{0, 0, 255, 255};

// ProgramCache::reload swaps the program behind references taken from get() earlier.
TEST_F(HotReload, ReloadSwapsTheProgramBehindEarlierReferences) {
    gl::Program& program = cache_->get("unicolor");
    const unsigned before = program.id();
    const auto& variant = cache_->variantOf("unicolor", {});
    cache_->reload("unicolor", variant.name, gl::Program(variant, shaders::kCatalog.contractAttributes, "rebuilt"));
    EXPECT_EQ(&cache_->get("unicolor"), &program);
    EXPECT_NE(program.id(), before);
    EXPECT_EQ(program.label(), "rebuilt");
    EXPECT_EQ(cache_->size(), 1u);
    EXPECT_EQ(cache_->reloadCount(), 1u);
    EXPECT_EQ(cache_->builtVariants("unicolor"), std::vector<std::string>{std::string(variant.name)});
}

TEST_F(HotReload, ReloadRejectsUnknownShaderAndVariantNames) {
    const auto& variant = cache_->variantOf("unicolor", {});
    auto program = [&] { return gl::Program(variant, shaders::kCatalog.contractAttributes); };
    EXPECT_THROW(cache_->reload("unicolour", variant.name, program()), render::UnknownShaderError);
    EXPECT_THROW(cache_->reload("unicolor", "FOG=2", program()), render::UnknownShaderError);
    EXPECT_EQ(cache_->size(), 0u);
    EXPECT_EQ(cache_->reloadCount(), 0u);
}

// The usage example of shader_watcher.hpp and docs/hot-reload.md, verbatim between the
// markers (CTest hotreload.snippet_matches_docs compares the three).
TEST_F(HotReload, DocsSnippetRuns) {
    const std::string sourceTree = root_.string();
    cache_.reset();
    // [snippet: hot reload]
    prism::render::ProgramCache cache(prism::shaders::kCatalog);
    prism::render::ShaderWatchOptions options;
    options.sourceRoot = sourceTree;  // the tree the catalogue was built from
    prism::render::ShaderWatcher watcher(cache, options);
    prism::render::RenderJob job;
    job.shader = "phong";
    job.mesh = prism::render::meshForShader("phong", prism::render::namedMesh("torus"));
    for (int frame = 0; frame < 3; ++frame) {                                  // the render loop, on the GL thread
        for (const auto& d : watcher.poll().diagnostics) std::cerr << d;       // path:line:col: error: ...
        prism::image::Image8 image = prism::render::renderImage8(cache, job);  // newest good program
    }
    // [end snippet]
    EXPECT_EQ(cache.size(), 1u);
    EXPECT_TRUE(watcher.errors().empty());
}

TEST_F(HotReload, WatchesTheModulesAndStagesTheCatalogueWasBuiltFrom) {
    auto& w = watcher();
    const auto files = w.watchedFiles();
    auto watched = [&](const fs::path& p) {
        return std::find(files.begin(), files.end(), p.lexically_normal().string()) != files.end();
    };
    EXPECT_TRUE(watched(material_));
    EXPECT_TRUE(watched(root_ / "modules" / "contract.json"));
    EXPECT_TRUE(watched(root_ / "shader_sources" / "unicolor.frag"));
    EXPECT_FALSE(watched(fs::path(PRISM_SOURCE_DIR) / "modules" / "material.glsl"));  // the copy, not the tree
}

// A copy of the recorded tree (the viewer's --source-root): what lay under the recorded base
// dir is watched in the copy; a folder outside it (installed modules) stays where it was.
TEST_F(HotReload, FromAMovedTreeWatchesTheCopy) {
    const std::string base = PRISM_SOURCE_DIR, modules = base + "/modules", contract = modules + "/contract.json";
    const std::string outside = "/opt/prism-installed/share/prism/modules";  // not under the base dir
    const std::string_view dirs[] = {modules, outside}, contracts[] = {contract};
    const catalog::SourceTree tree{"prism::shaders", base, dirs, contracts, {}};
    const auto options = render::ShaderWatchOptions::from(tree, root_.string());
    EXPECT_EQ(options.sourceRoot, root_.string());
    EXPECT_EQ(options.moduleDirs, (std::vector<std::string>{"modules", outside}));
    EXPECT_EQ(options.contractFiles, std::vector<std::string>{"modules/contract.json"});
    EXPECT_EQ(render::ShaderWatchOptions::from(tree).moduleDirs, (std::vector<std::string>{modules, outside}));

    cache_->get("unicolor");
    const render::ShaderWatcher moved(*cache_, options);
    const auto files = moved.watchedFiles();
    EXPECT_NE(std::find(files.begin(), files.end(), material_.lexically_normal().string()), files.end());
    for (const auto& f : files) EXPECT_EQ(f.rfind(root_.string(), 0), 0u) << f << " is not in the copy";
}

// (1) A module edit is picked up, rebuilt and the new program is the one drawing.
TEST_P(HotReloadBy, ModuleEditIsRebuiltAndDrawn) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    EXPECT_TRUE(w.pollNow().reloaded.empty()) << "nothing changed yet";

    editMaterial(kSwapRedAndBlue);
    const auto result = w.pollNow();
    ASSERT_EQ(result.changedFiles.size(), 1u);
    EXPECT_EQ(result.changedFiles[0], material_.lexically_normal().string());
    EXPECT_TRUE(result.diagnostics.empty()) << result.diagnostics.front();
    ASSERT_EQ(result.reloaded.size(), 1u);  // only the variant in use
    EXPECT_EQ(result.reloaded[0].rfind("unicolor (", 0), 0u) << result.reloaded[0];
    EXPECT_EQ(cache_->reloadCount(), 1u);
    EXPECT_EQ(centre(), kBlue);

    // Rewriting the same text (a new modification time) rebuilds nothing.
    editMaterial(kSwapRedAndBlue);
    EXPECT_TRUE(w.pollNow().reloaded.empty());
    EXPECT_EQ(cache_->reloadCount(), 1u);
}

// The program a reload swaps in still knows its shader: another shader's handle stays refused.
TEST_F(HotReload, RebuiltProgramStillKnowsItsShader) {
    auto& w = watcher();
    gl::Program& program = cache_->get("unicolor");
    editMaterial(kSwapRedAndBlue);
    ASSERT_EQ(w.pollNow().reloaded.size(), 1u);
    EXPECT_TRUE(program.builtFrom(shaders::shaderInfo(shaders::ShaderId::unicolor)));
    program.setWarningHandler([](std::string_view) {});
    program.set(shaders::phong::u_color, glm::vec4(1.0f));
    program.set(shaders::unicolor::u_color, glm::vec4(1.0f));
    EXPECT_EQ(program.foreignHandleReports(), std::vector<std::string>{"phong::u_color"});
}

// File times tick coarsely (a jiffy or more): a second edit of the same size may keep the
// first one's mtime. Simulated exactly by setting it back; the content must still count.
TEST_P(HotReloadBy, SameSizeEditWithTheSameMtimeIsSeen) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    editMaterial(kSwapRedAndBlue);
    const auto firstMtime = fs::last_write_time(material_);
    ASSERT_EQ(w.pollNow().reloaded.size(), 1u);
    ASSERT_EQ(centre(), kBlue);
    const std::string swapRedAndGreen = "#define u_color u_color.grba\n";  // (g, r, b): green
    ASSERT_EQ(swapRedAndGreen.size(), kSwapRedAndBlue.size());
    editMaterial(swapRedAndGreen);
    fs::last_write_time(material_, firstMtime);
    EXPECT_EQ(w.pollNow().reloaded.size(), 1u);
    EXPECT_EQ(centre(), (image::Rgba8{0, 255, 0, 255}));
}

// A variant first built after the edit (from the stale catalogue) is rebuilt on the next poll.
TEST_F(HotReload, VariantBuiltAfterTheEditIsRebuiltToo) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    editMaterial(kSwapRedAndBlue);
    ASSERT_EQ(w.pollNow().reloaded.size(), 1u);
    job_.fog = view::Fog{{0.0f, 0.0f, 0.0f}, 0.0f};  // FOG=1, with no visible fog
    EXPECT_EQ(centre(), kRed) << "the FOG=1 program comes from the catalogue until the next poll";
    const auto result = w.pollNow();
    ASSERT_EQ(result.reloaded.size(), 1u);
    EXPECT_NE(result.reloaded[0].find("FOG=1"), std::string::npos) << result.reloaded[0];
    EXPECT_EQ(centre(), kBlue);
}

// (2) A broken edit keeps the last good program and names the module's file and line.
TEST_F(HotReload, SyntaxErrorKeepsTheOldProgramAndNamesModuleLine) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    editMaterial(kSyntaxError);
    const auto result = w.pollNow();
    EXPECT_TRUE(result.reloaded.empty());
    ASSERT_FALSE(result.diagnostics.empty());
    const std::string expected = material_.lexically_normal().string() + ":6:";
    EXPECT_EQ(result.diagnostics[0].rfind(expected, 0), 0u) << result.diagnostics[0];
    EXPECT_NE(result.diagnostics[0].find(": error: "), std::string::npos) << result.diagnostics[0];
    std::cout << "diagnostic: " << result.diagnostics[0];
    EXPECT_EQ(w.errors(), result.diagnostics);
    EXPECT_EQ(cache_->reloadCount(), 0u);
    EXPECT_EQ(centre(), kRed) << "the last good program keeps drawing";
}

TEST_F(HotReload, MissingIncludeKeepsTheOldProgramAndNamesModuleLine) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    editMaterial(kMissingInclude);
    const auto result = w.pollNow();
    EXPECT_TRUE(result.reloaded.empty());
    ASSERT_FALSE(result.diagnostics.empty());
    const std::string expected = material_.lexically_normal().string() + ":6:";
    EXPECT_EQ(result.diagnostics[0].rfind(expected, 0), 0u) << result.diagnostics[0];
    EXPECT_NE(result.diagnostics[0].find("no_such_module.glsl"), std::string::npos) << result.diagnostics[0];
    EXPECT_EQ(centre(), kRed);
}

// An edit only the build step's checks catch (the driver would link it): rejected the same way.
TEST_F(HotReload, ContractViolationKeepsTheOldProgram) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    editMaterial(kUniformOutsideContract);
    const auto result = w.pollNow();
    EXPECT_TRUE(result.reloaded.empty());
    ASSERT_FALSE(result.diagnostics.empty());
    const std::string expected = material_.lexically_normal().string() + ":6:";
    EXPECT_EQ(result.diagnostics[0].rfind(expected, 0), 0u) << result.diagnostics[0];
    EXPECT_NE(result.diagnostics[0].find("u_colour"), std::string::npos) << result.diagnostics[0];
    std::cout << "diagnostic: " << result.diagnostics[0];
    EXPECT_EQ(centre(), kRed);
}

// A broken contract stops every rebuild (nothing can be checked against it) and names
// the contract file's line; fixing it rebuilds what was edited meanwhile.
TEST_P(HotReloadBy, BrokenContractKeepsProgramsAndNamesTheFile) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    const auto contract = root_ / "modules" / "contract.json";
    const std::string good = readFile(contract);
    writeFile(contract, "{\n  \"attributes\": [\n    {\"name\": \"a_position\",\n");  // cut off at line 4
    editMaterial(kSwapRedAndBlue);
    auto result = w.pollNow();
    EXPECT_TRUE(result.reloaded.empty());
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_EQ(result.diagnostics[0].rfind(contract.lexically_normal().string() + ":", 0), 0u) << result.diagnostics[0];
    EXPECT_NE(result.diagnostics[0].find(": error: "), std::string::npos) << result.diagnostics[0];
    EXPECT_EQ(centre(), kRed);

    writeFile(contract, good);
    result = w.pollNow();
    EXPECT_TRUE(result.diagnostics.empty()) << result.diagnostics.front();
    EXPECT_EQ(result.reloaded.size(), 1u);
    EXPECT_TRUE(w.errors().empty());
    EXPECT_EQ(centre(), kBlue);
}

// (3) Fixing the error recovers: the fixed program is swapped in and the errors clear.
TEST_P(HotReloadBy, FixingTheErrorRecovers) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    editMaterial(kSwapRedAndBlue);
    ASSERT_EQ(w.pollNow().reloaded.size(), 1u);
    ASSERT_EQ(centre(), kBlue);

    editMaterial(kSyntaxError);
    ASSERT_FALSE(w.pollNow().diagnostics.empty());
    EXPECT_EQ(centre(), kBlue) << "the reloaded program is the last good one";
    EXPECT_FALSE(w.errors().empty());

    writeFile(material_, originalMaterial_);  // fixed by undoing the edit
    const auto result = w.pollNow();
    EXPECT_TRUE(result.diagnostics.empty()) << result.diagnostics.front();
    EXPECT_EQ(result.reloaded.size(), 1u);
    EXPECT_TRUE(w.errors().empty());
    EXPECT_EQ(centre(), kRed);
}

// The watcher picks inotify on Linux by itself; asking for polling gets polling.
TEST_F(HotReload, UsesInotifyWhereThePlatformHasIt) {
    EXPECT_EQ(watcher().mechanism(), render::WatchMechanism::Inotify);
    mechanism_ = render::WatchMechanism::Polling;
    EXPECT_EQ(watcher().mechanism(), render::WatchMechanism::Polling);
}

// An editor that saves by writing a new file and renaming it over the module (vim's
// backupcopy=no, most IDEs) replaces the file: still seen, and watched after.
TEST_P(HotReloadBy, SaveByRenameIsSeen) {
    auto& w = watcher();
    ASSERT_EQ(centre(), kRed);
    const auto saved = material_.string() + ".swp";
    writeFile(saved, originalMaterial_ + kSwapRedAndBlue);
    fs::rename(saved, material_);
    EXPECT_EQ(w.pollNow().reloaded.size(), 1u);
    EXPECT_EQ(centre(), kBlue);
    editMaterial("");
    EXPECT_EQ(w.pollNow().reloaded.size(), 1u) << "the new file is watched too";
    EXPECT_EQ(centre(), kRed);
}

// With inotify a check looks only at the files the kernel reported, and poll() looks at
// every call (no interval): an edit is in use at the next frame.
TEST_F(HotReload, InotifyPollSeesAnEditAtTheNextCall) {
    auto& w = watcher(std::chrono::hours(1));
    ASSERT_EQ(w.mechanism(), render::WatchMechanism::Inotify);
    ASSERT_EQ(centre(), kRed);
    editMaterial(kSwapRedAndBlue);
    const auto result = w.poll();
    EXPECT_TRUE(result.checked);
    EXPECT_EQ(result.reloaded.size(), 1u);
    EXPECT_EQ(centre(), kBlue);
}

// A catalogue built against modules outside its --base-dir (an installed Prism's): the
// line tables give those modules' paths relative to their -I directory (searchDir 1), and
// the watcher watches them there, not under the base dir (issue 22, item 3).
TEST_P(HotReloadBy, ModuleOutsideTheBaseDirIsWatchedWhereTheBuildFoundIt) {
    const fs::path project = root_ / "project";
    fs::create_directories(project);
    fs::rename(root_ / "shader_sources", project / "shader_sources");  // modules/ stays outside the project
    std::vector<std::vector<catalog::SourceFile>> files;
    const auto& unicolor = *catalog::findShader(shaders::kCatalog, "unicolor");
    for (const auto& v : unicolor.variants)
        for (const auto& st : v.stages) {
            auto& rows = files.emplace_back(st.files.begin(), st.files.end());
            for (auto& f : rows)
                if (f.path.starts_with("modules/")) f = {f.number, f.path.substr(8), 1};
        }
    std::vector<std::vector<catalog::StageSource>> stages;
    std::vector<catalog::Variant> variants;
    for (std::size_t v = 0, k = 0; v < unicolor.variants.size(); ++v) {
        auto& list = stages.emplace_back();
        for (const auto& st : unicolor.variants[v].stages) list.push_back({st.stage, st.chunks, files[k++]});
    }
    for (std::size_t v = 0; v < unicolor.variants.size(); ++v) {
        variants.push_back(unicolor.variants[v]);
        variants.back().stages = stages[v];
    }
    const catalog::Shader shader{unicolor.name, unicolor.axes, variants, unicolor.modules};
    const catalog::Catalog outside{std::span(&shader, 1), shaders::kCatalog.modules,
                                   shaders::kCatalog.contractAttributes, shaders::kCatalog.contractUniforms,
                                   shaders::kCatalog.versionDirective};
    cache_ = std::make_unique<render::ProgramCache>(outside);
    render::ShaderWatchOptions options;
    options.sourceRoot = project.string();
    options.moduleDirs = {(root_ / "modules").string()};
    options.mechanism = GetParam();
    watcher_ = std::make_unique<render::ShaderWatcher>(*cache_, options);
    const auto watched = watcher_->watchedFiles();
    EXPECT_NE(std::find(watched.begin(), watched.end(), material_.lexically_normal().string()), watched.end());
    ASSERT_EQ(centre(), kRed);
    editMaterial(kSwapRedAndBlue);
    const auto result = watcher_->pollNow();
    EXPECT_TRUE(result.diagnostics.empty()) << result.diagnostics.front();
    EXPECT_EQ(result.reloaded.size(), 1u);
    EXPECT_EQ(centre(), kBlue);
    watcher_.reset();  // before `outside`, which both refer to
    cache_.reset();
}

// (4) Issue 9: "a test writes a module edit and measures the time until the new program
// is in use: under 1 s". A render loop polls at the default interval (100 ms) as the
// viewer does; the clock runs from the write until a frame shows the new colour.
TEST_F(HotReload, EditToNewProgramInUseUnderOneSecond) {
    mechanism_ = render::WatchMechanism::Polling;
    auto& w = watcher(std::chrono::milliseconds(100));
    ASSERT_EQ(centre(), kRed);
    const auto start = std::chrono::steady_clock::now();
    editMaterial(kSwapRedAndBlue);
    double ms = 0.0;
    int frames = 0;
    for (;;) {
        w.poll();
        ++frames;
        const bool swapped = centre() == kBlue;
        ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (swapped || ms > 5000.0) break;
    }
    std::cout << "hot reload: module edit to new program in use: " << ms << " ms (" << frames
              << " frames, poll interval 100 ms; target < 1000 ms)\n";
    EXPECT_LT(ms, 1000.0);
    EXPECT_EQ(centre(), kBlue);
}

}  // namespace
}  // namespace prism::test
