// Module identifiers: a module's path relative to the root that found it (an -I
// directory, a stage folder, or --base-dir), mangled into a C++ identifier that no
// other path can produce:
//   - a trailing ".glsl" is dropped; the path's folders are joined with "__":
//     color/space/rgb2hsv.glsl -> color__space__rgb2hsv, fragment_output.glsl -> fragment_output;
//   - a path component that is not letters and digits with single inner underscores
//     (or, first, starts with a digit) is written as "_" + the hex of its bytes:
//     my-lib/x.glsl -> _6d792d6c6962__x;
//   - a C++ keyword gets a trailing "_" (new.glsl -> new_).
// So a_b/c -> a_b__c and a/b_c -> a__b_c differ, and demangleModuleIdentifier() gives
// the path back (without ".glsl"), which is what makes the mapping collision-free.
//
// A program's name (a stage file's base name or a --program NAME) is mangled as one folder
// of such a path, so that any text gives a usable ShaderId enumerator and name() keeps the text:
//   phong -> phong, blur-h -> _626c75722d68, 16bit_storage -> _31366269745f73746f72616765.
//
//   assert(mangleModulePath("color/space/rgb2hsv.glsl") == "color__space__rgb2hsv");
//   assert(demangleName(mangleName("blur-h")) == "blur-h");
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace prism::shaderc {

std::string mangleModulePath(std::string_view relativePath);

// The relative path (without a dropped ".glsl") a mangled identifier came from, or
// nullopt when no path mangles to it.
std::optional<std::string> demangleModuleIdentifier(std::string_view identifier);

// The identifier of a program name (see above); nullopt from demangleName() when no name
// mangles to `identifier`.
std::string mangleName(std::string_view name);
std::optional<std::string> demangleName(std::string_view identifier);

// A C++ keyword (C++20, alternative tokens included): an identifier the generated header
// writes with a trailing "_" instead. The one list for every generated name.
bool isCppKeyword(std::string_view word);

// `name` made a valid C++ identifier that is no keyword.
std::string cppIdentifier(const std::string& name);

}  // namespace prism::shaderc
