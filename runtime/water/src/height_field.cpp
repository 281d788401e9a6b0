// Height fields and permeability maps: PNG loading (own libpng path for 16-bit
// samples), procedural terrain and soil (see height_field.hpp).
#include "prism/water/height_field.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <string>

#include "prism/water/rain_rates.hpp"

namespace prism::water {
namespace {

std::string quoted(const std::filesystem::path& p) {
    return p.string();
}

struct FileCloser {
    void operator()(std::FILE* f) const {
        if (f) std::fclose(f);
    }
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
    throw HeightMapError(quoted(path) + ": " + why);
}

void pngErrorHandler(png_structp png, png_const_charp message) {
    auto* text = static_cast<std::string*>(png_get_error_ptr(png));
    if (text) *text = message ? message : "unknown libpng error";
    png_longjmp(png, 1);
}

constexpr png_alloc_size_t kMaxAncillaryChunkBytes = 1u << 20;

void pngWarningHandler(png_structp, png_const_charp) {}

std::uint32_t hash32(std::uint32_t v) {
    v ^= v >> 16;
    v *= 0x7feb352dU;
    v ^= v >> 15;
    v *= 0x846ca68bU;
    v ^= v >> 16;
    return v;
}

float smoothStep01(float t) {
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

void validate(const HeightField& f, const char* what) {
    const std::string w = what;
    if (f.width < 1 || f.height < 1)
        throw std::invalid_argument(w + ": the height field must have at least 1x1 cells, got " +
                                    std::to_string(f.width) + "x" + std::to_string(f.height));
    if (!(f.cellSize > 0.0f) || !std::isfinite(f.cellSize))
        throw std::invalid_argument(w + ": the cell size must be a finite number > 0");
    if (f.heights.size() != f.cellCount())
        throw std::invalid_argument(w + ": " + std::to_string(f.heights.size()) + " heights for " +
                                    std::to_string(f.cellCount()) + " cells");
    if (!(f.cellSize <= kMaxCellSize))
        throw std::invalid_argument(w + ": the cell size must be at most " + std::to_string(kMaxCellSize) + " m (got " +
                                    std::to_string(f.cellSize) + ")");
    for (float h : f.heights) {
        if (!std::isfinite(h)) throw std::invalid_argument(w + ": the height field holds a NaN or infinite height");
        if (std::abs(h) > kMaxHeight)
            throw std::invalid_argument(w + ": a height of " + std::to_string(h) +
                                        " m relative to the origin is beyond the limit of " +
                                        std::to_string(kMaxHeight) + " m; put the offset into HeightField::origin");
    }
    if (!std::isfinite(f.origin)) throw std::invalid_argument(w + ": the origin must be a finite height");
}

namespace {

// What a PNG read keeps across libpng's longjmp: everything that changes after setjmp lives
// on the heap behind a pointer fixed before it.
struct PngReadState {
    std::string libpngError;
    std::string problem;  // why the header is no map's (mapProblem)
    std::vector<unsigned char> pixels;
    std::vector<png_bytep> rows;
    png_uint_32 w = 0, h = 0;
    int depth = 0, channels = 0;
};

// Why a PNG with this header is no height or permeability map; empty when it is one.
std::string mapProblem(png_uint_32 w, png_uint_32 h, int colorType, int depth) {
    if (w > kMaxMapSide || h > kMaxMapSide || static_cast<std::uint64_t>(w) * h > kMaxMapCells)
        return std::to_string(w) + "x" + std::to_string(h) +
               " pixels is past the limit for height and permeability maps (" + std::to_string(kMaxMapSide) +
               " a side, " + std::to_string(kMaxMapCells) + " in all)";
    if (colorType == PNG_COLOR_TYPE_PALETTE)
        return "palette PNG; height and permeability maps must be greyscale (or RGB, red channel) with 8 or 16 bits";
    if (depth != 8 && depth != 16)
        return std::to_string(depth) + "-bit PNG; height and permeability maps must have 8 or 16 bits per sample";
    return {};
}

// The first channel of every pixel (grey, or red of RGB), 16-bit samples little-endian.
GreyImage firstChannel(const PngReadState& state) {
    const png_uint_32 w = state.w, h = state.h;
    GreyImage image;
    image.width = static_cast<int>(w);
    image.height = static_cast<int>(h);
    image.bitDepth = state.depth;
    image.values.resize(static_cast<std::size_t>(w) * h);
    const std::size_t bytesPerSample = state.depth == 16 ? 2 : 1;
    for (png_uint_32 y = 0; y < h; ++y)
        for (png_uint_32 x = 0; x < w; ++x) {
            const unsigned char* p =
                state.rows[y] + static_cast<std::size_t>(x) * static_cast<std::size_t>(state.channels) * bytesPerSample;
            image.values[static_cast<std::size_t>(y) * w + x] =
                state.depth == 16 ? static_cast<std::uint16_t>(p[0] | (p[1] << 8)) : p[0];
        }
    return image;
}

}  // namespace

// libpng reports errors by longjmp; they are rethrown as exceptions naming the file.
GreyImage readGreyPng(const std::filesystem::path& path) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) fail(path, std::filesystem::exists(path) ? "cannot be opened for reading" : "no such file");
    unsigned char signature[8] = {};
    if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) fail(path, "not a PNG file");
    const auto state = std::make_unique<PngReadState>();
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &state->libpngError, pngErrorHandler, pngWarningHandler);
    if (!png) fail(path, "libpng could not be initialised");
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        fail(path, "corrupt PNG: " + state->libpngError);
    }
    png_init_io(png, file.get());
    png_set_sig_bytes(png, 8);
    // Compressed ancillary chunks may claim any size: a 90-byte file's iCCP profile made
    // libpng allocate 1.6 GB (found by fuzzing). Maps need none of them: skip them unread.
    static const png_byte kSkipped[] = "iCCP\0zTXt\0iTXt\0tEXt\0sPLT\0eXIf\0pCAL\0sCAL";
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, kSkipped, 8);
    png_set_chunk_malloc_max(png, kMaxAncillaryChunkBytes);
    png_read_info(png, info);
    state->w = png_get_image_width(png, info);
    state->h = png_get_image_height(png, info);
    state->depth = png_get_bit_depth(png, info);
    state->problem = mapProblem(state->w, state->h, png_get_color_type(png, info), state->depth);
    if (!state->problem.empty()) {
        png_destroy_read_struct(&png, &info, nullptr);
        fail(path, state->problem);
    }
    if (state->depth == 16) png_set_swap(png);  // little-endian 16-bit samples in memory
    png_read_update_info(png, info);
    const std::size_t rowBytes = png_get_rowbytes(png, info);
    state->channels = png_get_channels(png, info);
    state->pixels.resize(rowBytes * state->h);
    state->rows.resize(state->h);
    for (png_uint_32 y = 0; y < state->h; ++y) state->rows[y] = state->pixels.data() + y * rowBytes;
    png_read_image(png, state->rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return firstChannel(*state);
}

