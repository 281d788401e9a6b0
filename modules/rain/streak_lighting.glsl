// Provides: light- and view-dependent streak appearance from the procedural streak
// texture array (prism/rain/streak_texture.hpp), indexed like Tariq's: vertical light
// angle theta (5 bins, 10..170 deg from the streak's upward axis) x horizontal angle phi
// between the light's and the eye's planes through the axis (9 bins, 10..170 deg) x
// drop oscillation type (10). rainStreakBins() gives fractional bin coordinates (per
// drop); rainStreakTexel() blends the 4 nearest (theta, phi) layers bilinearly from one fetch:
// the array is packed (prism::rain::packStreakBinCorners) so that layer (osc, b, c) holds the
// layers (b, c), (b, c + 1), (b + 1, c), (b + 1, c + 1) in R, G, B, A.
// Layer index = (oscillation * 5 + theta bin) * 9 + phi bin.
uniform sampler2DArray u_streakTexture;

const float RAIN_THETA_BINS = 5.0;
const float RAIN_PHI_BINS = 9.0;
const float RAIN_OSCILLATION_TYPES = 10.0;

vec2 rainStreakBins(vec3 toLight, vec3 toEye, vec3 axisUp) {
    float cosTheta = clamp(dot(toLight, axisUp), -1.0, 1.0);
    float theta = degrees(acos(cosTheta));
    vec3 lp = toLight - axisUp * dot(toLight, axisUp);
    vec3 ep = toEye - axisUp * dot(toEye, axisUp);
    float ll = length(lp);
    float le = length(ep);
    float phi = 90.0;  // light (or eye) on the axis: every plane is the same
    if (ll > 1e-4 && le > 1e-4) phi = degrees(acos(clamp(dot(lp, ep) / (ll * le), -1.0, 1.0)));
    return vec2(clamp((theta - 10.0) / 40.0, 0.0, RAIN_THETA_BINS - 1.0),
                clamp((phi - 10.0) / 20.0, 0.0, RAIN_PHI_BINS - 1.0));
}

float rainStreakLayer(float oscillation, float thetaBin, float phiBin) {
    return (oscillation * RAIN_THETA_BINS + thetaBin) * RAIN_PHI_BINS + phiBin;
}

float rainStreakTexel(vec2 uv, vec2 bins, float oscillation) {
    vec2 b0 = floor(bins);
    vec2 f = bins - b0;
    vec4 t = texture(u_streakTexture, vec3(uv, rainStreakLayer(oscillation, b0.x, b0.y)));
    return mix(mix(t.r, t.g, f.y), mix(t.b, t.a, f.y), f.x);
}

// The soft streak silhouette without any light: the sky's reflection in the drop.
float rainStreakShape(vec2 uv) {
    float x = (uv.x - 0.5) / 0.18;
    float across = exp(-0.5 * x * x);
    float ends = smoothstep(0.0, 0.1, uv.y) * (1.0 - smoothstep(0.9, 1.0, uv.y));
    return across * ends;
}
