// Conditional evaluation for the include resolver: logical lines, directives, macros,
// the `#if` expression evaluator and the conditional stack (see the header).
#include "preprocessor_conditions.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <set>

namespace prism::shaderc {
namespace {

// ---- lines and comments ----------------------------------------------------------

std::vector<std::string> splitPhysicalLines(std::string_view text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.emplace_back(line);
        start = end + 1;
    }
    return lines;
}

bool endsWithContinuation(const std::string& line) {
    return !line.empty() && line.back() == '\\';
}

bool startsWith(std::string_view text, std::size_t at, std::string_view prefix) {
    return text.substr(at, prefix.size()) == prefix;
}

// Replaces comments in `spliced` by spaces (same length). `inBlockComment` carries a
// /* */ comment over from the previous logical line and out to the next one. On a
// directive line a "..." string is opaque, so `#include "a//b"` keeps its name.
std::string blankComments(std::string_view spliced, bool& inBlockComment) {
    std::string code(spliced);
    bool inString = false;
    bool sawCode = false;
    bool directiveLine = false;
    std::size_t i = 0;
    while (i < code.size()) {
        if (inBlockComment) {
            if (startsWith(code, i, "*/")) {
                code[i] = code[i + 1] = ' ';
                inBlockComment = false;
                i += 2;
            } else {
                code[i++] = ' ';
            }
        } else if (inString) {
            inString = code[i++] != '"';
        } else if (startsWith(code, i, "//")) {
            std::fill(code.begin() + static_cast<std::ptrdiff_t>(i), code.end(), ' ');
            break;
        } else if (startsWith(code, i, "/*")) {
            code[i] = code[i + 1] = ' ';
            inBlockComment = true;
            i += 2;
        } else {
            const char c = code[i++];
            if (!sawCode && !std::isspace(static_cast<unsigned char>(c))) {
                sawCode = true;
                directiveLine = c == '#';
            }
            inString = directiveLine && c == '"';
        }
    }
    return code;
}

bool isIdentifierStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}

bool isIdentifierChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// ---- expression tokens -------------------------------------------------------------

struct ExpressionError {
    std::string message;
};

struct Token {
    enum class Kind { Number, Identifier, Punctuator };
    Kind kind = Kind::Punctuator;
    std::string text;
    std::int64_t value = 0;
};

constexpr int kMaxMacroExpansionDepth = 64;

std::int64_t parseIntegerLiteral(std::string_view text) {
    std::string_view digits = text;
    if (!digits.empty() && (digits.back() == 'u' || digits.back() == 'U')) digits.remove_suffix(1);
    int base = 10;
    if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
        base = 16;
        digits.remove_prefix(2);
    } else if (digits.size() > 1 && digits[0] == '0') {
        base = 8;
        digits.remove_prefix(1);
    }
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
        throw ExpressionError{"invalid integer literal '" + std::string(text) + "'"};
    return static_cast<std::int64_t>(value);
}

std::string_view matchPunctuator(std::string_view rest) {
    static constexpr std::array<std::string_view, 8> twoChar = {"<<", ">>", "<=", ">=", "==", "!=", "&&", "||"};
    for (const auto op : twoChar)
        if (rest.starts_with(op)) return op;
    static constexpr std::string_view oneChar = "!~-+*/%<>&^|?:()";
    if (oneChar.find(rest.front()) != std::string_view::npos) return rest.substr(0, 1);
    return {};
}

std::vector<Token> tokenize(std::string_view text) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t end = i;
            while (end < text.size() && (isIdentifierChar(text[end]) || text[end] == '.')) ++end;
            const std::string_view literal = text.substr(i, end - i);
            tokens.push_back({Token::Kind::Number, std::string(literal), parseIntegerLiteral(literal)});
            i = end;
        } else if (isIdentifierStart(c)) {
            std::size_t end = i;
            while (end < text.size() && isIdentifierChar(text[end])) ++end;
            tokens.push_back({Token::Kind::Identifier, std::string(text.substr(i, end - i)), 0});
            i = end;
        } else {
            const std::string_view op = matchPunctuator(text.substr(i));
            if (op.empty()) throw ExpressionError{"unexpected character '" + std::string(1, c) + "'"};
            tokens.push_back({Token::Kind::Punctuator, std::string(op), 0});
            i += op.size();
        }
    }
    return tokens;
}

