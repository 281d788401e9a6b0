// prism-shaderc: the build-time GLSL toolchain, a thin client of prism_shaderc_lib
// (prism/shaderc/tool.hpp), like Filament's matc of filamat.
#include "prism/shaderc/tool.hpp"

int main(int argc, char** argv) {
    return prism::shaderc::runTool(argc, argv);
}
