// Loading GL function pointers for whichever context backend is current (internal).
// Deliberately free of GL headers so that context_osmesa.cpp can include it.
#pragma once

#include <string>
#include <string_view>

namespace prism::gl::detail {

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// Loads every GL function through `loader` unless it was the last loader used; the
// context of `backendName` must be current. Throws ContextError on failure.
void loadGlFunctions(GlProcLoader loader, std::string_view backendName);

// Forgets the last loader, so the next loadGlFunctions() reloads (after a backend's
// library has been torn down).
void forgetGlFunctions(GlProcLoader loader);

// GL_VERSION, GL_RENDERER, GL_VENDOR and the parsed major/minor version of the
// current context.
struct CurrentGlInfo {
    std::string version, renderer, vendor;
    int major = 0, minor = 0;
};
CurrentGlInfo queryCurrentGlInfo();

}  // namespace prism::gl::detail