bool isPunctuator(const Token& token, std::string_view text) {
    return token.kind == Token::Kind::Punctuator && token.text == text;
}

Token numberToken(std::int64_t value) {
    return {Token::Kind::Number, std::to_string(value), value};
}

// Reads `defined X` or `defined ( X )` starting after `defined` at `i`; returns the name.
std::string takeDefinedOperand(const std::vector<Token>& tokens, std::size_t& i) {
    const bool parenthesised = i < tokens.size() && isPunctuator(tokens[i], "(");
    if (parenthesised) ++i;
    if (i >= tokens.size() || tokens[i].kind != Token::Kind::Identifier)
        throw ExpressionError{"'defined' must be followed by a macro name"};
    std::string name = tokens[i++].text;
    if (parenthesised) {
        if (i >= tokens.size() || !isPunctuator(tokens[i], ")"))
            throw ExpressionError{"missing ')' after 'defined(" + name + "'"};
        ++i;
    }
    return name;
}

// Replaces `defined` operators by 0/1 and object-like macros by their (expanded)
// tokens. A macro is not expanded again inside its own expansion, as in C.
std::vector<Token> expandMacros(const std::vector<Token>& tokens, const MacroTable& macros,
                                std::set<std::string>& expanding, int depth) {
    if (depth > kMaxMacroExpansionDepth)
        throw ExpressionError{"macro expansion nested more than " + std::to_string(kMaxMacroExpansionDepth) + " deep"};
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < tokens.size()) {
        const Token& token = tokens[i++];
        if (token.kind != Token::Kind::Identifier) {
            out.push_back(token);
            continue;
        }
        if (token.text == "defined") {
            out.push_back(numberToken(macros.isDefined(takeDefinedOperand(tokens, i)) ? 1 : 0));
            continue;
        }
        const Macro* macro = macros.find(token.text);
        if (macro == nullptr || expanding.contains(token.text)) {
            out.push_back(token);
            continue;
        }
        if (macro->functionLike) throw ExpressionError{"function-like macro '" + token.text + "' cannot be used here"};
        expanding.insert(token.text);
        const auto expansion = expandMacros(tokenize(macro->value), macros, expanding, depth + 1);
        expanding.erase(token.text);
        out.insert(out.end(), expansion.begin(), expansion.end());
    }
    return out;
}

// ---- expression parser -------------------------------------------------------------

int binaryPrecedence(const Token& token) {
    if (token.kind != Token::Kind::Punctuator) return 0;
    static const std::map<std::string, int, std::less<>> precedence = {
        {"||", 1}, {"&&", 2}, {"|", 3},  {"^", 4},  {"&", 5}, {"==", 6}, {"!=", 6}, {"<", 7},  {">", 7},
        {"<=", 7}, {">=", 7}, {"<<", 8}, {">>", 8}, {"+", 9}, {"-", 9},  {"*", 10}, {"/", 10}, {"%", 10}};
    const auto found = precedence.find(token.text);
    return found == precedence.end() ? 0 : found->second;
}

std::int64_t wrapped(std::uint64_t value) {
    return static_cast<std::int64_t>(value);
}

std::int64_t divide(std::int64_t lhs, std::int64_t rhs, bool remainder) {
    if (rhs == 0) throw ExpressionError{"division by zero"};
    if (rhs == -1) return remainder ? 0 : wrapped(0 - static_cast<std::uint64_t>(lhs));
    return remainder ? lhs % rhs : lhs / rhs;
}

