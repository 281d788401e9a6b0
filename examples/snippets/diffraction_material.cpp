// The usage example of prism/diffraction/material.hpp, compiled and run by tests/snippets.
#include <cstddef>

#include "prism/diffraction/taylor_bound.hpp"
// [snippet]
#include <nlohmann/json.hpp>
#include "prism/diffraction/material.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    nlohmann::json j = nlohmann::json::parse(R"({"height_field": {"type": "sinusoid", "period_nm": 2500,
        "amplitude_nm": 60, "periods": 8}, "path": "b", "table_size": 64, "wavelength_step_nm": 20})");
    DiffractionMaterial m = parseDiffractionMaterial(j, "/objects/0/material/diffraction", ".");
    StamBrdf brdf = makeBrdf(m);                           // N from the height range and m.tolerance
    MaterialTables tables = buildMaterialTables(m, brdf);  // only path b's 2N + 1 layers
    // [/snippet]
    const bool ok = m.path == 'b' && m.tableSize == 64 && brdf.terms() > 0 && tables.integrated && !tables.spectral &&
                    !tables.volume && tables.integrated->size == 64 &&
                    tables.integrated->terms == termsForTolerance(60.0, kLambdaMinNm, 1e-3) &&
                    tables.integrated->terms == brdf.terms() &&
                    tables.integrated->texels.size() == std::size_t(2 * brdf.terms() + 1) * 64 * 64 * 3;
    return ok ? 0 : 1;
}
