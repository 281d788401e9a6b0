// CPU soft shadows under a rectangular light with the three samplers, and the reference.
#include "prism/bluenoise/soft_shadows.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "prism/bluenoise/sorting.hpp"

namespace prism::bluenoise {
namespace {

struct Point {
    double x, y;
};

Point groundPoint(const SoftShadowScene& s, int x, int y, int w, int h) {
    return {(x + 0.5) / w * 2.0 * s.extent - s.extent, s.extent - (y + 0.5) / h * 2.0 * s.extent};
}

// Does the segment from ground point p to light point q hit a sphere?
bool occluded(const SoftShadowScene& s, Point p, double qx, double qy) {
    const double dx = qx - p.x, dy = qy - p.y, dz = s.lightHeight;
    for (const Sphere& sp : s.spheres) {
        const double ox = p.x - sp.x, oy = p.y - sp.y, oz = -sp.z;
        const double a = dx * dx + dy * dy + dz * dz;
        const double b = 2.0 * (ox * dx + oy * dy + oz * dz);
        const double c = ox * ox + oy * oy + oz * oz - sp.radius * sp.radius;
        const double disc = b * b - 4.0 * a * c;
        if (disc < 0.0) continue;
        const double root = std::sqrt(disc);
        const double t0 = (-b - root) / (2.0 * a), t1 = (-b + root) / (2.0 * a);
        if ((t0 > 0.0 && t0 < 1.0) || (t1 > 0.0 && t1 < 1.0)) return true;
    }
    return false;
}

// Irradiance estimate of one light sample (u, v) in [0, 1)^2, before normalisation.
double unnormalised(const SoftShadowScene& s, Point p, double u, double v) {
    const double qx = (2.0 * u - 1.0) * s.lightHalfLength, qy = (2.0 * v - 1.0) * s.lightHalfWidth;
    const double dx = qx - p.x, dy = qy - p.y, h = s.lightHeight;
    const double r2 = dx * dx + dy * dy + h * h;
    const double cosine2 = h * h / r2;  // cos at the ground times cos at the light
    const double area = 4.0 * s.lightHalfLength * s.lightHalfWidth;
    return occluded(s, p, qx, qy) ? 0.0 : area * cosine2 / r2;
}

double normaliser(const SoftShadowScene& s) {
    // Unoccluded irradiance right below the light's centre, by a 64x64 midpoint rule.
    SoftShadowScene open = s;
    open.spheres.clear();
    double sum = 0.0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) sum += unnormalised(open, {0.0, 0.0}, (i + 0.5) / 64.0, (j + 0.5) / 64.0);
    return sum / 4096.0;
}

double sampleValue(const SoftShadowScene& s, double scale, Point p, double u, double v) {
    return scale * unnormalised(s, p, u, v);
}

void validate(const RenderOptions& o) {
    if (o.width < 1 || o.height < 1 || o.width > 4096 || o.height > 4096)
        throw std::invalid_argument("soft shadows: image size must be 1..4096 in each direction");
    if (o.spp < 1 || o.spp > 65536)
        throw std::invalid_argument("soft shadows: spp must be 1..65536, got " + std::to_string(o.spp));
    if (o.frames < 1 || o.frames > 100000) throw std::invalid_argument("soft shadows: frames must be 1..100000");
    if (o.frame < 0) throw std::invalid_argument("soft shadows: frame must be >= 0");
    if (o.block < 1) throw std::invalid_argument("soft shadows: block must be >= 1");
}

std::vector<double> renderFrame(const SoftShadowScene& s, double scale, const StochasticSetup& setup,
                                const RenderOptions& o, std::uint32_t frame) {
    std::vector<double> out(static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height));
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const Point p = groundPoint(s, x, y, o.width, o.height);
            double sum = 0.0;
            for (int i = 0; i < o.spp; ++i) {
                const std::uint32_t index = frame * static_cast<std::uint32_t>(o.spp) + static_cast<std::uint32_t>(i);
                const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
                sum += sampleValue(s, scale, p, toUnitFloat(sample(o.sampler, setup.tables, ux, uy, index, 0)),
                                   toUnitFloat(sample(o.sampler, setup.tables, ux, uy, index, 1)));
            }
            out[static_cast<std::size_t>(y * o.width + x)] = sum / o.spp;
        }
    return out;
}