std::int64_t applyBinary(std::string_view op, std::int64_t lhs, std::int64_t rhs) {
    const auto ulhs = static_cast<std::uint64_t>(lhs);
    const auto urhs = static_cast<std::uint64_t>(rhs);
    const auto shift = static_cast<unsigned>(rhs & 63);
    if (op == "+") return wrapped(ulhs + urhs);
    if (op == "-") return wrapped(ulhs - urhs);
    if (op == "*") return wrapped(ulhs * urhs);
    if (op == "/") return divide(lhs, rhs, false);
    if (op == "%") return divide(lhs, rhs, true);
    if (op == "<<") return wrapped(ulhs << shift);
    if (op == ">>") return lhs >> shift;
    if (op == "<") return lhs < rhs;
    if (op == ">") return lhs > rhs;
    if (op == "<=") return lhs <= rhs;
    if (op == ">=") return lhs >= rhs;
    if (op == "==") return lhs == rhs;
    if (op == "!=") return lhs != rhs;
    if (op == "&") return lhs & rhs;
    if (op == "^") return lhs ^ rhs;
    if (op == "|") return lhs | rhs;
    if (op == "&&") return lhs != 0 && rhs != 0;
    return lhs != 0 || rhs != 0;  // "||"
}

// Recursive descent with precedence climbing. `evaluate` is false inside operands
// that short-circuiting skips, so `0 && 1/0` is fine.
class ExpressionParser {
  public:
    explicit ExpressionParser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

    std::int64_t parseAll() {
        if (tokens_.empty()) throw ExpressionError{"missing expression"};
        const std::int64_t value = parseConditional(true);
        if (pos_ < tokens_.size()) throw ExpressionError{"unexpected '" + tokens_[pos_].text + "'"};
        return value;
    }

  private:
    std::int64_t parseConditional(bool evaluate) {
        const std::int64_t condition = parseBinary(1, evaluate);
        if (!accept("?")) return condition;
        const std::int64_t whenTrue = parseConditional(evaluate && condition != 0);
        expect(":");
        const std::int64_t whenFalse = parseConditional(evaluate && condition == 0);
        return condition != 0 ? whenTrue : whenFalse;
    }

    std::int64_t parseBinary(int minPrecedence, bool evaluate) {
        std::int64_t lhs = parseUnary(evaluate);
        while (pos_ < tokens_.size()) {
            const int precedence = binaryPrecedence(tokens_[pos_]);
            if (precedence < minPrecedence || precedence == 0) break;
            const std::string op = tokens_[pos_++].text;
            const bool shortCircuits = (op == "&&" && lhs == 0) || (op == "||" && lhs != 0);
            const std::int64_t rhs = parseBinary(precedence + 1, evaluate && !shortCircuits);
            if (shortCircuits)
                lhs = op == "||";
            else if (evaluate)
                lhs = applyBinary(op, lhs, rhs);
        }
        return lhs;
    }

    std::int64_t parseUnary(bool evaluate) {
        if (accept("!")) return parseUnary(evaluate) == 0;
        if (accept("~")) return ~parseUnary(evaluate);
        if (accept("-")) return wrapped(0 - static_cast<std::uint64_t>(parseUnary(evaluate)));
        if (accept("+")) return parseUnary(evaluate);
        return parsePrimary(evaluate);
    }

    std::int64_t parsePrimary(bool evaluate) {
        if (pos_ >= tokens_.size()) throw ExpressionError{"expression ends too early"};
        const Token& token = tokens_[pos_++];
        if (token.kind == Token::Kind::Number) return token.value;
        if (token.kind == Token::Kind::Identifier) return 0;  // undefined macro
        if (token.text == "(") {
            const std::int64_t value = parseConditional(evaluate);
            expect(")");
            return value;
        }
        throw ExpressionError{"unexpected '" + token.text + "'"};
    }

    bool accept(std::string_view punctuator) {
        if (pos_ < tokens_.size() && isPunctuator(tokens_[pos_], punctuator)) {
            ++pos_;
            return true;
        }
        return false;
    }

    void expect(std::string_view punctuator) {
        if (!accept(punctuator)) throw ExpressionError{"expected '" + std::string(punctuator) + "'"};
    }

    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
};

}  // namespace

// ---- public helpers ------------------------------------------------------------------

