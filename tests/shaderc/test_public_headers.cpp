// Issue 10, item 1: no public runtime header includes a generated catalogue, so that
// only the files that name a catalogue's ids recompile when its header changes, and a
// module edit (which changes only the data file) recompiles none of them. Runtime
// headers take `const prism::catalog::Catalog&` or a variant instead.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace fs = std::filesystem;

TEST(PublicHeaders, IncludeNoGeneratedCatalogue) {
    const fs::path runtime = fs::path(PRISM_SOURCE_DIR) / "runtime";
    // A generated catalogue: anything prism_add_shaders() writes, named *shaders.hpp.
    const std::regex include(R"(^\s*#\s*include\s*[<"]([^>"]*shaders\.hpp)[>"])");
    int headers = 0;
    for (const auto& e : fs::recursive_directory_iterator(runtime)) {
        const auto p = e.path().generic_string();
        if (!e.is_regular_file() || e.path().extension() != ".hpp" || p.find("/include/prism/") == std::string::npos)
            continue;
        ++headers;
        std::ifstream in(e.path());
        int n = 0;
        for (std::string line; std::getline(in, line);) {
            ++n;
            std::smatch m;
            EXPECT_FALSE(std::regex_search(line, m, include))
                << p << ":" << n << ": error: public header includes the generated catalogue " << m[1]
                << "; take a const prism::catalog::Catalog& and include it in the .cpp";
        }
    }
    EXPECT_GT(headers, 30);
}
