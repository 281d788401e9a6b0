// The translation unit that owns the one precompiled gtest/gtest.h every test binary reuses
// (prism_precompile_gtest in tests/CMakeLists.txt). It has no code of its own.
#include <gtest/gtest.h>
