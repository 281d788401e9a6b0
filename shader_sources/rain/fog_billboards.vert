// fog_billboards: volumetric fog as a few large, slow, camera-facing sprites
// (RainCL §4.4). The vertex stage passes each billboard centre (xyz) and its random (w).
#include <version.glsl>

in vec4 a_fogBillboard;
out vec4 v_billboard;

void main() {
    v_billboard = a_fogBillboard;
    gl_Position = vec4(a_fogBillboard.xyz, 1.0);
}
