// The usage example of prism/water/procedural_textures.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/water/procedural_textures.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::water::CubeFaces sky = prism::water::proceduralSky({.faceSize = 128});
    prism::water::RippleFrames ripples = prism::water::proceduralRipples({});
    // [/snippet]
    return sky.size == 128 && ripples.rgba.size() == 16u * 64u * 64u * 4u ? 0 : 1;
}
