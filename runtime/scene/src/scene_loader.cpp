// JSON scene reading with path-precise errors (see prism/scene_loader.hpp).
#include "prism/io/json_nesting.hpp"
#include "prism/scene/scene_loader.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "prism/rain/rain_classes.hpp"
#include "prism/scene/stochastic.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/water_simulation.hpp"

namespace prism::scene {
namespace {

using nlohmann::json;

class Reader {
  public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& pointer, const std::string& expected) const {
        throw SceneError(file_ + ": " + (pointer.empty() ? "/" : pointer) + ": expected " + expected);
    }

    // A message that already starts with its JSON pointer ("/objects/0/...: expected ...").
    [[noreturn]] void failWith(const std::string& pointerAndMessage) const {
        throw SceneError(file_ + ": " + pointerAndMessage);
    }

    void object(const json& j, const std::string& at, std::initializer_list<const char*> allowed) const {
        if (!j.is_object()) fail(at, "an object");
        const std::set<std::string> keys(allowed.begin(), allowed.end());
        for (const auto& [key, value] : j.items()) {
            if (keys.count(key)) continue;
            std::string list;
            for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
            fail(at + "/" + key, "no such key here; known keys: " + list);
        }
    }

    // Scenes store their numbers as float: by default a number must fit one (4e94 would
    // become infinity, found by fuzz.scene_json).
    double number(const json& j, const std::string& at, double min = -std::numeric_limits<float>::max(),
                  double max = std::numeric_limits<float>::max()) const {
        if (!j.is_number()) fail(at, "a number");
        const double v = j.get<double>();
        if (!std::isfinite(v) || v < min || v > max) {
            std::ostringstream range;
            range << "a number in [" << min << ", " << max << "]";
            fail(at, range.str());
        }
        return v;
    }

    unsigned whole(const json& j, const std::string& at, unsigned min, unsigned max) const {
        if (!j.is_number_integer() || j.get<long long>() < min || j.get<long long>() > max)
            fail(at, "a whole number from " + std::to_string(min) + " to " + std::to_string(max));
        return static_cast<unsigned>(j.get<long long>());
    }

    glm::vec3 vec3(const json& j, const std::string& at) const {
        if (!j.is_array() || j.size() != 3) fail(at, "3 numbers");
        glm::vec3 v;
        for (int i = 0; i < 3; ++i) {
            if (!j[static_cast<std::size_t>(i)].is_number()) fail(at, "3 numbers");
            v[i] = static_cast<float>(number(j[static_cast<std::size_t>(i)], at + "/" + std::to_string(i)));
        }
        return v;
    }

    glm::vec3 color(const json& j, const std::string& at) const {
        glm::vec3 c = vec3(j, at);
        for (int i = 0; i < 3; ++i)
            if (c[i] < 0.0f) fail(at + "/" + std::to_string(i), "a colour component >= 0");
        return c;
    }

    std::string string(const json& j, const std::string& at) const {
        if (!j.is_string()) fail(at, "a string");
        return j.get<std::string>();
    }

