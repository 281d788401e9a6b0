// Constructors of the per-backend contexts, each in its own source file (internal).
// A backend's file is compiled only when its library was found at configure time.
#pragma once

#include <memory>

#include "prism/gl/gl_context.hpp"

namespace prism::gl::detail {

// Each creates the context, makes it current and loads the GL functions; the
// factory fills in ContextInfo afterwards.
std::unique_ptr<Context> createEglContext(const ContextOptions& options);
std::unique_ptr<Context> createOsMesaContext(const ContextOptions& options);
std::unique_ptr<Context> createGlfwContext(const ContextOptions& options);

}  // namespace prism::gl::detail
