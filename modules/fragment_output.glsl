// Provides: the single colour output of a fragment stage, `frag`.
out vec4 frag;
