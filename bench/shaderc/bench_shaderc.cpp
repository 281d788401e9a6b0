// prism_bench_shaderc: how fast prism-shaderc checks and generates a shader catalogue
// against the naive build (one glslangValidator process per stage file), on a copy of
// the project catalogue and on a larger synthetic one. Prints a Markdown table
// (median and minimum of N interleaved runs, the (a)/(b) ratio, the 10x and 50 ms
// targets) and writes the same rows as CSV. docs/shaderc-bench.md quotes its output.
//
//     prism_bench_shaderc [--runs N] [--shaders N] [--jobs N] [--csv FILE]
//                         [--shaderc PATH] [--glslang PATH] [--source-dir DIR]
//                         [--work-dir DIR] [--keep] [--no-cmake]
//
// Everything runs in a fresh temporary directory: the source tree is only read.
// Measured cases, per catalogue (each a sequence of separate processes, timed with
// std::chrono around fork/exec/wait4; CPU = user+sys of the process and its children):
//   (a)  glslangValidator FILE, once per flattened stage file, sequentially
//   (a') glslangValidator with all flattened stage files in one process (reference)
//   (b)  prism-shaderc --check on the whole catalogue, -j <jobs> and -j 1
//   (c)  prism-shaderc -o header, header absent (full generate)
//   (d)  the same command again with the header up to date (no-op; must not write)
//   (e)  ninja in a configured CMake build dir (prism_add_shaders) with nothing to do
//   (f)  ninja after `touch` of a module: the depfile re-runs the tool with unchanged
//        inputs, which should cost about (d), not (c) (a note is printed if not)
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#ifndef PRISM_BENCH_SHADERC
#define PRISM_BENCH_SHADERC ""
#endif
#ifndef PRISM_BENCH_CSV_DEFAULT
#define PRISM_BENCH_CSV_DEFAULT "shaderc_bench.csv"
#endif
#ifndef PRISM_BENCH_GLSLANG
#define PRISM_BENCH_GLSLANG ""
#endif
#ifndef PRISM_BENCH_SOURCE_DIR
#define PRISM_BENCH_SOURCE_DIR ""
#endif
#ifndef PRISM_BENCH_CMAKE
#define PRISM_BENCH_CMAKE ""
#endif
#ifndef PRISM_BENCH_NINJA
#define PRISM_BENCH_NINJA ""
#endif

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using Command = std::vector<std::string>;

// ---------------------------------------------------------------- settings

struct Settings {
    int runs = 15;
    int syntheticShaders = 40;
    int jobs = 0;                               // 0: hardware concurrency
    std::string csv = PRISM_BENCH_CSV_DEFAULT;  // in the build tree, never the source tree
    std::string shaderc = PRISM_BENCH_SHADERC;
    std::string glslang = PRISM_BENCH_GLSLANG;
    std::string sourceDir = PRISM_BENCH_SOURCE_DIR;
    std::string cmake = PRISM_BENCH_CMAKE;
    std::string ninja = PRISM_BENCH_NINJA;
    std::string workDir;  // empty: mkdtemp under $TMPDIR or /tmp
    bool keep = false;
    bool cmakeStep = true;
    // The light-count axes multiply the catalogue 15-fold; by default the bench builds
    // the variants an application with two directional and one point light uses.
    bool allVariants = false;
};

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "prism_bench_shaderc: %s\n"
                 "usage: prism_bench_shaderc [--runs N] [--shaders N] [--jobs N] [--csv FILE]\n"
                 "         [--shaderc PATH] [--glslang PATH] [--source-dir DIR] [--work-dir DIR]\n"
                 "         [--keep] [--no-cmake] [--all-variants]\n"
                 "  --runs N      timed runs per case, after one warm-up round (default 15)\n"
                 "  --shaders N   shaders in the synthetic catalogue, copies of the project's (default 40)\n"
                 "  --jobs N      -j of the parallel prism-shaderc --check (default: all cores)\n"
                 "  --csv FILE    where the CSV goes (default " PRISM_BENCH_CSV_DEFAULT
                 ")\n"
                 "  --work-dir D  scratch directory (default: a new one under $TMPDIR, removed at exit)\n"
                 "  --keep        keep the scratch directory\n"
                 "  --no-cmake    skip the CMake/ninja cases (e) and (f)\n"
                 "  --all-variants  every light-count variant (default: '*:DIRECTIONAL_LIGHTS=2,POINT_LIGHTS=1')\n",
                 problem.c_str());
    std::exit(problem.empty() ? 0 : 2);
}

