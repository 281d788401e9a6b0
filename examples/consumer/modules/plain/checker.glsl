// Provides: checker(), a two-colour checkerboard over texture coordinates with
// u_checkerScale squares per unit, alternating u_checkerColor and its inverse.
#pragma once

uniform float u_checkerScale;
uniform vec4 u_checkerColor;

vec3 checker(vec2 uv) {
    vec2 cell = floor(uv * max(u_checkerScale, 1.0));
    float odd = mod(cell.x + cell.y, 2.0);
    return mix(u_checkerColor.rgb, vec3(1.0) - u_checkerColor.rgb, odd);
}
