// Where an #include finds its file, the way glslang's own includer searches:
//   - #include "x": the including file's folder, then the folders of the files further
//     up the include chain (innermost first, ending with the stage's), then each -I
//     directory in order;
//   - #include <x>: the -I directories only;
//   - a name starting with '/' ("/lib/a.glsl", as shader packs write it) is relative to
//     each -I directory in order and then --base-dir, never the filesystem root.
// glslc searches only the including file's folder and then -I, so a project moving from
// glslc can silently get another file of the same name from a folder up the chain: when a
// later folder holds a different file of that name, shadowedIncludeMessage() says so.
// Also the directive helpers the resolver and the preprocessor share.
//
//   auto target = *parseIncludeTarget("\"a.glsl\"");
//   auto dirs = includeSearchDirs(target, {"s/x.frag"}, {"modules"}, "");
//   // dirs: s (the including file's folder), modules
//   MemoryReader reader{{"s/a.glsl", ""}, {"modules/a.glsl", ""}};
//   auto found = findInclude(target, dirs, reader);  // s/a.glsl
//   auto warning = shadowedIncludeMessage(target, dirs, *found, reader);
//   // "#include "a.glsl" could mean s/a.glsl (...) or modules/a.glsl (-I); ..."
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "directive_lines.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

struct IncludeTarget {
    std::string name;
    bool angled = false;  // <name>
};

// `"name"` or `<name>` with nothing after it; nullopt when malformed.
std::optional<IncludeTarget> parseIncludeTarget(std::string_view argument);

struct SearchDir {
    std::string path;
    std::string role;       // why it is searched, for "searched: ..." messages
    bool ancestor = false;  // a folder further up the include chain: glslang searches it, glslc does not
};

// `chain`: display paths of the including file and the files above it, innermost first.
std::vector<SearchDir> includeSearchDirs(const IncludeTarget& target, const std::vector<std::string>& chain,
                                         const std::vector<std::string>& includeDirs, const std::string& baseDir);

struct FoundFile {
    std::string display;
    std::string canonical;
    std::size_t dir = 0;  // index of the searched folder that held it
};

std::optional<FoundFile> findInclude(const IncludeTarget& target, const std::vector<SearchDir>& dirs,
                                     const SourceReader& reader);

// When a folder searched after `found`'s holds another file of the same name: a warning
// naming the file taken and the one it shadows (and glslc's pick where that differs),
// and how to make the include unambiguous. "" when no other file could be meant; the same
// file reached through two folders is not ambiguous.
std::string shadowedIncludeMessage(const IncludeTarget& target, const std::vector<SearchDir>& dirs,
                                   const FoundFile& found, const SourceReader& reader);

std::string missingIncludeMessage(const IncludeTarget& target, const std::vector<SearchDir>& dirs);

// 1-based column of the '#' of a directive line.
int directiveColumn(const LogicalLine& line);
// 1-based column of the quote or '<' of an #include target (else the '#').
int includeTargetColumn(const LogicalLine& line);

bool isPragmaOnce(const Directive& directive);
bool isPrismPragma(const Directive& directive);
// #extension lines of include-aware front ends, never passed to a GL driver.
bool isIncludeExtension(const Directive& directive);

}  // namespace prism::shaderc