int parsePositive(const std::string& flag, const char* text) {
    char* end = nullptr;
    long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value <= 0 || value > 100000)
        usage(flag + ": expected a positive integer, got '" + text + "'");
    return static_cast<int>(value);
}

Settings parseArguments(int argc, char** argv) {
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "-h" || flag == "--help") usage("");
        if (flag == "--keep") {
            s.keep = true;
            continue;
        }
        if (flag == "--no-cmake") {
            s.cmakeStep = false;
            continue;
        }
        if (flag == "--all-variants") {
            s.allVariants = true;
            continue;
        }
        if (i + 1 >= argc) usage("missing value after " + flag);
        const char* value = argv[++i];
        if (flag == "--runs")
            s.runs = parsePositive(flag, value);
        else if (flag == "--shaders")
            s.syntheticShaders = parsePositive(flag, value);
        else if (flag == "--jobs")
            s.jobs = parsePositive(flag, value);
        else if (flag == "--csv")
            s.csv = value;
        else if (flag == "--shaderc")
            s.shaderc = value;
        else if (flag == "--glslang")
            s.glslang = value;
        else if (flag == "--source-dir")
            s.sourceDir = value;
        else if (flag == "--work-dir")
            s.workDir = value;
        else
            usage("unknown option " + flag);
    }
    if (s.jobs == 0) s.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return s;
}

// ---------------------------------------------------------------- processes

struct Sample {
    double wallMs = 0;
    double cpuMs = 0;  // user + sys of the process and the children it waited for
};

struct Outcome {
    Sample sample;
    int exitCode = -1;
};

std::string g_logPath;  // every child's stdout+stderr goes here (truncated per process)
std::string g_workDir;  // the scratch directory, named when a command fails

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Outcome runProcess(const Command& cmd, const fs::path& cwd) {
    std::vector<char*> argv;
    for (const auto& a : cmd) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);

    const auto start = Clock::now();
    const pid_t pid = fork();
    if (pid < 0) {
        std::perror("prism_bench_shaderc: fork");
        std::exit(1);
    }
    if (pid == 0) {
        if (chdir(cwd.c_str()) != 0) _exit(126);
        int log = open(g_logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (log >= 0) {
            dup2(log, STDOUT_FILENO);
            dup2(log, STDERR_FILENO);
            close(log);
        }
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0) {
        if (errno != EINTR) {
            std::perror("prism_bench_shaderc: wait4");
            std::exit(1);
        }
    }
    const auto end = Clock::now();
    auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
    Outcome out;
    out.sample.wallMs = std::chrono::duration<double, std::milli>(end - start).count();
    out.sample.cpuMs = ms(usage.ru_utime) + ms(usage.ru_stime);
    out.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return out;
}

std::string joined(const Command& cmd) {
    std::string s;
    for (const auto& a : cmd) s += (s.empty() ? "" : " ") + a;
    return s;
}

// Runs a command that must succeed; on failure shows its output and stops the benchmark.
Sample mustRun(const Command& cmd, const fs::path& cwd) {
    Outcome o = runProcess(cmd, cwd);
    if (o.exitCode != 0) {
        std::fprintf(stderr,
                     "prism_bench_shaderc: command failed (exit %d) in %s:\n  %s\n%s\n(scratch directory kept: %s)\n",
                     o.exitCode, cwd.c_str(), joined(cmd).c_str(), readFile(g_logPath).c_str(), g_workDir.c_str());
        std::exit(1);
    }
    return o.sample;
}

std::string firstLineOf(const Command& cmd) {
    Outcome o = runProcess(cmd, fs::current_path());
    std::string text = readFile(g_logPath);
    auto nl = text.find('\n');
    return o.exitCode == 0 ? text.substr(0, nl) : "?";
}

std::string findInPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    if (!path) return {};
    std::stringstream ss(path);
    std::string dir;
    while (std::getline(ss, dir, ':')) {
        fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    return {};
}

