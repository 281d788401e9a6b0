// Which build of prism-shaderc is running: its version, glslang's, and this executable's
// size and modification time (read once per process from /proc/self/exe). Two builds that
// could generate or validate differently never share a no-op decision or a cached result:
// the validation cache's keys, the clean-check record and the --stamp carry it, never the
// generated header or data file, which stay byte-identical whichever build wrote them
// (reproducible and relocatable). A rebuilt tool counts as new even when its code is
// unchanged: one extra generation, against a stale catalogue the other way round. Size
// and time, not a hash of the executable, because the no-op run stats it in microseconds
// where reading its megabytes would cost more than the rest of the run.
//
//   if (readFile(options.stamp) != stampText()) ...  // the outputs were written by another build
//   key.add(toolIdentity());
#pragma once

#include <string>

namespace prism::shaderc {

// "0.1.0 glslang 12.0.0 10982712 1795262400123456789"; the first part alone when the
// executable cannot be read.
const std::string& toolIdentity();

// What --stamp holds: the identity of the build that wrote the outputs, one line.
std::string stampText();

}  // namespace prism::shaderc
