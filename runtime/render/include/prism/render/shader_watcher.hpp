// Hot reload of catalogue shaders: watches the stage files and module files a catalogue
// was built from, and when one changes, re-resolves and re-validates the affected
// variants in process through the shader tool's library (include resolver, glslang
// validation, cross-stage interface and contract checks; no prism-shaderc process),
// then swaps the new programs into the ProgramCache.
//
// Usage (snippet: examples/snippets/render_shader_watcher.cpp):
//
//     prism::render::ProgramCache cache(prism::shaders::kCatalog);
//     prism::render::ShaderWatchOptions options;
//     options.sourceRoot = sourceTree;  // the tree the catalogue was built from
//     prism::render::ShaderWatcher watcher(cache, options);
//     prism::render::RenderJob job;
//     job.shader = "phong";
//     job.mesh = prism::render::meshForShader("phong", prism::render::namedMesh("torus"));
//     for (int frame = 0; frame < 3; ++frame) {                                  // the render loop, on the GL thread
//         for (const auto& d : watcher.poll().diagnostics) std::cerr << d;       // path:line:col: error: ...
//         prism::image::Image8 image = prism::render::renderImage8(cache, job);  // newest good program
//     }
//
// - A catalogue of your own: ShaderWatchOptions::from(<ns>::kSourceTree), from the
//   <header>_sources.hpp that prism_add_shaders() writes (docs/hot-reload.md).
// - The catalogue stores paths relative to prism-shaderc's --base-dir (the source tree
//   for Prism's own catalogue), or to the -I directory a file outside it was found in
//   (catalog::SourceFile::searchDir): `sourceRoot` is the base dir, `moduleDirs` the -I
//   directories in order (default: sourceRoot/modules) and `contractFiles` the --contract
//   files (default: contract.json in the first module dir).
// - Changes: inotify on the files' folders where the platform has it, else polling every
//   pollInterval (ShaderWatchOptions::mechanism, chosen at construction). Either way a
//   file counts as changed when its size, time and content hash say so, so saving a file
//   unchanged reloads nothing; a file modified in the last 2 s is hashed at every look
//   (file times tick coarsely, so a second same-size edit may keep the mtime). A shader
//   depends on every file its variants include; a contract change affects every shader.
// - Only variants that have a program in the cache are rebuilt (a variant built later
//   from the stale catalogue is rebuilt on the next poll).
// - On any error (missing include, glslang, interface or contract check, driver link)
//   the cache keeps the last good program and poll() returns the diagnostics, GCC
//   style `path:line:col: error: message`; errors() keeps them until a rebuild works.
// Needs the cache's context current during poll(). Not thread-safe.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "prism/catalog/source_tree.hpp"
#include "prism/render/program_cache.hpp"

namespace prism::render {

namespace detail {
class ShaderRebuilder;
class FileEvents;
}  // namespace detail

// How a watcher learns of edits. Automatic: Inotify where the platform has it, else Polling.
enum class WatchMechanism { Automatic, Inotify, Polling };

struct ShaderWatchOptions {
    std::string sourceRoot;                       // the catalogue's base dir
    std::vector<std::string> moduleDirs;          // default {sourceRoot/modules}
    std::vector<std::string> contractFiles;       // default {moduleDirs[0]/contract.json}, unless:
    bool builtInContract = false;                 // no contract files: Prism's built-in one, as --contract left out
    std::chrono::milliseconds pollInterval{100};  // Polling: the least time between looks
    std::vector<std::pair<std::string, std::string>> defines;  // prism-shaderc -D, if it had any
    WatchMechanism mechanism = WatchMechanism::Automatic;

    // Everything prism_add_shaders() recorded for a catalogue (its generated
    // <header>_sources.hpp): base dir, -I dirs, contract files (none: the built-in
    // contract) and defines. `movedTo`, when given, is a copy of the recorded base dir (a
    // checkout elsewhere, a scratch copy to edit): the folders and files recorded under the
    // base dir are watched under it instead; those outside it (installed modules) stay.
    static ShaderWatchOptions from(const catalog::SourceTree& sources, const std::string& movedTo = {});
};

struct WatchPollResult {
    bool checked = false;                   // false: called again within pollInterval
    std::vector<std::string> changedFiles;  // whose content changed since the last check
    std::vector<std::string> reloaded;      // "shader (variant)" now running rebuilt programs
    std::vector<std::string> diagnostics;   // errors of this poll's rebuilds, one text each
};

class ShaderWatcher {
  public:
    ShaderWatcher(ProgramCache& cache, ShaderWatchOptions options);
    ~ShaderWatcher();
    ShaderWatcher(const ShaderWatcher&) = delete;
    ShaderWatcher& operator=(const ShaderWatcher&) = delete;

    // Checks the files: at every call with inotify, else when pollInterval has passed
    // since the last check.
    WatchPollResult poll();
    // Checks the files now.
    WatchPollResult pollNow();

    // Outstanding errors: those of the latest failed rebuilds not yet fixed, in order.
    std::vector<std::string> errors() const;
    // Every file watched (absolute, normalised), sorted.
    std::vector<std::string> watchedFiles() const;
    // options.sourceRoot, absolute and normalised (diagnostics name files under it).
    const std::string& sourceRoot() const { return options_.sourceRoot; }
    // Inotify or Polling: the mechanism in use.
    WatchMechanism mechanism() const;

  private:
    struct FileState {
        bool exists = false;
        std::int64_t mtime = 0;
        std::uintmax_t size = 0;
        std::uint64_t hash = 0;
        bool racy = false;  // modified so recently that a same-size edit may keep its mtime
    };
    using VariantKey = std::pair<std::string, std::string>;  // shader, variant name

    std::string locate(const catalog::SourceFile& file) const;  // where the build step read it
    void watch(const std::string& path);
    bool refresh(const std::string& path, FileState& state);  // true when the content changed
    void rebuild(const std::string& shader, const std::string& variant, WatchPollResult& result,
                 std::set<std::string>& seenDiagnostics);

    ProgramCache& cache_;
    ShaderWatchOptions options_;
    std::unique_ptr<detail::ShaderRebuilder> rebuilder_;
    std::unique_ptr<detail::FileEvents> events_;
    std::map<std::string, FileState> files_;                     // watched path -> last state
    std::map<std::string, std::set<std::string>> dependencies_;  // shader -> files
    std::set<std::string> editedShaders_;                        // catalogue text is stale
    std::set<VariantKey> current_;                               // rebuilt since the last edit
    std::map<VariantKey, std::vector<std::string>> errors_;      // failing variants
    std::vector<std::string> contractErrors_;
    std::chrono::steady_clock::time_point lastCheck_{};
};

}  // namespace prism::render
