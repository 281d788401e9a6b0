// The usage example of prism/hash/content_hash.hpp, compiled and run by tests/snippets:
// the parts' boundaries count, and equal inputs give equal hashes.
#include <cstdint>
#include <string>

// [snippet]
#include "prism/hash/content_hash.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::hash::ContentHash key;
    key.add("shaders/phong.frag").add("void main() {}");  // ("ab","c") and ("a","bc") differ
    const std::string name = key.hex();                   // 32 hex digits
    const std::uint64_t quick = prism::hash::hash64("void main() {}");
    // [/snippet]
    prism::hash::ContentHash other;
    other.add("shaders/phong.fra").add("gvoid main() {}");
    const bool ok = name.size() == 32 && other.hex() != name && quick == prism::hash::hash64("void main() {}") &&
                    quick != prism::hash::hash64("void main() { }");
    return ok ? 0 : 1;
}
