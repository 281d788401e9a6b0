// The usage example of prism/catalog/block_struct.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/catalog/block_struct.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::catalog::Padded<float, 16> weights[4];  // std140 `float weights[4]`
    weights[2] = 0.5f;                             // assigns the value, keeps the padding
    static_assert(sizeof(weights) == 64);
    // [/snippet]
    return static_cast<float>(weights[2]) == 0.5f ? 0 : 1;
}
