// Reporting for prism_bench_tradeoffs: the per-(shader, level) results, the Pareto front
// of (median frame time, mean error), the Markdown table, the CSV and the SVG plot.
//
//     std::vector<prism::bench::Row> rows = ...;                 // one per shader x level
//     auto front = prism::bench::paretoFront(rows, prism::bench::fullError);
//     prism::bench::printTable(std::cout, rows);
//     prism::bench::writeCsv("docs/tradeoffs.csv", rows, front);
//     prism::bench::writeSvg("docs/tradeoffs.svg", rows, front, "512x512, llvmpipe");
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "prism/reference/image_metrics.hpp"

namespace prism::bench {

using reference::ErrorStats;
using reference::Metrics;

struct Row {
    std::string shader;
    unsigned level = 0;
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    bool diffuseModel = false;  // flat/smooth: `matched` is against the diffuse-only reference
    double medianMs = 0.0, minMs = 0.0, p25Ms = 0.0, p75Ms = 0.0;  // wall time per frame
    double medianCpuMs = 0.0;                                      // process CPU time per frame (all threads)
    int frames = 0;
    Metrics matched;  // against the reference of the shader's own lighting model
    Metrics full;     // against the full (diffuse + Phong specular) reference
};

// Which error a front or a budget is about.
using ErrorOf = std::function<double(const Row&)>;
inline double fullError(const Row& r) {
    return r.full.union_.mean;
}
inline double matchedError(const Row& r) {
    return r.matched.union_.mean;
}

// Indices of the non-dominated rows (no other row is at least as fast AND at least as
// accurate, and better in one), fastest first.
std::vector<std::size_t> paretoFront(const std::vector<Row>& rows, const ErrorOf& error);

// The fastest row (by median) whose error is <= budget, among `candidates` (all rows when empty).
std::optional<std::size_t> cheapestWithin(const std::vector<Row>& rows, const ErrorOf& error, double budget,
                                          const std::vector<std::size_t>& candidates = {});

void printTable(std::ostream& out, const std::vector<Row>& rows);
void writeCsv(const std::filesystem::path& path, const std::vector<Row>& rows, const std::vector<std::size_t>& front);
// Two panels: median frame time vs mean error against the full reference (with the
// Pareto front), and against each shader's own lighting model. Log-log axes.
void writeSvg(const std::filesystem::path& path, const std::vector<Row>& rows, const std::vector<std::size_t>& front,
              const std::string& subtitle);

std::string rowName(const Row& row);  // "phong L4"

}  // namespace prism::bench