std::string resolveExecutable(const std::string& given, const std::string& fallbackName) {
    if (!given.empty() && access(given.c_str(), X_OK) == 0) return given;
    if (!given.empty() && given.find('/') == std::string::npos) return findInPath(given);
    return given.empty() ? findInPath(fallbackName) : std::string{};
}

// ---------------------------------------------------------------- machine

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    return "unknown";
}

std::string loadAverage() {
    std::string text = readFile("/proc/loadavg");
    std::istringstream ss(text);
    std::string a, b, c;
    ss >> a >> b >> c;
    return a + " " + b + " " + c;
}

// ---------------------------------------------------------------- catalogues

struct Catalogue {
    std::string name;   // "project" or "synthetic-40"
    fs::path root;      // <work>/<name>
    fs::path sources;   // stage files
    fs::path modules;   // -I
    fs::path contract;  // --contract
    int shaders = 0;
    int stageSourceFiles = 0;
    std::vector<std::string> flattened;  // --emit-glsl output: one file per stage and variant
};

bool isStageFile(const fs::path& p) {
    static const char* kExt[] = {".vert", ".geom", ".frag", ".comp"};
    return std::any_of(std::begin(kExt), std::end(kExt), [&](const char* e) { return p.extension() == e; });
}

std::vector<fs::path> sortedFiles(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// copies = 1 and suffix false: an exact copy of the project catalogue. Otherwise the
// project's shaders are copied under new names (<shader>_cNN) until `shaders` exist.
Catalogue makeCatalogue(const Settings& s, const fs::path& work, const std::string& name, int shaders, bool rename) {
    Catalogue c;
    c.name = name;
    c.root = work / name;
    c.sources = c.root / "shader_sources";
    c.modules = c.root / "modules";
    c.contract = c.modules / "contract.json";
    fs::create_directories(c.sources);
    fs::copy(fs::path(s.sourceDir) / "modules", c.modules, fs::copy_options::recursive);

    std::vector<std::string> stems;
    for (const auto& f : sortedFiles(fs::path(s.sourceDir) / "shader_sources"))
        if (isStageFile(f) && std::find(stems.begin(), stems.end(), f.stem().string()) == stems.end())
            stems.push_back(f.stem().string());
    if (stems.empty()) {
        std::fprintf(stderr, "prism_bench_shaderc: no stage files in %s/shader_sources\n", s.sourceDir.c_str());
        std::exit(1);
    }
    for (int i = 0; i < shaders; ++i) {
        const std::string& stem = stems[static_cast<std::size_t>(i) % stems.size()];
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, "_c%02zu", static_cast<std::size_t>(i) / stems.size());
        const std::string newStem = rename ? stem + suffix : stem;
        for (const auto& f : sortedFiles(fs::path(s.sourceDir) / "shader_sources"))
            if (isStageFile(f) && f.stem() == stem) {
                fs::copy_file(f, c.sources / (newStem + f.extension().string()));
                ++c.stageSourceFiles;
            }
    }
    c.shaders = shaders;
    return c;
}

int countProjectShaders(const Settings& s) {
    std::vector<std::string> stems;
    for (const auto& f : sortedFiles(fs::path(s.sourceDir) / "shader_sources"))
        if (isStageFile(f) && std::find(stems.begin(), stems.end(), f.stem().string()) == stems.end())
            stems.push_back(f.stem().string());
    return static_cast<int>(stems.size());
}

Command shadercCommand(const Settings& s, const Catalogue& c, std::initializer_list<std::string> extra) {
    Command cmd{s.shaderc};
    cmd.insert(cmd.end(), extra.begin(), extra.end());
    if (!s.allVariants) {
        cmd.push_back("--variant");
        cmd.push_back("*:DIRECTIONAL_LIGHTS=2,POINT_LIGHTS=1");
    }
    for (std::string a :
         {std::string("-I"), c.modules.string(), std::string("--contract"), c.contract.string(), c.sources.string()})
        cmd.push_back(a);
    return cmd;
}

// ---------------------------------------------------------------- cases

