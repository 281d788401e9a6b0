#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp samplerCube;
precision highp sampler3D;
precision highp samplerCubeShadow;
precision highp sampler2DShadow;
precision highp sampler2DArray;
precision highp sampler2DArrayShadow;
precision highp isampler2D;
precision highp isampler3D;
precision highp isamplerCube;
precision highp isampler2DArray;
precision highp usampler2D;
precision highp usampler3D;
precision highp usamplerCube;
precision highp usampler2DArray;
#define BLINN 1
#define FOG 1
#define DIRECTIONAL_LIGHTS 1
#define POINT_LIGHTS 1
#line 1 0
// Phong: passes the eye-space position and normal on; lighting happens per fragment.
#line 1 1
// Provides: the GLSL version every Prism shader targets (330 core) and default precision.

precision highp float;
#line 3 0
#line 1 2
// Provides: the engine's transform uniforms (u_world, u_view, u_projection, u_normal)
// and helpers from object space to world, eye and clip space. u_normal is the
// inverse-transpose of the upper 3x3 of u_view * u_world (eye-space normals).
uniform mat4 u_world;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform mat3 u_normal;

vec4 eyePosition(vec3 objectPosition) {
    return u_view * (u_world * vec4(objectPosition, 1.0));
}

vec4 clipPosition(vec4 eye) {
    return u_projection * eye;
}
#line 4 0

in vec3 a_position;
in vec3 a_normal;
out vec3 v_eyePosition;
out vec3 v_eyeNormal;

void main() {
    vec4 eye = eyePosition(a_position);
    v_eyePosition = eye.xyz;
    v_eyeNormal = u_normal * a_normal;
    gl_Position = clipPosition(eye);
}
