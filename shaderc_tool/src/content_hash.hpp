// Content hashes for prism-shaderc's validation cache and keys: a 128-bit hash (two
// independent 64-bit multiply-xorshift lanes over 8-byte words) as 32 hex digits. Not
// cryptographic: it names cache entries in the user's own build tree.
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
    std::uint64_t a_ = 14695981039346656037ull;
    std::uint64_t b_ = 0x84222325cbf29ce4ull;  // a second lane, another start
};

}  // namespace prism::shaderc