// The mask's values on screen for frame t: shifted by t R2 frame steps.
std::vector<std::uint32_t> sortTarget(const StochasticSetup& setup, int width, int height, int t) {
    std::vector<std::uint32_t> target(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const int mw = setup.tables.maskWidth, mh = setup.tables.maskHeight;
    const long long sx = static_cast<long long>(t) * setup.shiftX, sy = static_cast<long long>(t) * setup.shiftY;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            target[static_cast<std::size_t>(y * width + x)] =
                setup.tables.mask[static_cast<std::size_t>(((y + sy) % mh) * mw + (x + sx) % mw)];
    return target;
}

std::vector<float> asFloats(const std::vector<double>& v) {
    return {v.begin(), v.end()};
}

}  // namespace

SoftShadowScene SoftShadowScene::classic() {
    SoftShadowScene s;
    s.spheres = {{-0.55, 0.35, 0.55, 0.3}, {0.5, -0.25, 0.9, 0.22}, {0.2, 0.75, 0.3, 0.18}};
    return s;
}
SoftShadowScene SoftShadowScene::black() {
    SoftShadowScene s = classic();
    s.radiance = 0.0;
    return s;
}
SoftShadowScene SoftShadowScene::white() {
    SoftShadowScene s;
    s.radiance = 1000.0;
    return s;
}

StochasticSetup StochasticSetup::make(const Mask& mask) {
    StochasticSetup setup;
    setup.mask = mask;
    setup.tables = SamplerTables::fromMask(mask);
    frameShift(mask.width, mask.height, setup.shiftX, setup.shiftY);
    return setup;
}

SoftShadowUniforms softShadowUniforms(const SoftShadowScene& scene, const SamplerTables& tables,
                                      const RenderOptions& options) {
    if (scene.spheres.size() > kGpuSpheres)
        throw std::invalid_argument("prism::bluenoise: the GPU soft shadows draw at most 3 spheres, the scene has " +
                                    std::to_string(scene.spheres.size()));
    SoftShadowUniforms u;
    u.stackDepth = tables.stackDepth;
    u.sampler = static_cast<int>(options.sampler);
    u.spp = options.spp;
    u.imageSize = {static_cast<float>(options.width), static_cast<float>(options.height)};
    u.extent = static_cast<float>(scene.extent);
    u.light = {static_cast<float>(scene.lightHeight), static_cast<float>(scene.lightHalfLength),
               static_cast<float>(scene.lightHalfWidth), static_cast<float>(irradianceScale(scene))};
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& sp = scene.spheres[i];
        u.spheres[i] = {static_cast<float>(sp.x), static_cast<float>(sp.y), static_cast<float>(sp.z),
                        static_cast<float>(sp.radius)};
    }
    return u;
}

double irradianceScale(const SoftShadowScene& scene) {
    const double norm = normaliser(scene);
    return norm > 0.0 ? scene.radiance / norm : 0.0;
}

RealImage renderSoftShadows(const SoftShadowScene& scene, StochasticSetup& setup, const RenderOptions& o) {
    validate(o);
    const double scale = irradianceScale(scene);
    return runSoftShadowPipeline(setup, o, [&](const SamplerTables&, std::uint32_t frame) {
        return renderFrame(scene, scale, setup, o, frame);
    });
}

