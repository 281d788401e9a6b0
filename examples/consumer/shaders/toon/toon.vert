// Toon: a shader of the consumer's own, built without CONTRACT or NAMESPACE (so its
// catalogue is toon_shaders, checked against Prism's built-in contract).
#include <version.glsl>
#include <transforms.glsl>

in vec3 a_position;
in vec3 a_normal;
out vec3 v_normal;

void main() {
    v_normal = a_normal;
    gl_Position = clipPosition(eyePosition(a_position));
}
