// Formatting and de-duplication of prism-shaderc diagnostics (see diagnostics.hpp).
#include "diagnostics.hpp"

#include <ostream>
#include <sstream>

namespace prism::shaderc {
namespace {

std::string_view severityWord(Severity s) {
    switch (s) {
        case Severity::Error: return "error";
        case Severity::Warning: return "warning";
        case Severity::Note: return "note";
    }
    return "error";
}

void formatOne(std::ostringstream& out, const Diagnostic& d, ErrorFormat fmt) {
    const int col = d.column > 0 ? d.column : 1;
    if (d.file.empty()) {
        out << "prism-shaderc: ";
    } else if (fmt == ErrorFormat::Gcc) {
        out << d.file << ':';
        if (d.line > 0) out << d.line << ':' << col << ':';
        out << ' ';
    } else {
        out << d.file;
        if (d.line > 0) out << '(' << d.line << ',' << col << ')';
        out << ": ";
    }
    out << severityWord(d.severity) << ": " << d.message << '\n';
    for (const auto& site : d.includedFrom) {
        if (fmt == ErrorFormat::Gcc)
            out << "  included from " << site.file << ':' << site.line << '\n';
        else
            out << "  included from " << site.file << '(' << site.line << ")\n";
    }
}

}  // namespace

std::string formatDiagnostic(const Diagnostic& d, ErrorFormat fmt) {
    std::ostringstream out;
    formatOne(out, d, fmt);
    for (const auto& n : d.notes) formatOne(out, n, fmt);
    return out.str();
}

bool DiagnosticSink::report(Diagnostic d) {
    auto key = std::make_tuple(static_cast<int>(d.severity), d.file, d.line, d.column, d.message);
    if (!seen_.insert(std::move(key)).second) return false;
    kept_.push_back(std::move(d));
    return true;
}

int DiagnosticSink::errorCount() const {
    int n = 0;
    for (const auto& d : kept_) n += d.severity == Severity::Error;
    return n;
}

void DiagnosticSink::print(std::ostream& out, ErrorFormat fmt) const {
    for (const auto& d : kept_) out << formatDiagnostic(d, fmt);
}

}  // namespace prism::shaderc
