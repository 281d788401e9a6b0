// State changes shared by keys, panels and scripts (viewer_actions.hpp).
#include "viewer_actions.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "prism/rain/rain_classes.hpp"
#include "prism/rain/rain_params.hpp"
#include "prism/scene/stochastic.hpp"
#include "prism/water/water_simulation.hpp"
#include "prism/scene/scene_loader.hpp"

namespace prism::viewer {

namespace {
double number(const std::string& name, const std::string& value) {
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != value.size() || value.empty())
        throw std::invalid_argument(name + " wants a number, got '" + value + "'");
    return v;
}
bool flag(const std::string& name, const std::string& value) {
    if (value == "1" || value == "on" || value == "true") return true;
    if (value == "0" || value == "off" || value == "false") return false;
    throw std::invalid_argument(name + " wants 0 or 1, got '" + value + "'");
}
scene::Scene& openSceneOf(ViewerState& state, const std::string& name) {
    if (!state.scene.open) throw std::invalid_argument(name + " needs an open scene (scene FILE first)");
    state.scene.dirty = true;
    return state.scene.scene;
}
}  // namespace

void selectShader(ViewerState& state, const catalog::Catalog& catalog, const std::string& shader) {
    if (!catalog::findShader(catalog, shader)) throw std::invalid_argument("unknown shader '" + shader + "'");
    state.catalogue.shader = shader;
    state.meshDirty = true;  // flat needs other normals
}

void nextShader(ViewerState& state, const catalog::Catalog& catalog) {
    std::size_t i = 0;
    while (i < catalog.shaders.size() && catalog.shaders[i].name != state.catalogue.shader) ++i;
    selectShader(state, catalog, std::string(catalog.shaders[(i + 1) % catalog.shaders.size()].name));
}

void nextMesh(ViewerState& state) {
    std::size_t i = 0;
    while (i < std::size(kMeshes) && state.catalogue.mesh != kMeshes[i]) ++i;
    state.catalogue.mesh = kMeshes[(i + 1) % std::size(kMeshes)];
    state.meshDirty = true;
}

void pickAxis(ViewerState& state, const std::string& axis, const std::string& value) {
    for (auto& [n, v] : state.catalogue.picks)
        if (n == axis) {
            v = value;
            return;
        }
    state.catalogue.picks.emplace_back(axis, value);
}

void openScene(ViewerState& state, const std::string& path) {
    state.scene.scene = scene::loadScene(path);
    state.scene.file = path;
    state.scene.open = true;
    state.scene.dirty = true;
    state.scene.waterRunning = false;
    if (state.scene.scene.water) state.scene.waterStartSeconds = state.scene.scene.water->seconds;
}

void closeScene(ViewerState& state) {
    state.scene.open = false;
    state.scene.file.clear();
}