  private:
    std::string file_;
};

view::Camera readCamera(const Reader& r, const json& j) {
    r.object(j, "/camera", {"eye", "target", "up", "fovY", "near", "far"});
    view::Camera c;
    if (j.contains("eye")) c.eye = r.vec3(j["eye"], "/camera/eye");
    if (j.contains("target")) c.target = r.vec3(j["target"], "/camera/target");
    if (j.contains("up")) c.up = r.vec3(j["up"], "/camera/up");
    if (j.contains("fovY")) c.fovYDegrees = static_cast<float>(r.number(j["fovY"], "/camera/fovY", 1e-3, 179.0));
    if (j.contains("near")) c.nearPlane = static_cast<float>(r.number(j["near"], "/camera/near", 1e-9));
    if (j.contains("far")) c.farPlane = static_cast<float>(r.number(j["far"], "/camera/far", 1e-9));
    if (!(c.farPlane > c.nearPlane)) r.fail("/camera/far", "a value greater than /camera/near");
    const glm::vec3 d = c.target - c.eye;
    if (glm::dot(d, d) < 1e-20f) r.fail("/camera/target", "a point other than /camera/eye");
    return c;
}

void readLights(const Reader& r, const json& j, view::Lights& lights) {
    if (!j.is_array()) r.fail("/lights", "an array of lights");
    lights.ambient = glm::vec3(0.0f);
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string at = "/lights/" + std::to_string(i);
        const json& l = j[i];
        if (!l.is_object() || !l.contains("type")) r.fail(at, "an object with \"type\": ambient, directional or point");
        const std::string type = r.string(l["type"], at + "/type");
        if (type == "ambient") {
            r.object(l, at, {"type", "color"});
            lights.ambient += r.color(l.value("color", json::array({0.1, 0.1, 0.1})), at + "/color");
        } else if (type == "directional") {
            r.object(l, at, {"type", "direction", "color"});
            if (!l.contains("direction")) r.fail(at + "/direction", "3 numbers");
            view::DirectionalLight d{r.vec3(l["direction"], at + "/direction"), glm::vec3(1.0f)};
            if (glm::dot(d.direction, d.direction) < 1e-20f) r.fail(at + "/direction", "a non-zero direction");
            if (l.contains("color")) d.color = r.color(l["color"], at + "/color");
            lights.directional.push_back(d);
        } else if (type == "point") {
            r.object(l, at, {"type", "position", "color"});
            if (!l.contains("position")) r.fail(at + "/position", "3 numbers");
            view::PointLight p{r.vec3(l["position"], at + "/position"), glm::vec3(1.0f)};
            if (l.contains("color")) p.color = r.color(l["color"], at + "/color");
            lights.points.push_back(p);
        } else {
            r.fail(at + "/type", "ambient, directional or point");
        }
    }
}

glm::mat4 readTransform(const Reader& r, const json& j, const std::string& at) {
    r.object(j, at, {"translate", "rotateDegrees", "scale"});
    glm::mat4 m(1.0f);
    if (j.contains("translate")) m = glm::translate(m, r.vec3(j["translate"], at + "/translate"));
    if (j.contains("rotateDegrees")) {
        const glm::vec3 deg = r.vec3(j["rotateDegrees"], at + "/rotateDegrees");
        m = glm::rotate(m, glm::radians(deg.y), glm::vec3(0, 1, 0));
        m = glm::rotate(m, glm::radians(deg.x), glm::vec3(1, 0, 0));
        m = glm::rotate(m, glm::radians(deg.z), glm::vec3(0, 0, 1));
    }
    if (j.contains("scale")) {
        const json& s = j["scale"];
        m = glm::scale(
            m, s.is_number() ? glm::vec3(static_cast<float>(r.number(s, at + "/scale"))) : r.vec3(s, at + "/scale"));
    }
    return m;
}

SceneObject readObject(const Reader& r, const json& j, const std::string& at, const std::string& baseDir) {
    r.object(j, at, {"mesh", "subdivision", "transform", "material"});
    SceneObject o;
    if (j.contains("mesh")) o.mesh = r.string(j["mesh"], at + "/mesh");
    if (j.contains("subdivision")) o.subdivision = r.whole(j["subdivision"], at + "/subdivision", 0, 7);
    if (j.contains("transform")) o.world = readTransform(r, j["transform"], at + "/transform");
    if (j.contains("material")) {
        const std::string m = at + "/material";
        const json& mj = j["material"];
        r.object(mj, m, {"shader", "color", "shininess", "specular", "variant", "diffraction"});
        if (mj.contains("shader")) o.shader = r.string(mj["shader"], m + "/shader");
        if (o.shader == "diffraction") {
            if (!mj.contains("diffraction"))
                r.fail(m + "/diffraction",
                       "the diffraction parameters (an object with a height_field; docs/scenes.md)");
            o.diffractionPointer = m + "/diffraction";
            try {
                o.diffraction = diffraction::parseDiffractionMaterial(mj["diffraction"], o.diffractionPointer, baseDir);
            } catch (const diffraction::MaterialError& e) {
                r.failWith(e.what());
            }
        } else if (mj.contains("diffraction")) {
            r.fail(m + "/diffraction", "no diffraction parameters unless \"shader\" is \"diffraction\"");
        }
        if (mj.contains("color")) o.material.color = glm::vec4(r.color(mj["color"], m + "/color"), 1.0f);
        if (mj.contains("shininess"))
            o.material.shininess = static_cast<float>(r.number(mj["shininess"], m + "/shininess", 0.0));
        if (mj.contains("specular"))
            o.material.specular = static_cast<float>(r.number(mj["specular"], m + "/specular", 0.0));
        if (mj.contains("variant")) {
            if (!mj["variant"].is_object()) r.fail(m + "/variant", "an object of NAME: \"VALUE\" pairs");
            for (const auto& [name, value] : mj["variant"].items())
                o.variantOverrides.emplace_back(
                    name, value.is_string() ? value.get<std::string>()
                                            : std::to_string(r.whole(value, m + "/variant/" + name, 0, 1u << 20)));
        }
    }
    return o;
}

