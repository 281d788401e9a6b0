// The text of a --program argument (program_argument.hpp).
#include "program_argument.hpp"

namespace prism::shaderc {

std::vector<std::string> splitProgramFiles(const std::string& list) {
    std::vector<std::string> files;
    std::size_t start = 0;
    while (true) {
        const auto comma = list.find(',', start);
        files.push_back(list.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return files;
        start = comma + 1;
    }
}

std::string declarationWithPaths(const std::string& declaration,
                                 const std::function<std::string(const std::string&)>& pathOf) {
    const auto eq = declaration.find('=');
    if (eq == std::string::npos) return declaration;
    std::string out = declaration.substr(0, eq + 1);
    const auto files = splitProgramFiles(declaration.substr(eq + 1));
    for (std::size_t i = 0; i < files.size(); ++i) out += (i ? "," : "") + pathOf(files[i]);
    return out;
}

}  // namespace prism::shaderc
