// The content-addressed cache of program validation results (glslang compile, link,
// interface and contract checks, reflection), kept in the build tree so that a check
// after an edit validates only the programs whose token streams changed.
//
// - Key: the program's token key (tool build and glslang version, contract, each stage's kind, #version
//   and token signature) and its text key (also the exact texts, line tables and
//   paths). A result without diagnostics is reused on the token key alone (comments
//   or line layout cannot change it); one with diagnostics only on the text key too,
//   since its lines and paths must still be right.
// - One file per program, `<dir>/<key[0:2]>/<key>.json`, written to a temporary file
//   and renamed into place, so concurrent writers (parallel builds sharing the
//   directory) never expose a torn entry; an unreadable or foreign entry is a miss.
//
//   ValidationCache cache("build/shaders/prism-shaderc-cache");
//   if (auto hit = cache.find(key)) ... else cache.store(key, validateProgram(...));
#pragma once

#include <optional>
#include <string>

#include "validator.hpp"

namespace prism::shaderc {

struct ProgramKey {
    std::string tokens;  // what the compiler sees
    std::string text;    // + exact texts, line tables and paths
};

class ValidationCache {
  public:
    explicit ValidationCache(std::string dir);  // "" = disabled: finds nothing, stores nothing
    bool enabled() const { return !dir_.empty(); }
    std::optional<ValidatedVariant> find(const ProgramKey& key) const;
    void store(const ProgramKey& key, const ValidatedVariant& result) const;
    // Where the entry for `tokenKey` lives.
    std::string entryPath(const std::string& tokenKey) const;

  private:
    std::string dir_;
};

}  // namespace prism::shaderc
