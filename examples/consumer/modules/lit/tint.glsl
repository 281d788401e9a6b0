// Provides: applyTint(), which blends a colour towards the consumer's tint colour
// u_tint by the tint's alpha (0 keeps the colour, 1 multiplies it by the tint).
#pragma once

uniform vec4 u_tint;

vec3 applyTint(vec3 color) {
    return mix(color, color * u_tint.rgb, clamp(u_tint.a, 0.0, 1.0));
}
