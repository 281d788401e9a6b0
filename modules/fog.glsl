// Provides: exponential distance fog, applyFog(colour, eyeDistance) = mix(u_fogColor,
// colour, exp(-u_fogDensity * distance)). Shaders include it only under `#if FOG`
// (the FOG variant), so a scene without fog runs no fog code and has no fog uniforms.
uniform vec3 u_fogColor;
uniform float u_fogDensity;

// Never NaN for density >= 0 and finite distances: the exponent is clamped.
vec3 applyFog(vec3 color, float eyeDistance) {
    float visibility = exp(-clamp(u_fogDensity * max(eyeDistance, 0.0), 0.0, 80.0));
    return mix(u_fogColor, color, visibility);
}
