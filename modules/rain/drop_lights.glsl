// Provides: the rain scene's lights as rain and ground see them: a directional sun and
// one point lamp whose light falls off as 1 / (1 + (d / range)^2), so the lamp lights a
// pool of ground and the drops near it (the catalogue's point lights have no falloff).
uniform vec3 u_sunDirection;  // from the sun into the scene, unit length
uniform vec3 u_sunColor;
uniform vec3 u_lampPosition;
uniform vec3 u_lampColor;
uniform float u_lampRange;    // m

vec3 rainLampLight(vec3 worldPosition) {
    vec3 d = u_lampPosition - worldPosition;
    return u_lampColor / (1.0 + dot(d, d) / max(u_lampRange * u_lampRange, 1e-6));
}
