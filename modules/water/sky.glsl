// Provides: skyColor(direction), the project's procedural cloudy sky cube map seen in a
// world-space direction, blended into the fog colour towards the horizon when FOG is on
// (the sky is infinitely far, so it takes the fog of a virtual distance that grows as
// the direction approaches the horizon: terrain and sky meet in the same fog colour).
#include <math_utils.glsl>

uniform samplerCube u_skybox;
#if FOG
#include <fog.glsl>
uniform float u_skyFogDistance;  // metres of fog looking straight up
#endif

vec3 skyColor(vec3 direction) {
    vec3 d = safeNormalize(direction, vec3(0.0, 1.0, 0.0));
    vec3 c = texture(u_skybox, d).rgb;
#if FOG
    float elevation = max(d.y, 0.0);
    c = applyFog(c, u_skyFogDistance / max(elevation, 0.01));
#endif
    return c;
}
