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
