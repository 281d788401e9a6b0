// BRDF strip: the diffraction BRDF in the plane of incidence (xz of the tangent frame), pixel
// column c at theta = u_diffractionStripAngles.x + c * u_diffractionStripAngles.y degrees
// (positive towards +x), light from u_diffractionStripLight (tangent space, unit). Rendered
// into an RGBA32F target to compare the GPU with the CPU reference (tests/diffraction).
#include <version.glsl>
#include <diffraction/stam.glsl>
#include <fragment_output.glsl>

uniform vec3 u_diffractionStripLight;
uniform vec2 u_diffractionStripAngles;  // start, step in degrees

void main() {
    float theta = radians(u_diffractionStripAngles.x + floor(gl_FragCoord.x) * u_diffractionStripAngles.y);
    vec3 toViewer = vec3(sin(theta), 0.0, cos(theta));
    frag = vec4(diffractionRgb(u_diffractionStripLight, toViewer), 1.0);
}