std::vector<LogicalLine> splitLogicalLines(std::string_view text) {
    const std::vector<std::string> physical = splitPhysicalLines(text);
    std::vector<LogicalLine> lines;
    bool inBlockComment = false;
    std::size_t i = 0;
    while (i < physical.size()) {
        LogicalLine line;
        line.firstLine = static_cast<int>(i) + 1;
        line.startsInComment = inBlockComment;
        std::string spliced;
        bool continues = true;
        while (continues && i < physical.size()) {
            const std::string& current = physical[i++];
            line.physical.push_back(current);
            continues = endsWithContinuation(current);
            spliced += continues ? std::string_view(current).substr(0, current.size() - 1) : std::string_view(current);
        }
        line.code = blankComments(spliced, inBlockComment);
        lines.push_back(std::move(line));
    }
    return lines;
}

std::string_view trim(std::string_view text) {
    const auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

std::vector<std::string> splitWhitespace(std::string_view text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        std::size_t end = i;
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
        if (end > i) words.emplace_back(text.substr(i, end - i));
        i = end;
    }
    return words;
}

bool isIdentifier(std::string_view text) {
    return !text.empty() && isIdentifierStart(text.front()) && std::all_of(text.begin(), text.end(), isIdentifierChar);
}

std::optional<Directive> parseDirective(const LogicalLine& line) {
    if (line.startsInComment) return std::nullopt;
    std::string_view code = trim(line.code);
    if (code.empty() || code.front() != '#') return std::nullopt;
    code = trim(code.substr(1));
    std::size_t nameEnd = 0;
    while (nameEnd < code.size() && isIdentifierChar(code[nameEnd])) ++nameEnd;
    return Directive{std::string(code.substr(0, nameEnd)), std::string(trim(code.substr(nameEnd)))};
}

// ---- macros ------------------------------------------------------------------------

void MacroTable::define(const std::string& name, std::string value, bool functionLike) {
    macros_[name] = Macro{std::move(value), functionLike};
}

void MacroTable::undefine(const std::string& name) {
    macros_.erase(name);
}

bool MacroTable::isDefined(const std::string& name) const {
    return macros_.contains(name);
}

const Macro* MacroTable::find(const std::string& name) const {
    const auto found = macros_.find(name);
    return found == macros_.end() ? nullptr : &found->second;
}

std::string MacroTable::defineFromDirective(std::string_view argument) {
    std::size_t nameEnd = 0;
    while (nameEnd < argument.size() && isIdentifierChar(argument[nameEnd])) ++nameEnd;
    const std::string name(argument.substr(0, nameEnd));
    if (!isIdentifier(name)) return "#define needs a macro name";
    const bool functionLike = nameEnd < argument.size() && argument[nameEnd] == '(';
    std::string_view body = argument.substr(nameEnd);
    if (functionLike) {
        const std::size_t close = body.find(')');
        body = close == std::string_view::npos ? std::string_view{} : body.substr(close + 1);
    }
    define(name, std::string(trim(body)), functionLike);
    return {};
}

// ---- versions ----------------------------------------------------------------------

std::string GlslVersion::effectiveProfile() const {
    if (isEs()) return "es";
    if (profile.empty()) return number >= 150 ? "core" : "";
    return profile;
}

std::string GlslVersion::directive() const {
    return "#version " + std::to_string(number) + (profile.empty() ? "" : " " + profile);
}

bool GlslVersion::sameAs(const GlslVersion& other) const {
    return number == other.number && effectiveProfile() == other.effectiveProfile();
}

std::optional<GlslVersion> parseVersionArgument(std::string_view argument) {
    const auto words = splitWhitespace(argument);
    if (words.empty() || words.size() > 2) return std::nullopt;
    GlslVersion version;
    const auto& digits = words[0];
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), version.number);
    if (error != std::errc() || end != digits.data() + digits.size() || version.number <= 0) return std::nullopt;
    if (words.size() == 2) {
        version.profile = words[1];
        if (version.profile != "core" && version.profile != "compatibility" && version.profile != "es")
            return std::nullopt;
    }
    return version;
}

