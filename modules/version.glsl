// Provides: the GLSL version every Prism shader targets (330 core) and default precision.
#version 330 core
precision highp float;