void writeGreyPng(const std::filesystem::path& path, const GreyImage& image) {
    if (image.bitDepth != 8 && image.bitDepth != 16) fail(path, "writeGreyPng writes 8- or 16-bit images only");
    if (image.width < 1 || image.height < 1 ||
        image.values.size() != static_cast<std::size_t>(image.width) * image.height)
        fail(path, "writeGreyPng: the image size does not match its samples");
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
    if (!file) fail(path, "cannot be opened for writing");
    struct WriteState {
        std::string libpngError;
        std::vector<unsigned char> row;
    };
    const auto state = std::make_unique<WriteState>();
    state->row.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.bitDepth / 8));
    auto& row = state->row;
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &state->libpngError, pngErrorHandler, pngWarningHandler);
    if (!png) fail(path, "libpng could not be initialised");
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fail(path, "writing failed: " + state->libpngError);
    }
    png_init_io(png, file.get());
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height),
                 image.bitDepth, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint16_t v = image.values[static_cast<std::size_t>(y) * image.width + x];
            if (image.bitDepth == 16) {
                row[static_cast<std::size_t>(x) * 2] = static_cast<unsigned char>(v >> 8);  // PNG is big-endian
                row[static_cast<std::size_t>(x) * 2 + 1] = static_cast<unsigned char>(v & 0xff);
            } else {
                row[static_cast<std::size_t>(x)] = static_cast<unsigned char>(std::min<std::uint16_t>(v, 255));
            }
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
}

