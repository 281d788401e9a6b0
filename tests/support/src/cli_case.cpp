// checkCliCase and its helpers (prism/test/cli_case.hpp).
#include "prism/test/cli_case.hpp"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace prism::test {
namespace {

namespace fs = std::filesystem;

const CliCase& caseNamed(const CliSuite& suite, const std::string& name) {
    for (const auto& c : suite.cases)
        if (c.name == name) return c;
    throw std::invalid_argument("no command-line case named " + name);
}

std::string expand(std::string text, const CliSuite& suite, const fs::path& folder) {
    const std::pair<std::string, std::string> fields[] = {
        {"{D}", (folder / "out").string()}, {"{T}", folder.string()}, {"{S}", suite.scenes}};
    for (const auto& [field, value] : fields)
        for (std::size_t at; (at = text.find(field)) != std::string::npos;) text.replace(at, field.size(), value);
    return text;
}

CommandResult runCase(const CliSuite& suite, const CliCase& c, const fs::path& folder) {
    std::vector<std::string> command = appCommand(suite, c.program);
    for (const auto& a : c.args) command.push_back(expand(a, suite, folder));
    return runCommand(command, {.workDir = folder, .mergeStderr = false});
}

bool isPng(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    char head[24] = {};
    return in.read(head, sizeof head) && std::string(head, 8) == "\x89PNG\r\n\x1a\n";
}

void checkOutcome(const CliSuite& suite, const CliCase& c, const fs::path& folder, const CommandResult& r) {
    EXPECT_EQ(r.exitCode, c.exitCode) << r;
    EXPECT_NE(r.err.find(c.errText), std::string::npos) << "stderr lacks '" << c.errText << "'\n" << r;
    // An empty regex matches any text.
    EXPECT_TRUE(std::regex_search(r.out, std::regex(c.outRegex))) << "stdout does not match " << c.outRegex << "\n"
                                                                  << r;
    EXPECT_TRUE(std::regex_search(r.err, std::regex(c.errRegex))) << "stderr does not match " << c.errRegex << "\n"
                                                                  << r;
    for (const auto& f : c.files) {
        const fs::path path = expand(f, suite, folder);
        EXPECT_TRUE(fs::is_regular_file(path) && (path.extension() != ".png" || isPng(path)))
            << f << " was not written";
    }
    if (c.exitCode != 2) return;
    for (const auto& e : fs::directory_iterator(folder))
        EXPECT_NE(e.path().filename().string().rfind("out", 0), 0u) << "a refused run wrote " << e.path();
}

}  // namespace

std::vector<std::string> appCommand(const CliSuite& suite, const std::string& program) {
    std::istringstream words(program);
    std::string app, sub;
    words >> app >> sub;
    const auto found = suite.apps.find(app);
    if (found == suite.apps.end()) return {};
    std::vector<std::string> command{found->second};
    if (!sub.empty()) command.push_back(sub);
    return command;
}

std::vector<CliCase> runnableCases(const CliSuite& suite) {
    std::vector<CliCase> cases;
    for (const auto& c : suite.cases)
        if (!appCommand(suite, c.program).empty() &&
            (c.needs.empty() || !appCommand(suite, caseNamed(suite, c.needs).program).empty()))
            cases.push_back(c);
    return cases;
}

void checkCliCase(const CliSuite& suite, const CliCase& c) {
    const fs::path folder = suite.root / c.name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    if (!c.needs.empty()) {
        const auto first = runCase(suite, caseNamed(suite, c.needs), folder);
        ASSERT_EQ(first.exitCode, 0) << "the case this one needs failed: " << first;
    }
    checkOutcome(suite, c, folder, runCase(suite, c, folder));
}

std::string caseName(const ::testing::TestParamInfo<CliCase>& info) {
    return info.param.name;
}

void PrintTo(const CliCase& c, std::ostream* os) {
    *os << c.program;
    for (const auto& a : c.args) *os << ' ' << a;
}

}  // namespace prism::test
