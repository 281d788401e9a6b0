// What the report's live views need to draw the exact view of each gallery image in a browser
// (docs/web.md): the meshes as drawn (after meshForShader; identical ones stored once) and, per
// image, its shader, full variant, mesh, size, background and every active uniform's value as
// the program held it right after the llvmpipe render (read back with glGetUniform*, so the
// record is what was drawn, not a second computation of it). Written as DIR/live-views.json;
// scripts/gallery_live.py turns it into the page's embedded data.
//
//   LiveViews live;
//   auto image = prism::render::renderImage8(cache, job);
//   live.add("phong-torus.png", "torus", cache, job);  // with the context still current
//   live.write(outDir / "live-views.json");
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "prism/render/offscreen_render.hpp"

class LiveViews {
  public:
    // Records image `file` of `job`, just rendered with `cache`; `meshName` names the job's mesh.
    void add(const std::string& file, const std::string& meshName, prism::render::ProgramCache& cache,
             const prism::render::RenderJob& job);
    // Throws std::runtime_error when the file cannot be written.
    void write(const std::filesystem::path& path) const;

  private:
    std::string meshKey(const std::string& meshName, const prism::geometry::Mesh& mesh);

    std::vector<std::pair<std::string, prism::geometry::Mesh>> meshes_;
    nlohmann::ordered_json views_ = nlohmann::ordered_json::array();
};