std::optional<GlslVersion> parseVersionDirective(std::string_view line) {
    const auto lines = splitLogicalLines(line);
    if (lines.empty()) return std::nullopt;
    const auto directive = parseDirective(lines.front());
    if (!directive || directive->name != "version") return std::nullopt;
    return parseVersionArgument(directive->argument);
}

void predefineVersionMacros(MacroTable& macros, const GlslVersion& version) {
    macros.define("__VERSION__", std::to_string(version.number));
    macros.undefine("GL_core_profile");
    macros.undefine("GL_compatibility_profile");
    macros.undefine("GL_ES");
    const std::string profile = version.effectiveProfile();
    if (profile == "core") macros.define("GL_core_profile", "1");
    if (profile == "compatibility") macros.define("GL_compatibility_profile", "1");
    if (profile == "es") macros.define("GL_ES", "1");
}

// ---- conditions ----------------------------------------------------------------------

ConditionValue evaluateCondition(std::string_view expression, const MacroTable& macros) {
    try {
        std::set<std::string> expanding;
        auto tokens = expandMacros(tokenize(expression), macros, expanding, 0);
        return {ExpressionParser(std::move(tokens)).parseAll(), {}};
    } catch (const ExpressionError& error) {
        return {0, error.message};
    }
}

bool isConditionalDirective(std::string_view name) {
    return name == "if" || name == "ifdef" || name == "ifndef" || name == "elif" || name == "else" || name == "endif";
}

std::string ConditionalStack::apply(const Directive& directive, int line, const MacroTable& macros) {
    if (directive.name == "elif") return elif (directive, macros);
    if (directive.name == "else") return elseBranch(line);
    if (directive.name == "endif") return endGroup();
    return openGroup(directive, line, macros);
}

bool ConditionalStack::active() const {
    return groups_.empty() || groups_.back().active;
}

std::optional<ConditionalStack::OpenGroup> ConditionalStack::innermostOpen() const {
    if (groups_.empty()) return std::nullopt;
    return groups_.back().opened;
}

std::string ConditionalStack::openGroup(const Directive& directive, int line, const MacroTable& macros) {
    Group group;
    group.opened = {directive.name, line};
    group.parentActive = active();
    std::string error;
    bool condition = false;
    if (group.parentActive && directive.name == "if") {
        const ConditionValue value = evaluateCondition(directive.argument, macros);
        error = value.ok() ? "" : "#if: " + value.error;
        condition = value.ok() && value.value != 0;
    } else if (group.parentActive) {
        const auto words = splitWhitespace(directive.argument);
        if (words.empty() || !isIdentifier(words[0]))
            error = "#" + directive.name + " needs a macro name";
        else
            condition = macros.isDefined(words[0]) == (directive.name == "ifdef");
    }
    group.active = group.parentActive && condition;
    // After an error no branch of the group is taken, so nothing is half-followed.
    group.branchTaken = group.active || !error.empty();
    groups_.push_back(group);
    return error;
}

std::string ConditionalStack::elif (const Directive& directive, const MacroTable& macros) {
    if (groups_.empty()) return "#elif without #if";
    Group& group = groups_.back();
    if (group.elseLine != 0) {
        group.active = false;
        return "#elif after #else (the #else is at line " + std::to_string(group.elseLine) + ")";
    }
    if (!group.parentActive || group.branchTaken) {
        group.active = false;
        return {};
    }
    const ConditionValue value = evaluateCondition(directive.argument, macros);
    group.active = value.ok() && value.value != 0;
    group.branchTaken = group.active || !value.ok();
    return value.ok() ? "" : "#elif: " + value.error;
}

std::string ConditionalStack::elseBranch(int line) {
    if (groups_.empty()) return "#else without #if";
    Group& group = groups_.back();
    if (group.elseLine != 0) {
        group.active = false;
        return "#else after #else (the first #else is at line " + std::to_string(group.elseLine) + ")";
    }
    group.elseLine = line;
    group.active = group.parentActive && !group.branchTaken;
    group.branchTaken = true;
    return {};
}

std::string ConditionalStack::endGroup() {
    if (groups_.empty()) return "#endif without #if";
    groups_.pop_back();
    return {};
}

}  // namespace prism::shaderc
