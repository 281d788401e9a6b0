// envFlag (prism/test/env_flag.hpp).
#include "prism/test/env_flag.hpp"

#include <cstdlib>
#include <string_view>

namespace prism::test {

bool envFlag(const char* name) {
    const char* value = std::getenv(name);
    if (!value) return false;
    const std::string_view v(value);
    return !(v.empty() || v == "0" || v == "false" || v == "FALSE" || v == "off");
}

}  // namespace prism::test
