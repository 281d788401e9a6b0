// The usage example of prism/catalog/did_you_mean.hpp, compiled and run by tests/snippets.
#include <string>
#include <vector>

// [snippet]
#include "prism/catalog/did_you_mean.hpp"
// [/snippet]

int main() {
    // [snippet]
    std::vector<std::string> axes{"DIRECTIONAL_LIGHTS", "POINT_LIGHTS", "FOG"};
    std::string hint = prism::catalog::didYouMean("DIRECTIONAL_LIGHT", axes);
    // hint == " (did you mean 'DIRECTIONAL_LIGHTS'?)"; "" when nothing is close
    // [/snippet]
    const bool farIsEmpty = prism::catalog::didYouMean("BLOOM", axes).empty();
    return hint == " (did you mean 'DIRECTIONAL_LIGHTS'?)" && farIsEmpty ? 0 : 1;
}
