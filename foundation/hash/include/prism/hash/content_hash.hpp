// The one content hash of Prism (xxHash's XXH3), shared by prism-shaderc (generated-file
// records, validation keys) and the runtime (hot reload's change check, blue-noise cache
// keys). Not cryptographic: it names and compares contents in the user's own build tree.
//
// Usage (snippet: examples/snippets/hash_content_hash.cpp):
//
//     #include "prism/hash/content_hash.hpp"
//     prism::hash::ContentHash key;
//     key.add("shaders/phong.frag").add("void main() {}");  // ("ab","c") and ("a","bc") differ
//     const std::string name = key.hex();                   // 32 hex digits
//     const std::uint64_t quick = prism::hash::hash64("void main() {}");
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace prism::hash {

// A 128-bit XXH3 hash of a sequence of parts, streamed.
class ContentHash {
  public:
    ContentHash();
    ~ContentHash();
    ContentHash(const ContentHash&) = delete;
    ContentHash& operator=(const ContentHash&) = delete;

    // Adds `part` and then its length, so that the parts' boundaries count.
    ContentHash& add(std::string_view part);
    // Adds `bytes` as they are: consecutive calls hash like one call with their concatenation.
    ContentHash& addBytes(std::string_view bytes);

    std::string hex() const;      // the 128 bits, 32 hex digits
    std::string hex64() const;    // the low 64 bits, 16 hex digits
    std::uint64_t low64() const;  // the low 64 bits

  private:
    struct State;
    std::unique_ptr<State> state_;
};

// The 64-bit XXH3 hash of `bytes`.
std::uint64_t hash64(std::string_view bytes);

}  // namespace prism::hash
