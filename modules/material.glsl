// Provides: the material uniforms: base colour, shininess (Phong exponent) and
// specular strength.
uniform vec4 u_color;
uniform float u_shininess;
uniform float u_specular;
