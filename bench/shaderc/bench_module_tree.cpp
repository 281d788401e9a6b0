// prism_bench_module_tree: what a large module library costs prism-shaderc (issue 17).
// Generates a library of N modules (default 1000) in one -I folder, lygia-like: half
// of them leaves, half including one or two others under `#ifndef FNC_X` guards, plus
// a few stages that include some of them. Every module of the -I folder is scanned
// (description, text, dependencies, problems as warnings), used or not. Prints a
// Markdown table of median and minimum wall and CPU time over interleaved runs for:
//   (b)  prism-shaderc --check -j 1 with the whole library as -I
//   (b0) the same stages with only the modules they include as -I (no unused modules)
//   (c)  prism-shaderc -o header, header absent (full generate), whole library
//   (d)  the same again with the header up to date (the no-op), whole library
// The scan cost of the library is (b) - (b0); the no-op is (d).
//
//     prism_bench_module_tree [--modules N] [--runs N] [--shaderc PATH]
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <set>
#include <string>
#include <vector>

#ifndef PRISM_BENCH_SHADERC
#define PRISM_BENCH_SHADERC ""
#endif

namespace fs = std::filesystem;

namespace {

struct Sample {
    double wallMs = 0;
    double cpuMs = 0;
};

Sample run(const std::vector<std::string>& args, const fs::path& log) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    const auto end = std::chrono::steady_clock::now();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::ifstream in(log);
        std::cerr << "prism_bench_module_tree: command failed:\n" << in.rdbuf() << "\n";
        std::exit(1);
    }
    auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
    return {std::chrono::duration<double, std::milli>(end - start).count(), ms(usage.ru_utime) + ms(usage.ru_stime)};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

void write(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

std::string moduleName(int i) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "m%04d", i);
    return buf;
}

// Returns the modules the stages include, with their dependencies (for (b0)).
std::set<int> generate(const fs::path& root, int modules, int stages) {
    std::mt19937 random(17);
    std::vector<std::vector<int>> deps(static_cast<std::size_t>(modules));
    for (int i = 0; i < modules; ++i) {
        const std::string name = moduleName(i), guard = "FNC_" + name;
        std::string text = "// " + name + ": module " + std::to_string(i) + " of a generated library.\n";
        text += "#ifndef " + guard + "\n#define " + guard + "\n";
        std::string body = "x";
        if (i > 0 && random() % 2) {
            const int count = 1 + static_cast<int>(random() % 2);
            for (int k = 0; k < count; ++k) {
                const int dep = static_cast<int>(random() % static_cast<unsigned>(i));
                deps[static_cast<std::size_t>(i)].push_back(dep);
                text += "#include \"" + moduleName(dep) + ".glsl\"\n";
                body += " + f" + moduleName(dep) + "(x)";
            }
        }
        text += "float f" + name + "(float x) { return " + body + "; }\n#endif\n";
        write(root / "lib" / (name + ".glsl"), text);
    }
    std::set<int> used;
    std::vector<int> todo;
    for (int s = 0; s < stages; ++s) {
        const int top = modules - 1 - s * 7;
        todo.push_back(top);
        write(root / "shaders" / ("s" + std::to_string(s) + ".vert"),
              "#version 330 core\nin vec3 a_position;\nvoid main() { gl_Position = vec4(a_position, 1.0); }\n");
        write(root / "shaders" / ("s" + std::to_string(s) + ".frag"),
              "#version 330 core\n#include \"" + moduleName(top) + ".glsl\"\nout vec4 o;\nvoid main() { o = vec4(f" +
                  moduleName(top) + "(1.0)); }\n");
    }
    while (!todo.empty()) {
        const int m = todo.back();
        todo.pop_back();
        if (!used.insert(m).second) continue;
        for (int d : deps[static_cast<std::size_t>(m)]) todo.push_back(d);
    }
    for (int m : used)
        fs::copy_file(root / "lib" / (moduleName(m) + ".glsl"), root / "used" / (moduleName(m) + ".glsl"));
    return used;
}

}  // namespace

int main(int argc, char** argv) {
    int modules = 1000, runs = 7, stages = 4;
    std::string shaderc = PRISM_BENCH_SHADERC;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--modules" && i + 1 < argc)
            modules = std::atoi(argv[++i]);
        else if (a == "--runs" && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else if (a == "--shaderc" && i + 1 < argc)
            shaderc = argv[++i];
        else {
            std::cout << "usage: prism_bench_module_tree [--modules N] [--runs N] [--shaderc PATH]\n";
            return a == "--help" ? 0 : 2;
        }
    }
    if (modules < 40 || runs < 1 || shaderc.empty()) {
        std::cerr << "prism_bench_module_tree: need --modules >= 40, --runs >= 1 and prism-shaderc\n";
        return 2;
    }
    const fs::path root = fs::temp_directory_path() / ("prism-bench-module-tree-" + std::to_string(getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "used");
    const auto used = generate(root, modules, stages);
    const fs::path log = root / "log.txt", header = root / "h.hpp";
    const std::string lib = (root / "lib").string(), usedDir = (root / "used").string(),
                      sh = (root / "shaders").string();

    struct Case {
        std::string label;
        std::vector<std::string> args;
        bool freshHeader = false;
        std::vector<Sample> samples;
    };
    std::vector<Case> cases = {
        {"(b) --check -j 1, the whole library as -I", {shaderc, "--check", "-j", "1", "-I", lib, sh}, false, {}},
        {"(b0) --check -j 1, only the used modules as -I",
         {shaderc, "--check", "-j", "1", "-I", usedDir, sh},
         false,
         {}},
        {"(c) -o header -j 1, header absent (full generate)",
         {shaderc, "-o", header.string(), "-j", "1", "-I", lib, sh},
         true,
         {}},
        {"(d) -o header -j 1, header up to date (no-op)",
         {shaderc, "-o", header.string(), "-j", "1", "-I", lib, sh},
         false,
         {}},
    };
    for (int r = 0; r <= runs; ++r) {  // round 0 warms up
        for (auto& c : cases) {
            if (c.freshHeader) fs::remove(header);
            const Sample s = run(c.args, log);
            if (r > 0) c.samples.push_back(s);
        }
    }
    std::cout << "Library: " << modules << " modules in one -I folder (" << used.size() << " of them reached from "
              << stages << " shaders); " << runs << " interleaved runs per case after a warm-up.\n\n"
              << "| case | median ms | min ms | CPU ms (median) |\n|---|---:|---:|---:|\n";
    std::vector<double> medianCpu;
    for (const auto& c : cases) {
        std::vector<double> wall, cpu;
        for (const auto& s : c.samples) {
            wall.push_back(s.wallMs);
            cpu.push_back(s.cpuMs);
        }
        medianCpu.push_back(median(cpu));
        std::printf("| %s | %.1f | %.1f | %.1f |\n", c.label.c_str(), median(wall),
                    *std::min_element(wall.begin(), wall.end()), median(cpu));
    }
    std::printf(
        "\nScanning the %d-module library, CPU: (b) - (b0) = %.1f ms, %.3f ms per module. "
        "No-op (d): %.1f ms CPU (the 50 ms no-op target of docs/shaderc-bench.md is for the project "
        "catalogue).\n",
        modules, medianCpu[0] - medianCpu[1], (medianCpu[0] - medianCpu[1]) / modules, medianCpu[3]);
    fs::remove_all(root);
    return 0;
}