RainSettings readRain(const Reader& r, const json& j) {
    r.object(j, "/rain", {"intensity", "rateMmPerHour", "wind", "seed", "radius", "height", "budget"});
    RainSettings s;
    if (j.contains("intensity")) {
        const std::string name = r.string(j["intensity"], "/rain/intensity");
        const auto cls = rain::parseRainClass(name);
        if (!cls) r.fail("/rain/intensity", "one of " + rain::rainClassNames());
        s.intensityClass = *cls;
    }
    if (j.contains("rateMmPerHour"))
        s.rateMillimetresPerHour = r.number(j["rateMmPerHour"], "/rain/rateMmPerHour", 0.0, water::kMaxRainMmPerHour);
    if (j.contains("wind")) s.wind = r.vec3(j["wind"], "/rain/wind");
    if (j.contains("seed")) s.seed = r.whole(j["seed"], "/rain/seed", 0, 0xffffffffu);
    if (j.contains("radius")) s.cylinderRadius = static_cast<float>(r.number(j["radius"], "/rain/radius", 0.1, 1e4));
    if (j.contains("height")) s.cylinderHeight = static_cast<float>(r.number(j["height"], "/rain/height", 0.1, 1e4));
    if (j.contains("budget")) s.particleBudget = r.whole(j["budget"], "/rain/budget", 0, 1u << 24);
    return s;
}

WaterSettings readWater(const Reader& r, const json& j) {
    r.object(j, "/water",
             {"grid", "cellSize", "rainMmPerHour", "seconds", "soilMmPerHour", "seed", "relief", "cloudCover"});
    WaterSettings s;
    if (j.contains("grid")) s.gridSize = r.whole(j["grid"], "/water/grid", 1, 2048);
    if (j.contains("cellSize")) s.cellSize = static_cast<float>(r.number(j["cellSize"], "/water/cellSize", 1e-3, 1e3));
    if (j.contains("rainMmPerHour"))
        s.rainRateMillimetresPerHour =
            r.number(j["rainMmPerHour"], "/water/rainMmPerHour", 0.0, water::kMaxRainMmPerHour);
    if (j.contains("seconds")) s.seconds = r.number(j["seconds"], "/water/seconds", 0.0, 86400.0);
    if (j.contains("soilMmPerHour"))
        s.soilMillimetresPerHour = r.number(j["soilMmPerHour"], "/water/soilMmPerHour", 0.0, 1e6);
    if (j.contains("seed")) s.seed = r.whole(j["seed"], "/water/seed", 0, 0xffffffffu);
    if (j.contains("relief")) s.relief = static_cast<float>(r.number(j["relief"], "/water/relief", 0.0, 1e4));
    if (j.contains("cloudCover"))
        s.cloudCover = static_cast<float>(r.number(j["cloudCover"], "/water/cloudCover", 0.0, 1.0));
    try {  // the simulated time must fit the substep cap at this cell size
        water::planSubsteps(s.seconds, water::WaterParams{}, s.cellSize);
    } catch (const std::invalid_argument& e) {
        r.fail("/water/seconds", std::string("a time the water step can take in one call: ") + e.what());
    }
    return s;
}

