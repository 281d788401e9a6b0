// Toon: three bands of light that drift with time, with the uniforms a shader written in
// lygia's style declares (u_resolution, u_time): names of its own, far from every
// contract name, which Prism's contract must not reject.
#include <version.glsl>
#include <fragment_output.glsl>

uniform vec2 u_resolution;
uniform float u_time;
in vec3 v_normal;

void main() {
    vec2 st = gl_FragCoord.xy / u_resolution;
    float light = max(dot(normalize(v_normal), normalize(vec3(0.3, 0.8, 0.5))), 0.0);
    float band = floor(light * 3.0 + 0.1 * sin(u_time + st.x)) / 3.0;
    frag = vec4(vec3(band), 1.0);
}
