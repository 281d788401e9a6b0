// BRDF map: the diffraction BRDF in the plane of incidence (xz of the tangent frame). Pixel
// column c views at theta_r = x + c * y degrees (positive towards +x), pixel row r is lit
// from theta_i = z + r * w degrees on the -x side, with (x, y, z, w) = u_diffractionMapAngles.
// One row is a strip of outgoing angles; rendered into RGBA32F to compare the GPU with the CPU
// reference (tests/diffraction) and to measure the error of the fast paths (bench/diffraction).
#include <version.glsl>
#include <diffraction/stam.glsl>
#include <fragment_output.glsl>

uniform vec4 u_diffractionMapAngles;

void main() {
    float thetaR = radians(u_diffractionMapAngles.x + floor(gl_FragCoord.x) * u_diffractionMapAngles.y);
    float thetaI = radians(u_diffractionMapAngles.z + floor(gl_FragCoord.y) * u_diffractionMapAngles.w);
    vec3 toViewer = vec3(sin(thetaR), 0.0, cos(thetaR));
    vec3 toLight = vec3(-sin(thetaI), 0.0, cos(thetaI));
    frag = vec4(diffractionRgb(toLight, toViewer), 1.0);
}