bluenoise::SamplerKind samplerNamed(const Reader& r, const json& j, const std::string& at) {
    const std::string name = r.string(j, at);
    if (const auto kind = parseStochasticSampler(name)) return *kind;
    r.fail(at, "white, bluenoise or sorted, not \"" + name + "\"");
}

StochasticSettings readStochastic(const Reader& r, const json& j) {
    r.object(j, "/stochastic",
             {"effect", "sampler", "spp", "frame", "frames", "light", "spheres", "extent", "mask", "block",
              "retargetEpochs"});
    StochasticSettings s;
    if (j.contains("effect") && r.string(j["effect"], "/stochastic/effect") != "softShadows")
        r.fail("/stochastic/effect", "\"softShadows\" (the only effect so far)");
    if (j.contains("sampler")) s.sampler = samplerNamed(r, j["sampler"], "/stochastic/sampler");
    if (j.contains("spp")) s.spp = static_cast<int>(r.whole(j["spp"], "/stochastic/spp", 1, kMaxStochasticSpp));
    if (j.contains("frame"))
        s.frame = static_cast<int>(r.whole(j["frame"], "/stochastic/frame", 0, kMaxStochasticFrame));
    if (j.contains("frames"))
        s.frames = static_cast<int>(r.whole(j["frames"], "/stochastic/frames", 1, kMaxStochasticFrames));
    if (s.frame > 0 && s.frames > 1) r.fail("/stochastic/frames", "either frame or frames > 1, not both");
    if (j.contains("extent")) s.light.extent = r.number(j["extent"], "/stochastic/extent", 1e-3, 1e4);
    if (j.contains("light")) {
        const json& l = j["light"];
        r.object(l, "/stochastic/light", {"height", "halfLength", "halfWidth", "radiance"});
        if (l.contains("height")) s.light.lightHeight = r.number(l["height"], "/stochastic/light/height", 1e-3, 1e4);
        if (l.contains("halfLength"))
            s.light.lightHalfLength = r.number(l["halfLength"], "/stochastic/light/halfLength", 1e-4, 1e4);
        if (l.contains("halfWidth"))
            s.light.lightHalfWidth = r.number(l["halfWidth"], "/stochastic/light/halfWidth", 1e-4, 1e4);
        if (l.contains("radiance")) s.light.radiance = r.number(l["radiance"], "/stochastic/light/radiance", 0.0, 1e6);
    }
    if (j.contains("spheres")) {
        if (!j["spheres"].is_array()) r.fail("/stochastic/spheres", "an array of spheres");
        s.light.spheres.clear();
        for (std::size_t i = 0; i < j["spheres"].size(); ++i) {
            const std::string at = "/stochastic/spheres/" + std::to_string(i);
            const json& o = j["spheres"][i];
            r.object(o, at, {"center", "radius"});
            if (!o.contains("center")) r.fail(at + "/center", "3 numbers (the sphere's centre)");
            const json& c = o["center"];
            (void)r.vec3(c, at + "/center");  // 3 finite numbers; read again in double precision
            double centre[3];
            for (std::size_t k = 0; k < 3; ++k) centre[k] = c[k].get<double>();
            if (!o.contains("radius")) r.fail(at + "/radius", "a number (the sphere's radius)");
            const double radius = r.number(o["radius"], at + "/radius", 1e-4, 1e4);
            if (centre[2] <= 0.0 || centre[2] >= s.light.lightHeight)
                r.fail(at + "/center/2", "a height between the ground (0) and the light");
            s.light.spheres.push_back({centre[0], centre[1], centre[2], radius});
        }
    }
    if (j.contains("mask")) {
        const json& m = j["mask"];
        r.object(m, "/stochastic/mask", {"size", "seed"});
        if (m.contains("size")) s.maskSize = static_cast<int>(r.whole(m["size"], "/stochastic/mask/size", 1, 256));
        if (m.contains("seed")) s.maskSeed = r.whole(m["seed"], "/stochastic/mask/seed", 0, 0xffffffffu);
    }
    if (j.contains("block")) {
        s.block = static_cast<int>(r.whole(j["block"], "/stochastic/block", 4, 16));
        if (s.block != 4 && s.block != 8 && s.block != 16) r.fail("/stochastic/block", "4, 8 or 16");
    }
    if (j.contains("retargetEpochs"))
        s.retargetEpochs = static_cast<int>(r.whole(j["retargetEpochs"], "/stochastic/retargetEpochs", 0, 256));
    return s;
}

