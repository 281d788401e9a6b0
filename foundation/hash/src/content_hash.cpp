// The one content hash (see prism/hash/content_hash.hpp). xxHash is compiled in here
// (XXH_INLINE_ALL): users of prism_hash need neither its header nor its library.
#include "prism/hash/content_hash.hpp"

#include <cstdio>

#define XXH_INLINE_ALL
#include <xxhash.h>

namespace prism::hash {

struct ContentHash::State {
    XXH3_state_t xxh;
};

ContentHash::ContentHash() : state_(std::make_unique<State>()) {
    XXH3_128bits_reset(&state_->xxh);
}

ContentHash::~ContentHash() = default;

ContentHash& ContentHash::add(std::string_view part) {
    const std::uint64_t size = part.size();
    addBytes(part);
    XXH3_128bits_update(&state_->xxh, &size, sizeof size);
    return *this;
}

ContentHash& ContentHash::addBytes(std::string_view bytes) {
    XXH3_128bits_update(&state_->xxh, bytes.data(), bytes.size());
    return *this;
}

std::string ContentHash::hex() const {
    const XXH128_hash_t h = XXH3_128bits_digest(&state_->xxh);
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                  static_cast<unsigned long long>(h.low64));
    return buf;
}

std::string ContentHash::hex64() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(low64()));
    return buf;
}

std::uint64_t ContentHash::low64() const {
    return XXH3_128bits_digest(&state_->xxh).low64;
}

std::uint64_t hash64(std::string_view bytes) {
    return XXH3_64bits(bytes.data(), bytes.size());
}

}  // namespace prism::hash
