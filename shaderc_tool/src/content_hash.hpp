// Content hashes for prism-shaderc's validation cache: a 128-bit hash (two independent
// 64-bit FNV-1a streams) as 32 hex digits, and the token signature of a stage, the
// hash of glslang's preprocessed output without `#line` markers, blank lines and
// runs of blanks: two stages with the same signature are the same token stream for
// the compiler, whatever their comments, defines that nothing tests, or line layout.
//
//   ContentHash h; h.add(text); h.add(path); std::string key = h.hex();
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace prism::shaderc {

class ContentHash {
  public:
    // Adds `part` and a separator, so ("ab","c") and ("a","bc") differ.
    ContentHash& add(std::string_view part);
    std::string hex() const;

  private:
    std::uint64_t a_ = 14695981039346656037ull;  // FNV-1a offset basis
    std::uint64_t b_ = 0x84222325cbf29ce4ull;     // a second stream, another start and prime
};

// The token signature (32 hex digits) of glslang's preprocessed output of a stage.
std::string tokenSignature(std::string_view preprocessed);

}  // namespace prism::shaderc
