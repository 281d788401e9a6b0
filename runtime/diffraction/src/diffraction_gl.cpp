// Uploading the diffraction lookup tables and setting their uniforms (see diffraction_gl.hpp).
#include "prism/diffraction/diffraction_gl.hpp"

#include <utility>
#include <vector>

#include "prism/diffraction_shaders.hpp"
#include "prism/gl/gl.hpp"

namespace prism::diffraction {
namespace {

gl::Texture makeArray(int size, int layers, GLenum internalFormat, GLenum format, const std::vector<float>& texels) {
    gl::Texture texture = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, static_cast<GLint>(internalFormat), size, size, layers, 0, format, GL_FLOAT,
                 texels.data());
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    gl::throwIfGlError("uploading diffraction tables");
    return texture;
}

}  // namespace

DiffractionTextures::DiffractionTextures(const SpectralTables& t) : uniforms_(tableUniforms(t)) {
    tables_ = makeArray(t.size, t.terms + 1, GL_RG32F, GL_RG, t.texels);
    const std::vector<float> row = wavelengthTexels(t);
    wavelengths_ = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, wavelengths_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, uniforms_.wavelengthCount, 1, 0, GL_RGBA, GL_FLOAT, row.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    gl::throwIfGlError("uploading diffraction wavelengths");
    bytes_ = t.bytes() + row.size() * sizeof(float);
}

DiffractionTextures::DiffractionTextures(const IntegratedTables& t) : uniforms_(tableUniforms(t)) {
    tables_ = makeArray(t.size, 2 * t.terms + 1, GL_RGB32F, GL_RGB, t.texels);
    bytes_ = t.bytes();
}

DiffractionTextures::DiffractionTextures(const VolumeTables& t) : uniforms_(tableUniforms(t)) {
    tables_ = gl::Texture::create();
    glBindTexture(GL_TEXTURE_3D, tables_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB32F, t.size, t.size, t.slices, 0, GL_RGB, GL_FLOAT, t.texels.data());
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_3D, 0);
    gl::throwIfGlError("uploading the diffraction volume");
    bytes_ = t.bytes();
}

void DiffractionTextures::apply(gl::Program& program, int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    const TableUniforms& u = uniforms_;
    program.set(diffraction_shaders::contract::u_diffractionTableSize, static_cast<float>(u.size));
    program.set(diffraction_shaders::contract::u_diffractionExtent, static_cast<float>(u.extent));
    if (u.path == 2) {
        glBindTexture(GL_TEXTURE_3D, tables_.id());
        program.set(diffraction_shaders::contract::u_diffractionVolume, unit);
        program.set(diffraction_shaders::contract::u_diffractionSlices, static_cast<float>(u.slices));
    } else {
        glBindTexture(GL_TEXTURE_2D_ARRAY, tables_.id());
        program.set(diffraction_shaders::contract::u_diffractionTables, unit);
        program.set(diffraction_shaders::contract::u_diffractionTerms, u.terms);
    }
    if (u.path == 0) {
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit + 1));
        glBindTexture(GL_TEXTURE_2D, wavelengths_.id());
        program.set(diffraction_shaders::contract::u_diffractionWavelengths, unit + 1);
        program.set(diffraction_shaders::contract::u_diffractionHeightScale, static_cast<float>(u.heightScaleNm));
        program.set(diffraction_shaders::contract::u_diffractionWavelengthCount, u.wavelengthCount);
    }
    glActiveTexture(GL_TEXTURE0);
}

render::ProgramCache& diffractionPrograms() {
    static render::ProgramCache cache(diffraction_shaders::kCatalog);
    return cache;
}

}  // namespace prism::diffraction
