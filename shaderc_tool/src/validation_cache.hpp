// The content-addressed cache of program validation results (glslang compile, link,
// interface and contract checks, reflection), kept in the build tree so that a check
// after an edit validates only the programs whose token streams changed.
//
// - Key: the program's token key (tool build and glslang version, contract, each
//   stage's kind, #version and validation key, validation_key.hpp) and its text key
//   (also the exact texts, line tables and paths). A result without diagnostics is reused on the token
//   key alone (comments or line layout cannot change it); one with diagnostics only on
//   the text key too, since its lines and paths must still be right. The schedulers store
//   only clean results (target_scheduler.hpp), so that second rule is a safeguard.
// - Storage: one pack per catalogue, `<dir>/<catalogue key>.json`, mapping token keys to
//   results: one read per run and, when something new was validated, one write of the
//   entries this run used plus older ones up to 4x that number (+64), so an undone edit
//   still hits and the pack stays bounded. Written to a temporary file
//   and renamed into place, so concurrent writers (parallel builds sharing the
//   directory) never expose a torn pack; an unreadable or foreign pack is empty.
//   The es300 and spirv targets keep their own packs beside it, `<catalogue key>-es300.json`
//   and `-spirv.json` (target_scheduler.hpp). SPIR-V words are stored once per distinct
//   module, in the pack's module table, by content hash.
//
//   ValidationCache cache("build/shaders/prism-shaderc-cache", catalogueKey);
//   if (auto hit = cache.find(key)) ... else cache.store(key, validateProgram(...));
//   cache.flush();
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "validator.hpp"

namespace prism::shaderc {

struct ProgramKey {
    std::string tokens;  // what the compiler sees
    std::string text;    // + exact texts, line tables and paths
};

class ValidationCache {
  public:
    // dir "" = disabled: finds nothing, stores nothing.
    ValidationCache(std::string dir, const std::string& catalogueKey);
    bool enabled() const { return !path_.empty(); }
    std::optional<ValidatedVariant> find(const ProgramKey& key) const;  // thread-safe
    void store(const ProgramKey& key, const ValidatedVariant& result);  // thread-safe
    // Writes the pack when this run stored anything new.
    void flush();
    const std::string& packPath() const { return path_; }

  private:
    struct Entry {
        std::string text;
        ValidatedVariant result;
    };
    std::string path_;
    mutable std::mutex mutex_;
    std::map<std::string, Entry> entries_;  // by token key
    mutable std::set<std::string> used_;
    bool dirty_ = false;
};

}  // namespace prism::shaderc