struct Case {
    std::string catalogue;
    std::string id;
    std::string label;
    int processes = 1;
    int stages = 0;                 // flattened stage files of the catalogue
    std::function<void()> prepare;  // untimed, before every run
    std::function<Sample()> run;    // timed
    std::function<void()> check;    // untimed, after every run (may flag a problem)
    std::vector<Sample> samples;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

struct Stats {
    double medianWall, minWall, maxWall, medianCpu;
};

Stats statsOf(const Case& c) {
    std::vector<double> wall, cpu;
    for (const auto& s : c.samples) {
        wall.push_back(s.wallMs);
        cpu.push_back(s.cpuMs);
    }
    return {median(wall), *std::min_element(wall.begin(), wall.end()), *std::max_element(wall.begin(), wall.end()),
            median(cpu)};
}

std::int64_t mtimeNs(const fs::path& p) {
    struct stat st {};
    if (stat(p.c_str(), &st) != 0) return -1;
    return static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
}

std::vector<std::string> g_problems;  // printed after the table

void addCases(const Settings& s, const Catalogue& cat, bool withCmake, std::vector<Case>& cases) {
    const int stages = static_cast<int>(cat.flattened.size());
    const fs::path cwd = cat.root;
    auto base = [&](std::string id, std::string label, int processes) {
        Case c;
        c.catalogue = cat.name;
        c.id = std::move(id);
        c.label = std::move(label);
        c.processes = processes;
        c.stages = stages;
        return c;
    };

    {  // (a) the naive build: one glslangValidator process per flattened stage file
        Case c = base("a", "glslangValidator, one process per stage file", stages);
        c.run = [&s, files = cat.flattened, cwd] {
            Sample total;
            for (const auto& f : files) {
                Sample one = mustRun({s.glslang, f}, cwd);
                total.wallMs += one.wallMs;
                total.cpuMs += one.cpuMs;
            }
            return total;
        };
        cases.push_back(std::move(c));
    }
    {  // (a') reference: the same files in one glslangValidator process
        Case c = base("a'", "glslangValidator, all stage files in one process", 1);
        Command cmd{s.glslang};
        cmd.insert(cmd.end(), cat.flattened.begin(), cat.flattened.end());
        c.run = [cmd, cwd] { return mustRun(cmd, cwd); };
        cases.push_back(std::move(c));
    }
    std::vector<int> jobCounts{s.jobs};
    if (s.jobs != 1) jobCounts.push_back(1);
    for (int jobs : jobCounts) {  // (b) prism-shaderc --check, whole catalogue
        Case c = base(jobs == s.jobs ? "b" : "b1", "prism-shaderc --check -j " + std::to_string(jobs), 1);
        Command cmd = shadercCommand(s, cat, {"--check", "-j", std::to_string(jobs)});
        c.run = [cmd, cwd] { return mustRun(cmd, cwd); };
        cases.push_back(std::move(c));
    }
    const fs::path header = cat.root / "generated" / "shaders.hpp";
    const Command generate = shadercCommand(s, cat, {"-o", header.string(), "-j", std::to_string(s.jobs)});
    {  // (c) full generate, header absent
        Case c = base("c", "prism-shaderc -o header (fresh, header absent)", 1);
        c.prepare = [header] { fs::remove(header); };
        c.run = [generate, cwd] { return mustRun(generate, cwd); };
        c.check = [header, name = cat.name] {
            if (!fs::exists(header)) g_problems.push_back(name + " (c): the header was not written");
        };
        cases.push_back(std::move(c));
    }
    {  // (d) no-op: same command, header up to date; must leave the header alone
        Case c = base("d", "prism-shaderc -o header (no-op, header up to date)", 1);
        auto before = std::make_shared<std::int64_t>(0);
        c.prepare = [header, generate, cwd, before] {
            if (!fs::exists(header)) mustRun(generate, cwd);
            *before = mtimeNs(header);
        };
        c.run = [generate, cwd] { return mustRun(generate, cwd); };
        c.check = [header, before, name = cat.name] {
            if (mtimeNs(header) != *before) g_problems.push_back(name + " (d): the no-op run rewrote the header");
        };
        cases.push_back(std::move(c));
    }
    if (!withCmake) return;

    // (e)/(f): a CMake project that uses prism_add_shaders() on this catalogue.
    const fs::path project = cat.root / "cmake-project";
    const fs::path build = cat.root / "cmake-build";
    fs::create_directories(project);
    {
        std::ofstream out(project / "CMakeLists.txt");
        out << "# Generated by prism_bench_shaderc: prism_add_shaders() on one benchmark catalogue.\n"
               "cmake_minimum_required(VERSION 3.20)\n"
               "project(prism_bench_step NONE)\n"
               "add_executable(prism-shaderc IMPORTED GLOBAL)\n"
               "set_target_properties(prism-shaderc PROPERTIES IMPORTED_LOCATION \""
            << s.shaderc
            << "\")\n"
               "add_executable(Prism::shaderc ALIAS prism-shaderc)\n"
               "add_library(Prism::catalog INTERFACE IMPORTED GLOBAL)\n"
               "include(\""
            << (fs::path(s.sourceDir) / "cmake" / "PrismShaders.cmake").string()
            << "\")\n"
               "file(GLOB sources \""
            << cat.sources.string() << "/*.vert\" \"" << cat.sources.string()
            << "/*.frag\")\n"
               "prism_add_shaders(bench_shaders SOURCES ${sources} MODULE_DIRS \""
            << cat.modules.string() << "\" CONTRACT \"" << cat.contract.string() << "\" HEADER bench/shaders.hpp"
            << (s.allVariants ? "" : " VARIANTS \"*:DIRECTIONAL_LIGHTS=2,POINT_LIGHTS=1\"")
            << ")\n"
               "add_custom_target(bench_all ALL)\n"
               "add_dependencies(bench_all bench_shaders_generate)\n";
    }
    mustRun({s.cmake, "-S", project.string(), "-B", build.string(), "-G", "Ninja", "-DCMAKE_MAKE_PROGRAM=" + s.ninja},
            cwd);
    mustRun({s.ninja, "-C", build.string()}, cwd);  // the first, real build

    const Command noop{s.ninja, "-C", build.string()};
    {
        Case c = base("e", "ninja, CMake build dir with nothing to do", 1);
        c.run = [noop, cwd] { return mustRun(noop, cwd); };
        c.check = [name = cat.name] {
            if (readFile(g_logPath).find("no work to do") == std::string::npos)
                g_problems.push_back(name + " (e): ninja had work to do: " + readFile(g_logPath));
        };
        cases.push_back(std::move(c));
    }
    {
        Case c = base("f", "ninja after `touch` of a module (depfile re-runs the tool, inputs unchanged)", 2);
        const fs::path module = cat.modules / "version.glsl";
        const fs::path generatedHeader = build / "bench_shaders_generated" / "bench" / "shaders.hpp";
        auto before = std::make_shared<std::int64_t>(0);
        c.prepare = [module, generatedHeader, before] {
            fs::last_write_time(module, fs::file_time_type::clock::now());
            *before = mtimeNs(generatedHeader);
        };
        c.run = [noop, cwd] { return mustRun(noop, cwd); };
        c.check = [generatedHeader, before, name = cat.name] {
            const std::string log = readFile(g_logPath);
            if (log.find("no work to do") != std::string::npos)
                g_problems.push_back(name + " (f): touching a module did not re-run prism-shaderc");
            if (mtimeNs(generatedHeader) != *before)
                g_problems.push_back(name + " (f): the header was rewritten although nothing changed");
        };
        cases.push_back(std::move(c));
    }
}

// ---------------------------------------------------------------- report

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

const Case* findCase(const std::vector<Case>& cases, const std::string& catalogue, const std::string& id) {
    for (const auto& c : cases)
        if (c.catalogue == catalogue && c.id == id) return &c;
    return nullptr;
}

std::string csvQuote(const std::string& s) {
    std::string out = "\"";
    for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
    Settings s = parseArguments(argc, argv);
    s.shaderc = resolveExecutable(s.shaderc, "prism-shaderc");
    s.glslang = resolveExecutable(s.glslang, "glslangValidator");
    if (s.shaderc.empty()) usage("prism-shaderc not found; give --shaderc PATH");
    if (s.glslang.empty()) usage("glslangValidator not found (apt install glslang-tools); give --glslang PATH");
    if (s.sourceDir.empty() || !fs::is_directory(fs::path(s.sourceDir) / "shader_sources"))
        usage("the Prism source tree (with shader_sources/ and modules/) not found; give --source-dir DIR");
    s.shaderc = fs::absolute(s.shaderc).string();
    s.glslang = fs::absolute(s.glslang).string();
    std::string cmakeNote;
    if (s.cmakeStep) {
        s.cmake = resolveExecutable(s.cmake, "cmake");
        s.ninja = resolveExecutable(s.ninja, "ninja");
        if (s.cmake.empty() || s.ninja.empty()) {
            s.cmakeStep = false;
            cmakeNote = "cases (e) and (f) skipped: cmake or ninja not found";
        }
    } else {
        cmakeNote = "cases (e) and (f) skipped (--no-cmake)";
    }

    // Scratch directory.
    fs::path work;
    if (s.workDir.empty()) {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/prism-bench-shaderc.XXXXXX";
        if (!mkdtemp(pattern.data())) {
            std::perror("prism_bench_shaderc: mkdtemp");
            return 1;
        }
        work = pattern;
    } else {
        work = fs::absolute(s.workDir);
        fs::remove_all(work);
        fs::create_directories(work);
    }
    g_logPath = (work / "last-process.log").string();
    g_workDir = work.string();

    // Catalogues: the project's, copied, and a synthetic one of --shaders shaders.
    const int projectShaders = countProjectShaders(s);
    std::vector<Catalogue> catalogues;
    catalogues.push_back(makeCatalogue(s, work, "project", projectShaders, false));
    catalogues.push_back(
        makeCatalogue(s, work, "synthetic-" + std::to_string(s.syntheticShaders), s.syntheticShaders, true));

    std::vector<Case> cases;
    for (auto& cat : catalogues) {
        const fs::path flat = cat.root / "flattened";
        mustRun(shadercCommand(s, cat, {"--emit-glsl", flat.string()}), cat.root);
        for (const auto& f : sortedFiles(flat))
            if (isStageFile(f)) cat.flattened.push_back(f.string());
        if (cat.flattened.empty()) {
            std::fprintf(stderr, "prism_bench_shaderc: --emit-glsl wrote no stage files for %s\n", cat.name.c_str());
            return 1;
        }
        addCases(s, cat, s.cmakeStep, cases);
    }

    const std::string loadBefore = loadAverage();
    std::fprintf(stderr, "prism_bench_shaderc: %d timed runs (+1 warm-up) of %zu cases in %s\n", s.runs, cases.size(),
                 work.c_str());
    // Interleaved rounds, so that a change of machine load hits every case alike.
    for (int round = 0; round <= s.runs; ++round) {
        for (auto& c : cases) {
            if (c.prepare) c.prepare();
            Sample sample = c.run();
            if (c.check) c.check();
            if (round > 0) c.samples.push_back(sample);
        }
        std::fprintf(stderr, "\r  round %d/%d", round, s.runs);
    }
    std::fprintf(stderr, "\n");
    const std::string loadAfter = loadAverage();

    // ---- Markdown table
    std::printf("## prism-shaderc vs one glslangValidator process per stage file\n\n");
    std::printf("Machine: %s, %u logical cores (nproc); load average before %s, after %s.\n", cpuModel().c_str(),
                std::thread::hardware_concurrency(), loadBefore.c_str(), loadAfter.c_str());
    std::printf("Tools: %s; %s.\n", firstLineOf({s.shaderc, "--version"}).c_str(),
                firstLineOf({s.glslang, "--version"}).c_str());
    std::printf("Runs: %d per case (after one warm-up round), interleaved; wall-clock time of the whole case.\n\n",
                s.runs);
    for (const auto& cat : catalogues)
        std::printf("- `%s`: %d shaders, %d stage source files, %zu flattened stage files (variants expanded)\n",
                    cat.name.c_str(), cat.shaders, cat.stageSourceFiles, cat.flattened.size());
    std::printf(
        "\n| catalogue | case | processes | median ms | min ms | CPU ms (median) | median ms per stage file | "
        "(a) / this |\n|---|---|---:|---:|---:|---:|---:|---:|\n");

    std::ofstream csv(s.csv);
    csv << "catalogue,case,label,shaders,stage_files,processes,runs,median_wall_ms,min_wall_ms,max_wall_ms,"
           "median_cpu_ms,median_ms_per_stage_file,speedup_a_over_case,samples_wall_ms\n";
    for (const auto& c : cases) {
        const Stats st = statsOf(c);
        const Case* a = findCase(cases, c.catalogue, "a");
        const double speedup = a ? statsOf(*a).medianWall / st.medianWall : 0;
        const Catalogue* cat = nullptr;
        for (const auto& k : catalogues)
            if (k.name == c.catalogue) cat = &k;
        std::printf("| %s | (%s) %s | %d | %s | %s | %s | %s | %s× |\n", c.catalogue.c_str(), c.id.c_str(),
                    c.label.c_str(), c.processes, fixed(st.medianWall, 1).c_str(), fixed(st.minWall, 1).c_str(),
                    fixed(st.medianCpu, 1).c_str(), fixed(st.medianWall / c.stages, 2).c_str(),
                    fixed(speedup, 1).c_str());
        std::string samples;
        for (const auto& x : c.samples) samples += (samples.empty() ? "" : ";") + fixed(x.wallMs, 3);
        csv << c.catalogue << ',' << c.id << ',' << csvQuote(c.label) << ',' << cat->shaders << ',' << c.stages << ','
            << c.processes << ',' << c.samples.size() << ',' << fixed(st.medianWall, 3) << ',' << fixed(st.minWall, 3)
            << ',' << fixed(st.maxWall, 3) << ',' << fixed(st.medianCpu, 3) << ',' << fixed(st.medianWall / c.stages, 4)
            << ',' << fixed(speedup, 3) << ',' << samples << '\n';
    }

    // ---- targets (wall-clock medians; the CPU-time ratio is the one that load on the
    // machine disturbs least, since every case shares the cores with the same load)
    std::printf(
        "\n| catalogue | (a) / (b) -j %d | (a) / (b) -j 1 | (a) / (b) -j %d, CPU time | 10× target | "
        "no-op (d) median | 50 ms target |\n|---|---:|---:|---:|---|---:|---|\n",
        s.jobs, s.jobs);
    std::vector<std::string> notes;
    for (const auto& cat : catalogues) {
        const Stats a = statsOf(*findCase(cases, cat.name, "a"));
        const Stats b = statsOf(*findCase(cases, cat.name, "b"));
        const Case* b1 = findCase(cases, cat.name, "b1");
        const double rb = a.medianWall / b.medianWall;
        const std::string rb1 = b1 ? fixed(a.medianWall / statsOf(*b1).medianWall, 1) + "×" : "–";
        const double rcpu = a.medianCpu / b.medianCpu;
        const double td = statsOf(*findCase(cases, cat.name, "d")).medianWall;
        std::printf("| %s | %s× | %s | %s× | %s | %s ms | %s |\n", cat.name.c_str(), fixed(rb, 1).c_str(), rb1.c_str(),
                    fixed(rcpu, 1).c_str(), rb >= 10 ? "met" : "**not met**", fixed(td, 1).c_str(),
                    td < 50 ? "met" : "**not met**");
        // (f) re-runs the tool with unchanged inputs: it should cost about a no-op (d),
        // not a full generate (c). If it costs like (c), the fingerprint was not matched.
        const Case* f = findCase(cases, cat.name, "f");
        const double tc = statsOf(*findCase(cases, cat.name, "c")).medianCpu;
        if (f && statsOf(*f).medianCpu > 0.5 * tc)
            notes.push_back(cat.name + " (f) costs " + fixed(statsOf(*f).medianCpu, 1) +
                            " ms CPU, like a full generate (" + fixed(tc, 1) +
                            " ms): under prism_add_shaders() the up-to-date header was not recognised, "
                            "so glslang ran again");
    }
    for (const auto& n : notes) std::printf("\nNote: %s.\n", n.c_str());
    if (!cmakeNote.empty()) std::printf("\nNote: %s.\n", cmakeNote.c_str());
    for (const auto& p : std::set<std::string>(g_problems.begin(), g_problems.end()))
        std::printf("\nProblem: %s\n", p.c_str());
    std::printf("\nCSV: %s\n", fs::absolute(s.csv).c_str());

    if (!s.keep)
        fs::remove_all(work);
    else
        std::fprintf(stderr, "prism_bench_shaderc: kept %s\n", work.c_str());
    return g_problems.empty() ? 0 : 1;
}
