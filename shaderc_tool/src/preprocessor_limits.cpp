// Bounds on #if expressions and macro expansion, checked before glslang runs (see
// preprocessor_limits.hpp).
#include "preprocessor_limits.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <string_view>

namespace prism::shaderc {
namespace {

bool isIdentStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Identifiers, numbers and single punctuation characters; spaces dropped. Exact
// multi-character operators do not matter for a size bound.
std::vector<std::string> lex(std::string_view text) {
    std::vector<std::string> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (isIdentStart(c) || std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t end = i;
            while (end < text.size() && (isIdentChar(text[end]) || text[end] == '.')) ++end;
            tokens.emplace_back(text.substr(i, end - i));
            i = end;
        } else {
            tokens.emplace_back(1, c);
            ++i;
        }
    }
    return tokens;
}

// Counts the tokens a token sequence expands to, stopping once past `cap`.
class ExpansionSize {
  public:
    ExpansionSize(const MacroSizeTable& macros, std::uint64_t cap, int maxNesting)
        : macros_(macros), cap_(cap), maxNesting_(maxNesting) {}

    std::uint64_t of(const std::vector<std::string>& tokens) { return sequence(tokens, 0, tokens.size(), nullptr, 0); }
    bool tooDeep() const { return tooDeep_; }

  private:
    using ArgumentSizes = std::map<std::string, std::uint64_t>;

    std::uint64_t add(std::uint64_t a, std::uint64_t b) const { return std::min(a + b, cap_ + 1); }

    std::uint64_t sequence(const std::vector<std::string>& tokens, std::size_t begin, std::size_t end,
                           const ArgumentSizes* arguments, int depth) {
        std::uint64_t total = 0;
        std::size_t i = begin;
        while (i < end && total <= cap_) {
            const std::string& token = tokens[i];
            if (!isIdentStart(token.front())) {
                total = add(total, 1);
                ++i;
                continue;
            }
            if (arguments) {
                if (auto a = arguments->find(token); a != arguments->end()) {
                    total = add(total, a->second);
                    ++i;
                    continue;
                }
            }
            const auto* definitions = macros_.find(token);
            if (!definitions || expanding_.contains(token)) {
                total = add(total, 1);
                ++i;
                continue;
            }
            const bool call = i + 1 < end && tokens[i + 1] == "(";
            std::uint64_t largest = 1;
            std::size_t next = i + 1;
            for (const auto& d : *definitions) {
                if (!d.functionLike) {
                    largest = std::max(largest, objectSize(token, depth));
                } else if (call) {
                    std::size_t closing = 0;
                    largest = std::max(largest, callSize(token, d, tokens, i + 2, end, arguments, depth, closing));
                    next = std::max(next, closing + 1);
                }
                if (tooDeep_) return cap_ + 1;
            }
            total = add(total, largest);
            i = next;
        }
        return total;
    }

    std::uint64_t objectSize(const std::string& name, int depth) {
        auto& cache = macros_.objectSizeCache();
        if (auto cached = cache.find(name); cached != cache.end()) return cached->second;
        if (depth >= maxNesting_) {
            tooDeep_ = true;
            return cap_ + 1;
        }
        std::uint64_t largest = 1;
        expanding_.insert(name);
        for (const auto& d : *macros_.find(name))
            if (!d.functionLike) largest = std::max(largest, sequence(d.body, 0, d.body.size(), nullptr, depth + 1));
        expanding_.erase(name);
        // Cached even inside another expansion: that can only make a self-referring
        // macro look smaller, and it keeps a doubling chain linear to measure.
        if (!tooDeep_) cache[name] = largest;
        return largest;
    }

    // A call NAME( ... ) whose arguments start at `begin`; `closing` gets the ')'.
    std::uint64_t callSize(const std::string& name, const MacroSizeTable::Definition& d,
                           const std::vector<std::string>& tokens, std::size_t begin, std::size_t end,
                           const ArgumentSizes* outer, int depth, std::size_t& closing) {
        if (depth >= maxNesting_) {
            tooDeep_ = true;
            return cap_ + 1;
        }
        std::vector<std::pair<std::size_t, std::size_t>> spans;
        int level = 0;
        std::size_t start = begin, j = begin;
        for (; j < end; ++j) {
            if (tokens[j] == "(") {
                ++level;
            } else if (tokens[j] == ")") {
                if (level == 0) break;
                --level;
            } else if (tokens[j] == "," && level == 0) {
                spans.emplace_back(start, j);
                start = j + 1;
            }
        }
        closing = std::min(j, end - 1);
        if (j == end) return add(0, end - begin + 1);  // the call goes on past this line: count it as written
        spans.emplace_back(start, j);
        ArgumentSizes sizes;
        for (std::size_t k = 0; k < d.parameters.size(); ++k)
            sizes[d.parameters[k]] =
                k < spans.size() ? sequence(tokens, spans[k].first, spans[k].second, outer, depth + 1) : 0;
        expanding_.insert(name);
        const std::uint64_t size = sequence(d.body, 0, d.body.size(), &sizes, depth + 1);
        expanding_.erase(name);
        return size;
    }