HeightField loadHeightMap(const std::filesystem::path& path, const HeightMapOptions& o) {
    if (!(o.cellSize > 0.0f) || !(o.cellSize <= kMaxCellSize))
        fail(path, "the cell size must be a finite number in (0, " + std::to_string(kMaxCellSize) + "] m (got " +
                       std::to_string(o.cellSize) + ")");
    if (!(std::abs(o.heightScale) <= kMaxHeight))
        fail(path, "the height scale must be a finite number of metres with |scale| <= " + std::to_string(kMaxHeight) +
                       " (got " + std::to_string(o.heightScale) + ")");
    if (!std::isfinite(o.baseHeight))
        fail(path, "the base height must be a finite number of metres (got " + std::to_string(o.baseHeight) + ")");
    const GreyImage img = readGreyPng(path);
    HeightField f;
    f.width = img.width;
    f.height = img.height;
    f.cellSize = o.cellSize;
    f.heights.resize(img.values.size());
    const double scale = static_cast<double>(o.heightScale) / img.maxValue();
    for (std::size_t i = 0; i < img.values.size(); ++i) f.heights[i] = static_cast<float>(img.values[i] * scale);
    f.origin = o.baseHeight;  // kept apart: heights stay small, where fp32 resolves them finely
    return f;
}

float latticeNoise(int x, int y, int z, unsigned seed) {
    std::uint32_t h = hash32(static_cast<std::uint32_t>(x) * 0x8da6b343U ^
                             hash32(static_cast<std::uint32_t>(y) * 0xd8163841U ^
                                    hash32(static_cast<std::uint32_t>(z) * 0xcb1ab31fU ^ seed)));
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

float valueNoise3(float x, float y, float z, unsigned seed) {
    const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
    const float tx = smoothStep01(x - fx), ty = smoothStep01(y - fy), tz = smoothStep01(z - fz);
    auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
    float c[2][2];
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            c[dz][dy] =
                lerp(latticeNoise(ix, iy + dy, iz + dz, seed), latticeNoise(ix + 1, iy + dy, iz + dz, seed), tx);
    return lerp(lerp(c[0][0], c[0][1], ty), lerp(c[1][0], c[1][1], ty), tz);
}

float fbm3(float x, float y, float z, unsigned seed, int octaves) {
    float sum = 0.0f, amplitude = 0.5f, norm = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * valueNoise3(x, y, z, seed + static_cast<unsigned>(o) * 1013U);
        norm += amplitude;
        x *= 2.03f;
        y *= 2.03f;
        z *= 2.03f;
        amplitude *= 0.5f;
    }
    return norm > 0.0f ? sum / norm : 0.0f;
}

HeightField proceduralTerrain(const ProceduralTerrainOptions& o) {
    if (o.width < 1 || o.height < 1 || !(o.cellSize > 0.0f) || !std::isfinite(o.relief) || o.pits < 0)
        throw std::invalid_argument(
            "proceduralTerrain: needs at least 1x1 cells, a cell size > 0, a finite relief and pits >= 0");
    HeightField f;
    f.width = o.width;
    f.height = o.height;
    f.cellSize = o.cellSize;
    f.heights.resize(f.cellCount());
    struct Pit {
        float u, v, radius, depth;
    };
    std::vector<Pit> pits;
    for (int k = 0; k < o.pits; ++k) {
        const auto r = [&](int channel) { return latticeNoise(k, channel, 77, o.seed); };
        pits.push_back(
            {0.15f + 0.7f * r(0), 0.15f + 0.7f * r(1), 0.05f + 0.08f * r(2), (0.10f + 0.15f * r(3)) * o.relief});
    }
    const float aspect = static_cast<float>(o.height) / static_cast<float>(o.width);
    for (int z = 0; z < o.height; ++z)
        for (int x = 0; x < o.width; ++x) {
            const float u = o.width > 1 ? static_cast<float>(x) / static_cast<float>(o.width - 1) : 0.5f;
            const float v = o.height > 1 ? static_cast<float>(z) / static_cast<float>(o.height - 1) : 0.5f;
            const float hills = fbm3(u * 3.0f, v * 3.0f * aspect, 0.5f, o.seed, 5);
            const float tilt = 0.25f * (1.0f - u);  // drains towards x = max
            float h = o.relief * (hills + tilt);
            for (const Pit& p : pits) {
                const float du = u - p.u, dv = (v - p.v) * aspect;
                const float d = std::sqrt(du * du + dv * dv) / p.radius;
                if (d < 1.0f) {
                    const float b = 1.0f - d * d;
                    h -= p.depth * b * b;
                }
            }
            f.heights[f.index(x, z)] = h;
        }
    return f;
}