// Scenes nest 4 levels; deeper JSON is refused before parsing (docs/reliability.md).
constexpr int kMaxJsonDepth = 64;

}  // namespace

Scene parseScene(const std::string& text, const std::string& fileName) {
    if (const auto deep = io::firstTooDeep(text, kMaxJsonDepth)) {
        auto [line, col] = io::lineColumnAt(text, *deep);
        throw SceneError(fileName + ":" + std::to_string(line) + ":" + std::to_string(col) +
                         ": JSON nested more than " + std::to_string(kMaxJsonDepth) +
                         " levels deep (the limit); a scene needs 4");
    }
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        auto [line, col] = io::lineColumnAt(text, e.byte > 0 ? e.byte - 1 : 0);
        std::string what = e.what();
        auto pos = what.find("syntax error");
        throw SceneError(fileName + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " +
                         (pos == std::string::npos ? what : what.substr(pos)));
    } catch (const json::exception& e) {  // e.g. out_of_range 406: a number too large for a double
        std::string what = e.what();
        auto pos = what.find("] ");
        throw SceneError(fileName + ": " + (pos == std::string::npos ? what : what.substr(pos + 2)));
    }
    Reader r(fileName);
    // Files a scene names (a diffraction PNG height field) are relative to the scene file.
    const std::string baseDir = std::filesystem::path(fileName).parent_path().string();
    r.object(j, "", {"camera", "image", "lights", "fog", "objects", "rain", "water", "stochastic", "comment"});
    Scene s;
    s.file = fileName;
    if (j.contains("camera")) s.camera = readCamera(r, j["camera"]);
    if (j.contains("image")) {
        const json& im = j["image"];
        r.object(im, "/image", {"width", "height", "background"});
        if (im.contains("width")) s.width = static_cast<int>(r.whole(im["width"], "/image/width", 1, 16384));
        if (im.contains("height")) s.height = static_cast<int>(r.whole(im["height"], "/image/height", 1, 16384));
        if (im.contains("background")) s.background = glm::vec4(r.color(im["background"], "/image/background"), 1.0f);
    }
    if (j.contains("lights")) readLights(r, j["lights"], s.lights);
    if (j.contains("fog")) {
        r.object(j["fog"], "/fog", {"color", "density", "billboards", "ground"});
        if (j["fog"].contains("billboards"))
            s.fogBillboards = static_cast<float>(r.number(j["fog"]["billboards"], "/fog/billboards", 0.0, 1.0));
        if (j["fog"].contains("ground"))
            s.fogGroundHeight = static_cast<float>(r.number(j["fog"]["ground"], "/fog/ground", -1e4, 1e4));
        view::Fog f;
        if (j["fog"].contains("color")) f.color = r.color(j["fog"]["color"], "/fog/color");
        if (j["fog"].contains("density"))
            f.density = static_cast<float>(r.number(j["fog"]["density"], "/fog/density", 0.0, 1e6));
        s.fog = f;
    }
    if (j.contains("objects")) {
        if (!j["objects"].is_array()) r.fail("/objects", "an array of objects");
        for (std::size_t i = 0; i < j["objects"].size(); ++i)
            s.objects.push_back(readObject(r, j["objects"][i], "/objects/" + std::to_string(i), baseDir));
    }
    if (j.contains("rain")) s.rain = readRain(r, j["rain"]);
    if (j.contains("water")) s.water = readWater(r, j["water"]);
    if (j.contains("stochastic")) s.stochastic = readStochastic(r, j["stochastic"]);
    return s;
}

Scene loadScene(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open the scene file; check the path");
    std::ostringstream ss;
    ss << in.rdbuf();
    return parseScene(ss.str(), path);
}

}  // namespace prism::scene