    const MacroSizeTable& macros_;
    std::uint64_t cap_;
    int maxNesting_;
    bool tooDeep_ = false;
    std::set<std::string> expanding_;
};

std::string describe(std::uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

}  // namespace

void MacroSizeTable::defineFromDirective(const std::string& argument) {
    std::size_t nameEnd = 0;
    while (nameEnd < argument.size() && isIdentChar(argument[nameEnd])) ++nameEnd;
    const std::string name = argument.substr(0, nameEnd);
    if (name.empty() || !isIdentStart(name.front())) return;
    Definition d;
    std::string_view body = std::string_view(argument).substr(nameEnd);
    if (!body.empty() && body.front() == '(') {
        const std::size_t close = body.find(')');
        if (close == std::string_view::npos) return;
        d.functionLike = true;
        for (auto& p : lex(body.substr(1, close - 1)))
            if (p != ",") d.parameters.push_back(p);
        body = body.substr(close + 1);
    }
    d.body = lex(body);
    definitions_[name].push_back(std::move(d));
    ++definitionCount_;
    objectSizes_.clear();
}

void MacroSizeTable::define(const std::string& name, const std::string& value) {
    defineFromDirective(name + " " + value);
}

const std::vector<MacroSizeTable::Definition>* MacroSizeTable::find(const std::string& name) const {
    const auto found = definitions_.find(name);
    return found == definitions_.end() ? nullptr : &found->second;
}

std::vector<Diagnostic> checkConditionalStructure(const std::string& file, const std::vector<LogicalLine>& lines) {
    struct Group {
        std::string directive;
        int line = 0;
        int elseLine = 0;
    };
    std::vector<Group> open;
    std::vector<Diagnostic> problems;
    for (const LogicalLine& line : lines) {
        const auto directive = parseDirective(line);
        if (!directive) continue;
        const std::string& name = directive->name;
        const std::size_t at = line.code.find('#');
        const int column = at == std::string::npos ? 1 : static_cast<int>(at) + 1;
        if (name == "if" || name == "ifdef" || name == "ifndef") {
            open.push_back({name, line.firstLine, 0});
        } else if (name == "else" || name == "elif" || name == "endif") {
            if (open.empty()) {
                problems.push_back(makeError(file, line.firstLine, column, "#" + name + " without #if"));
            } else if (name == "endif") {
                open.pop_back();
            } else if (open.back().elseLine) {
                problems.push_back(makeError(
                    file, line.firstLine, column,
                    "#" + name + " after #else (the #else is at line " + std::to_string(open.back().elseLine) + ")"));
            } else if (name == "else") {
                open.back().elseLine = line.firstLine;
            }
        }
    }
    if (!open.empty())
        problems.push_back(
            makeError(file, open.back().line, 1,
                      "unterminated #" + open.back().directive + ": no matching #endif before the end of the file"));
    return problems;
}

std::vector<Diagnostic> checkPreprocessorLimits(const std::string& file, std::span<const LogicalLine> lines,
                                                MacroSizeTable& macros, const PreprocessorLimits& limits) {
    std::vector<Diagnostic> problems;
    for (const LogicalLine& line : lines) {
        const auto directive = parseDirective(line);
        if (directive && directive->name == "define") {
            macros.defineFromDirective(directive->argument);
            continue;
        }
        const bool condition = directive && (directive->name == "if" || directive->name == "elif");
        if (directive && !condition) continue;
        const std::uint64_t cap = condition ? limits.maxConditionTokens : limits.maxLineTokens;
        ExpansionSize size(macros, cap, limits.maxCallNesting);
        const std::uint64_t tokens = size.of(lex(condition ? directive->argument : line.code));
        std::string message;
        if (size.tooDeep())
            message = "macro expansion nested more than " + std::to_string(limits.maxCallNesting) +
                      " levels deep (limit); prism-shaderc stops here so the preprocessor cannot overflow its stack";
        else if (tokens > cap && condition)
            message = "#" + directive->name + " expression has more than " + describe(cap) +
                      " tokens after macro expansion (limit); split or simplify it";
        else if (tokens > cap)
            message = "the macros on this line expand to more than " + describe(cap) +
                      " tokens (limit); a macro that repeats another one at each level grows exponentially";
        if (message.empty()) continue;
        const std::size_t column = line.code.find_first_not_of(" \t");
        problems.push_back(makeError(
            file, line.firstLine, column == std::string::npos ? 1 : static_cast<int>(column) + 1, std::move(message)));
    }
    return problems;
}

}  // namespace prism::shaderc
