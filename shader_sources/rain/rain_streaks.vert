// rain_streaks: the geometry-shader technique. The vertex stage passes each particle
// (a GL_POINTS vertex read straight from the simulation buffer) to the geometry stage.
#include <version.glsl>

in vec4 a_rainSeed;
in vec4 a_rainPosition;
in vec4 a_rainVelocity;
out vec4 v_seed;
out vec4 v_position;
out vec4 v_velocity;

void main() {
    v_seed = a_rainSeed;
    v_position = a_rainPosition;
    v_velocity = a_rainVelocity;
    gl_Position = vec4(a_rainPosition.xyz, 1.0);
}