std::vector<float> loadPermeabilityMap(const std::filesystem::path& path, int width, int height,
                                       double maxRateMetresPerSecond) {
    if (!(maxRateMetresPerSecond >= 0.0) || !std::isfinite(maxRateMetresPerSecond))
        fail(path, "the maximum infiltration rate must be a finite number >= 0");
    const GreyImage img = readGreyPng(path);
    if (img.width != width || img.height != height)
        fail(path, "permeability map is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                       " but the terrain is " + std::to_string(width) + "x" + std::to_string(height) +
                       "; give it the terrain's size");
    std::vector<float> k(img.values.size());
    for (std::size_t i = 0; i < k.size(); ++i)
        k[i] = static_cast<float>(maxRateMetresPerSecond * img.values[i] / img.maxValue());
    return k;
}

std::vector<float> proceduralPermeability(const HeightField& t, const PermeabilityOptions& o) {
    validate(t, "proceduralPermeability");
    if (!(o.soilMmPerHour >= 0.0) || !(o.clayMmPerHour >= 0.0))
        throw std::invalid_argument("proceduralPermeability: infiltration rates must be >= 0");
    std::vector<float> k(t.cellCount());
    const double soil = mmPerHourToMetresPerSecond(o.soilMmPerHour), clay = mmPerHourToMetresPerSecond(o.clayMmPerHour);
    for (int z = 0; z < t.height; ++z)
        for (int x = 0; x < t.width; ++x) {
            const float u = static_cast<float>(x) / static_cast<float>(std::max(1, t.width - 1));
            const float v = static_cast<float>(z) / static_cast<float>(std::max(1, t.height - 1));
            float soilShare = std::clamp((fbm3(u * 5.0f, v * 5.0f, 3.5f, o.seed, 4) - 0.40f) * 4.0f, 0.0f, 1.0f);
            // Steep ground is bare and compacted.
            const int xl = std::max(0, x - 1), xr = std::min(t.width - 1, x + 1);
            const int zu = std::max(0, z - 1), zd = std::min(t.height - 1, z + 1);
            const float gx = (t.at(xr, z) - t.at(xl, z)) / (static_cast<float>(std::max(1, xr - xl)) * t.cellSize);
            const float gz = (t.at(x, zd) - t.at(x, zu)) / (static_cast<float>(std::max(1, zd - zu)) * t.cellSize);
            const float steep = std::clamp((std::sqrt(gx * gx + gz * gz) - 0.35f) * 4.0f, 0.0f, 1.0f);
            soilShare *= 1.0f - steep;
            k[t.index(x, z)] = static_cast<float>(clay + (soil - clay) * soilShare);
        }
    return k;
}

std::vector<float> uniformPermeability(const HeightField& t, double metresPerSecond) {
    if (!(metresPerSecond >= 0.0) || !std::isfinite(metresPerSecond))
        throw std::invalid_argument("uniformPermeability: the rate must be a finite number >= 0");
    return std::vector<float>(t.cellCount(), static_cast<float>(metresPerSecond));
}

}  // namespace prism::water
