// Diagnostics of prism-shaderc: one record per problem, printed GCC style
// (`path:line:col: error: message` + `  included from path:line`) or MSVC style,
// each distinct problem once even when many shaders include the same module.
#pragma once

#include <iosfwd>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace prism::shaderc {

enum class Severity { Error, Warning, Note };

// Where a file was (first) included: `file:line` of the #include directive.
struct IncludeSite {
    std::string file;
    int line = 0;
    bool operator==(const IncludeSite&) const = default;
};

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;  // display path; empty for errors not tied to a file
    int line = 0;      // 1-based; 0 = unknown
    int column = 0;    // 1-based; 0 = unknown (printed as 1)
    std::string message;
    std::vector<IncludeSite> includedFrom;  // innermost includer first
    std::vector<Diagnostic> notes;          // follow-up notes printed right after
};

enum class ErrorFormat { Gcc, Msvc };

std::string formatDiagnostic(const Diagnostic& d, ErrorFormat fmt);

// Collects diagnostics from every stage, drops exact repeats (same severity, file,
// line, column and message), and prints them in the order first seen.
class DiagnosticSink {
  public:
    // Returns false when `d` repeated an earlier one and was dropped.
    bool report(Diagnostic d);
    void reportAll(std::vector<Diagnostic> ds) {
        for (auto& d : ds) report(std::move(d));
    }
    const std::vector<Diagnostic>& diagnostics() const { return kept_; }
    int errorCount() const;
    void print(std::ostream& out, ErrorFormat fmt) const;

  private:
    std::vector<Diagnostic> kept_;
    std::set<std::tuple<int, std::string, int, int, std::string>> seen_;
};

inline Diagnostic makeError(std::string file, int line, int column, std::string message) {
    Diagnostic d;
    d.file = std::move(file);
    d.line = line;
    d.column = column;
    d.message = std::move(message);
    return d;
}

}  // namespace prism::shaderc