namespace {

[[noreturn]] void unknownParameter(const std::string& name) {
    throw std::invalid_argument("unknown parameter '" + name + "'");
}

// The catalogue view's lights, or the open scene's.
void setDirectionalLights(ViewerState& state, const std::string& name, const std::string& value) {
    if (name != "lights.directional") unknownParameter(name);
    const double count = number(name, value);
    if (count < 0 || count > 8) throw std::invalid_argument("lights.directional wants 0..8");
    const auto n = static_cast<std::size_t>(count);
    auto& directional =
        state.scene.open ? openSceneOf(state, name).lights.directional : state.catalogue.lights.directional;
    const auto defaults = render::defaultLights().directional;
    while (directional.size() > n) directional.pop_back();
    while (directional.size() < n)
        directional.push_back(directional.size() < defaults.size() ? defaults[directional.size()]
                                                                   : view::DirectionalLight{});
}

// The catalogue view's material, or the open scene's first object's.
void setMaterial(ViewerState& state, const std::string& name, const std::string& value) {
    view::Material* m = &state.catalogue.material;
    if (state.scene.open) {
        auto& objects = openSceneOf(state, name).objects;
        if (objects.empty()) throw std::invalid_argument(name + " needs a scene object");
        m = &objects.front().material;
    }
    if (name == "material.shininess")
        m->shininess = static_cast<float>(number(name, value));
    else if (name == "material.specular")
        m->specular = static_cast<float>(number(name, value));
    else
        unknownParameter(name);
}

// Distance fog of the catalogue view and of the open scene, and the scene's fog billboards.
void setFog(ViewerState& state, const std::string& name, const std::string& value) {
    if (name == "fog.billboards") {
        auto& s = openSceneOf(state, name);
        const double o = number(name, value);
        if (o <= 0)
            s.fogBillboards.reset();
        else
            s.fogBillboards = static_cast<float>(std::min(o, 1.0));
        return;
    }
    if (name != "fog.density") unknownParameter(name);
    auto& c = state.catalogue;
    const double d = number(name, value);
    if (d <= 0) {
        c.fog.reset();
    } else {
        if (!c.fog) c.fog = view::Fog{};
        c.fog->density = static_cast<float>(d);
    }
    if (state.scene.open) {
        auto& s = state.scene.scene;
        if (d <= 0)
            s.fog.reset();
        else
            s.fog = c.fog;
        state.scene.dirty = true;
    }
}

// Names are parsed here, once: the scene holds the rain class and the technique as enums.
void setRain(ViewerState& state, const std::string& name, const std::string& value) {
    auto& s = openSceneOf(state, name);
    if (name == "rain.enabled") {
        if (!flag(name, value))
            s.rain.reset();
        else if (!s.rain)
            s.rain = scene::RainSettings{};
        return;
    }
    if (name == "rain.intensity") {
        const auto cls = rain::parseRainClass(value);
        if (!cls) throw std::invalid_argument("unknown rain intensity class '" + value + "'");
        if (!s.rain) s.rain = scene::RainSettings{};
        s.rain->intensityClass = *cls;
        s.rain->rateMillimetresPerHour.reset();
        return;
    }
    if (!s.rain) throw std::invalid_argument(name + " needs rain (set rain.enabled 1)");
    if (name == "rain.wind.x" || name == "rain.wind.z") {
        (name == "rain.wind.x" ? s.rain->wind.x : s.rain->wind.z) = static_cast<float>(number(name, value));
    } else if (name == "rain.lodRings") {
        const double n = number(name, value);
        if (n < 1 || n > 16) throw std::invalid_argument("rain.lodRings wants 1..16");
        s.rain->lodRings = static_cast<int>(n);
    } else if (name == "rain.technique") {
        const auto technique = rain::parseTechnique(value);
        if (!technique) throw std::invalid_argument("rain.technique wants gs-quads, instanced-quads or point-sprites");
        s.rain->technique = *technique;
    } else {
        unknownParameter(name);
    }
}

void setWater(ViewerState& state, const std::string& name, const std::string& value) {
    auto& s = openSceneOf(state, name);
    if (name == "water.running") {
        state.scene.waterRunning = flag(name, value);
        return;
    }
    if (!s.water) throw std::invalid_argument(name + " needs a scene with water");
    if (name == "water.backend") {
        const auto backend = water::parseSimulationBackend(value);
        if (!backend) throw std::invalid_argument("water.backend wants fastest, cpu or gpu");
        s.water->backend = *backend;
    } else if (name == "water.seconds") {
        s.water->seconds = number(name, value);
    } else {
        unknownParameter(name);
    }
}

void setBlueNoise(ViewerState& state, const std::string& name, const std::string& value) {
    auto& s = openSceneOf(state, name);
    if (!s.stochastic) s.stochastic = scene::StochasticSettings{};
    auto& st = *s.stochastic;
    if (name == "bluenoise.spp") {
        st.spp = std::max(1, static_cast<int>(number(name, value)));
    } else if (name == "bluenoise.frames") {
        st.frames = std::max(1, static_cast<int>(number(name, value)));
    } else if (name == "bluenoise.sampler") {
        const auto sampler = scene::parseStochasticSampler(value);
        if (!sampler) throw std::invalid_argument("bluenoise.sampler wants white, bluenoise or sorted");
        st.sampler = *sampler;
    } else {
        unknownParameter(name);
    }
}

// The catalogue view's own parameters: mesh, subdivision, reference.
void setCatalogueView(ViewerState& state, const std::string& name, const std::string& value) {
    auto& c = state.catalogue;
    if (name == "mesh") {
        c.mesh = value;
        state.meshDirty = true;
    } else if (name == "subdivision") {
        const double n = number(name, value);
        if (n < 0 || n > 6) throw std::invalid_argument("subdivision wants 0..6");
        c.subdivision = static_cast<unsigned>(n);
        state.meshDirty = true;
    } else if (name == "reference") {
        state.readouts.referenceOn = flag(name, value);
    } else {
        unknownParameter(name);
    }
}

}  // namespace

// Each group of names ("rain.*", "water.*", ...) has its setter; the rest are the catalogue view's.
void setParameter(ViewerState& state, const std::string& name, const std::string& value) {
    using Setter = void (*)(ViewerState&, const std::string&, const std::string&);
    static const std::pair<const char*, Setter> groups[] = {
        {"lights.", setDirectionalLights},
        {"material.", setMaterial},
        {"fog.", setFog},
        {"rain.", setRain},
        {"water.", setWater},
        {"bluenoise.", setBlueNoise},
    };
    for (const auto& [prefix, set] : groups)
        if (name.rfind(prefix, 0) == 0) return set(state, name, value);
    setCatalogueView(state, name, value);
}

}  // namespace prism::viewer
