// The usage example of prism/geometry/normal_matrix.hpp, compiled and run by tests/snippets.
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include <cmath>

// [snippet]
#include "prism/geometry/normal_matrix.hpp"
// [/snippet]

int main() {
    const glm::mat4 world = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 0.0f, 1.0f));  // flattened in y
    const glm::vec3 normal(0.0f, 1.0f, 0.0f);
    // [snippet]
    glm::mat3 n = prism::geometry::normalMatrix(world);          // upload as u_normal
    glm::vec3 nw = prism::geometry::transformNormal(n, normal);  // unit, never NaN
    // [/snippet]
    return std::isfinite(n[0][0]) && std::abs(glm::length(nw) - 1.0f) < 1e-5f ? 0 : 1;
}
