// A scene's diffraction object built into its path's tables (see prism/scene/diffraction_object.hpp).
#include "prism/scene/diffraction_object.hpp"

#include <stdexcept>

#include "prism/scene/scene_loader.hpp"

namespace prism::scene {

diffraction::TableUniforms DiffractionObjectTables::uniforms() const {
    if (tables.spectral) return diffraction::tableUniforms(*tables.spectral);
    if (tables.integrated) return diffraction::tableUniforms(*tables.integrated);
    return diffraction::tableUniforms(*tables.volume);
}

DiffractionObjectTables buildDiffractionTables(const Scene& scene, const SceneObject& object) {
    const std::string pointer = object.diffractionPointer.empty() ? "/objects" : object.diffractionPointer;
    if (!object.diffraction)
        throw SceneError(scene.file + ": " + pointer + ": expected the diffraction parameters of a diffraction object");
    const diffraction::DiffractionMaterial& m = *object.diffraction;
    try {  // the height field, N from its range, and the tables of the material's path only
        const diffraction::StamBrdf brdf = diffraction::makeBrdf(m);
        return {diffraction::buildMaterialTables(m, brdf), brdf.terms()};
    } catch (const diffraction::MaterialError& e) {  // "terms: ..." or "tolerance: ..."
        throw SceneError(scene.file + ": " + pointer + "/" + e.what());
    } catch (const std::invalid_argument& e) {  // e.g. an unreadable PNG height field
        throw SceneError(scene.file + ": " + pointer + "/height_field: " + e.what());
    }
}

}  // namespace prism::scene
