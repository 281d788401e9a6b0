// The usage example of prism/rain/streak_texture.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/rain/streak_texture.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::rain::StreakTextureArray tex = prism::rain::generateStreakTextures();
    int layer = prism::rain::streakLayer(/*oscillation*/ 3, /*theta bin*/ 2, /*phi bin*/ 8);
    std::uint8_t t = tex.at(layer, 8, 32);
    // [/snippet]
    return t > 0 ? 0 : 1;  // the centre of a streak is never black
}
