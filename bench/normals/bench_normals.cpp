// prism_bench_normals: how long smooth normals take for an imported (split per face)
// mesh: weld by position + area-weighted normals, with the O(n) hash weld against
// the O(n^2) search of the FUDGE shader thesis (§6.3). Prints medians from one run and their ratio.
//
//     prism_bench_normals [--repeats N] [--quadratic-max-vertices N] [--sizes 10000,30000,100000,1000000]
//
// Times are the median thread CPU time (robust on a shared machine; equal to wall
// time on an idle one). The mesh is the ribbed trefoil knot split per face (3
// vertices per triangle, as an OBJ import gives). The O(n^2) method runs only while
// the split mesh has at most --quadratic-max-vertices vertices (default 100000);
// larger sizes show an extrapolation t * (n / n_measured)^2 from the largest
// measured size, marked "~". Default sizes: 10k, 30k (the largest the O(n^2) method
// measures by default), 100k and 1M triangles; about a minute in all.
#include "prism/geometry/normals.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/geometry/weld.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace prism::geometry;

struct Settings {
    int repeats = 5;
    std::size_t quadraticMaxVertices = 100000;
    std::vector<std::size_t> triangleCounts{10000, 30000, 100000, 1000000};
};

[[noreturn]] void usage(const char* problem) {
    std::fprintf(stderr,
                 "prism_bench_normals: %s\n"
                 "usage: prism_bench_normals [--repeats N] [--quadratic-max-vertices N] [--sizes A,B,...]\n",
                 problem);
    std::exit(2);
}

std::size_t parseCount(const char* text) {
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (end == text || *end != '\0' || value == 0) usage("expected a positive integer");
    return static_cast<std::size_t>(value);
}

Settings parseArguments(int argc, char** argv) {
    Settings settings;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) usage(("missing value after " + flag).c_str());
        const char* value = argv[++i];
        if (flag == "--repeats") {
            settings.repeats = static_cast<int>(parseCount(value));
        } else if (flag == "--quadratic-max-vertices") {
            settings.quadraticMaxVertices = parseCount(value);
        } else if (flag == "--sizes") {
            settings.triangleCounts.clear();
            std::stringstream list(value);
            for (std::string item; std::getline(list, item, ',');)
                settings.triangleCounts.push_back(parseCount(item.c_str()));
        } else {
            usage(("unknown option " + flag).c_str());
        }
    }
    return settings;
}

// A split knot with `triangles` triangles (exactly, when triangles / 2 has a divisor
// near sqrt(triangles / 16)): path x tube x 2 with the tube about path / 8.
Mesh importedKnot(std::size_t triangles) {
    const std::size_t cells = std::max<std::size_t>(triangles / 2, 24 * 8);
    std::size_t tube = std::max<std::size_t>(8, static_cast<std::size_t>(std::sqrt(static_cast<double>(cells) / 8.0)));
    for (std::size_t candidate = tube; candidate >= 8; --candidate) {
        if (cells % candidate == 0) {
            tube = candidate;
            break;
        }
    }
    TrefoilKnotShape shape;
    shape.tubeSegments = static_cast<std::uint32_t>(tube);
    shape.pathSegments = static_cast<std::uint32_t>(std::max<std::size_t>(24, (cells + tube / 2) / tube));
    Mesh knot = makeTrefoilKnot(shape);
    knot.normals.clear();
    return splitVerticesPerFace(knot);
}

// CPU time of this (single) thread: on a shared build machine wall time also counts
// the time other processes hold the core; on an idle machine the two agree.
double threadCpuMilliseconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

double medianMilliseconds(int repeats, const std::function<std::size_t()>& work, std::size_t& result) {
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r) {
        const double start = threadCpuMilliseconds();
        result = work();
        times.push_back(threadCpuMilliseconds() - start);
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const Settings settings = parseArguments(argc, argv);
    std::printf("Smooth normals for split (OBJ-style) meshes: weld by position + area-weighted normals\n");
    std::printf(
        "mesh: ribbed trefoil knot split per face; median thread CPU time of %d runs (O(n^2): of up to 3);\n"
        "O(n^2) measured up to %zu split vertices, extrapolated beyond\n\n",
        settings.repeats, settings.quadraticMaxVertices);
    std::printf("%10s %10s %9s | %12s %12s | %14s %10s\n", "triangles", "split v.", "welded v.", "normals ms",
                "O(n) weld ms", "O(n^2) ms", "ratio");
    std::printf("-----------------------------------------------------------------------------------------\n");

    double lastQuadraticMs = 0.0;
    std::size_t lastQuadraticVertices = 0;
    for (std::size_t requested : settings.triangleCounts) {
        const Mesh split = importedKnot(requested);
        const std::size_t vertices = split.positions.size();
        std::size_t welded = 0, ignored = 0;

        const Mesh indexed = weldVertices(split).mesh;
        const double normalsMs = medianMilliseconds(
            settings.repeats, [&] { return areaWeightedVertexNormals(indexed).size(); }, ignored);
        const double hashMs = medianMilliseconds(
            settings.repeats, [&] { return weldVertices(split).mesh.positions.size(); }, welded);

        char quadratic[32];
        double quadraticMs = 0.0;
        if (vertices <= settings.quadraticMaxVertices) {
            std::size_t referenceWelded = 0;
            // The O(n^2) runs are long: a median of at most 3.
            quadraticMs = medianMilliseconds(
                std::min(settings.repeats, 3), [&] { return weldQuadraticReference(split).mesh.positions.size(); },
                referenceWelded);
            if (referenceWelded != welded) {
                std::fprintf(stderr, "mismatch: O(n) welded %zu vertices, O(n^2) %zu\n", welded, referenceWelded);
                return 1;
            }
            lastQuadraticMs = quadraticMs;
            lastQuadraticVertices = vertices;
            std::snprintf(quadratic, sizeof quadratic, "%.1f", quadraticMs);
        } else if (lastQuadraticVertices > 0) {
            const double growth = static_cast<double>(vertices) / static_cast<double>(lastQuadraticVertices);
            quadraticMs = lastQuadraticMs * growth * growth;
            std::snprintf(quadratic, sizeof quadratic, "~%.0f", quadraticMs);
        } else {
            std::snprintf(quadratic, sizeof quadratic, "skipped");
        }
        char ratio[32] = "-";
        if (quadraticMs > 0.0)
            std::snprintf(ratio, sizeof ratio, "%s%.0fx", vertices <= settings.quadraticMaxVertices ? "" : "~",
                          quadraticMs / hashMs);
        std::printf("%10zu %10zu %9zu | %12.2f %12.2f | %14s %10s\n", triangleCount(split), vertices, welded, normalsMs,
                    hashMs, quadratic, ratio);
        std::fflush(stdout);
    }
    std::printf(
        "\nnormals ms: areaWeightedVertexNormals on the welded mesh alone.\n"
        "O(n) weld ms / O(n^2) ms: weldVertices / weldQuadraticReference, both including the normals.\n"
        "~: extrapolated as t * (n / n_measured)^2 from the largest measured size, not measured.\n");
    return 0;
}