RealImage runSoftShadowPipeline(StochasticSetup& setup, const RenderOptions& o, const FrameRenderer& render) {
    validate(o);
    RealImage image{o.width, o.height,
                    std::vector<double>(static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height), 0.0)};
    const int first = o.frames > 1 ? 0 : o.frame;
    const int last = o.frames > 1 ? o.frames - 1 : o.frame;
    auto frameValues = [&](int t) {
        std::vector<double> f = render(setup.tables, static_cast<std::uint32_t>(t));
        if (f.size() != image.values.size())
            throw std::runtime_error("soft shadows: a frame renderer returned " + std::to_string(f.size()) +
                                     " values for a " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                                     " image");
        return f;
    };
    if (o.sampler != SamplerKind::Sorted) {
        for (int t = first; t <= last; ++t) {
            const std::vector<double> f = frameValues(t);
            for (std::size_t i = 0; i < f.size(); ++i) image.values[i] += f[i];
        }
    } else {
        setup.tables.seedWidth = o.width;
        setup.tables.seedHeight = o.height;
        setup.tables.seeds = initialSeeds(o.width, o.height, o.seed);
        for (int t = 0; t <= last; ++t) {
            std::vector<double> f = frameValues(t);
            if (o.aPosteriori) {
                sortSeedsInBlocks(asFloats(f), sortTarget(setup, o.width, o.height, t), o.width, o.height, o.block,
                                  setup.tables.seeds);
                f = frameValues(t);
            }
            if (t >= first)
                for (std::size_t i = 0; i < f.size(); ++i) image.values[i] += f[i];
            if (!o.aPosteriori && t < last) {
                sortSeedsInBlocks(asFloats(f), sortTarget(setup, o.width, o.height, t), o.width, o.height, o.block,
                                  setup.tables.seeds);
                if (!setup.retarget.source.empty())
                    applyRetarget(setup.retarget, t * setup.shiftX, t * setup.shiftY, o.width, o.height,
                                  setup.tables.seeds);
            }
        }
    }
    for (double& v : image.values) v /= (last - first + 1);
    return image;
}

Reference renderReference(const SoftShadowScene& scene, int width, int height, int samples) {
    if (width < 1 || height < 1 || samples < 1)
        throw std::invalid_argument("soft shadows reference: bad size or sample count");
    // Strata shaped like the light (long side / short side), so a shadow edge crossing
    // the light cuts few of them.
    const double aspect =
        scene.lightHalfWidth > 0.0 ? std::max(1.0, scene.lightHalfLength / scene.lightHalfWidth) : 1.0;
    const int columns = std::max(1, static_cast<int>(std::lround(std::sqrt(samples * aspect))));
    const int rows = std::max(1, (samples + columns - 1) / columns);
    const double norm = normaliser(scene);
    const double scale = norm > 0.0 ? scene.radiance / norm : 0.0;
    Reference r{
        {width, height, std::vector<double>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height))},
        std::vector<char>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Point p = groundPoint(scene, x, y, width, height);
            double sum = 0.0;
            bool lit = false, shadowed = false;
            for (int j = 0; j < rows; ++j)
                for (int i = 0; i < columns; ++i) {
                    const std::uint32_t k = static_cast<std::uint32_t>(j * columns + i);
                    const double ju =
                        toUnitFloat(whiteSample(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), k, 100));
                    const double jv =
                        toUnitFloat(whiteSample(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), k, 101));
                    const double v = sampleValue(scene, scale, p, (i + ju) / columns, (j + jv) / rows);
                    sum += v;
                    (v > 0.0 ? lit : shadowed) = true;
                }
            const std::size_t index = static_cast<std::size_t>(y * width + x);
            r.image.values[index] = sum / (rows * columns);
            r.touched[index] = lit && shadowed;  // the penumbrae
        }
    return r;
}

ErrorStats compareToReference(const RealImage& image, const Reference& reference) {
    if (image.width != reference.image.width || image.height != reference.image.height ||
        image.values.size() != reference.image.values.size())
        throw std::invalid_argument("compareToReference: the image and the reference differ in size");
    RealImage error{image.width, image.height, std::vector<double>(image.values.size())};
    for (std::size_t i = 0; i < error.values.size(); ++i) error.values[i] = image.values[i] - reference.image.values[i];
    const RealImage blurred = gaussianBlur(error, 1.0);
    ErrorStats stats;
    double sum = 0.0, sumBlurred = 0.0;
    for (std::size_t i = 0; i < error.values.size(); ++i) {
        if (!reference.touched[i]) continue;
        sum += error.values[i] * error.values[i];
        sumBlurred += blurred.values[i] * blurred.values[i];
        ++stats.pixels;
    }
    if (stats.pixels > 0) {
        stats.rms = std::sqrt(sum / stats.pixels);
        stats.blurredRms = std::sqrt(sumBlurred / stats.pixels);
    }
    stats.lowFrequencyRatio = lowFrequencyPowerRatio(error);
    return stats;
}

}  // namespace prism::bluenoise
