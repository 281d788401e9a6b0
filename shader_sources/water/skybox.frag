// Skybox: the project's procedural cloudy sky cube map (runtime/water sky_texture.cpp);
// FOG blends it into the fog colour towards the horizon (modules/water/sky.glsl).
#pragma prism variant FOG
#include <version.glsl>
#include <water/sky.glsl>
#include <fragment_output.glsl>

in vec3 v_direction;

void main() {
    frag = vec4(skyColor(v_direction), 1.0);
}
