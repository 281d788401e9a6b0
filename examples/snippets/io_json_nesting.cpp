// The usage example of prism/io/json_nesting.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/io/json_nesting.hpp"
// [/snippet]

int main() {
    // [snippet]
    auto at = prism::io::firstTooDeep(R"({"a": [[1]]})", 2);     // offset 7: the second '['
    auto [line, column] = prism::io::lineColumnAt("{\n  [", 4);  // 2, 3: the '['
    // [/snippet]
    return at == 7u && !prism::io::firstTooDeep(R"({"a": "[[[["})", 2) && line == 2 && column == 3 ? 0 : 1;
}
