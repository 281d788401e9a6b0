#!/usr/bin/env python3
"""bench_noop_outputs: the no-op of the project catalogue with every output, beside a header-only one.

Issue 39, "Done when": in one run, prints the median wall time of prism-shaderc with nothing
changed, for
  - the project catalogue exactly as the build runs it: the command line is taken from the
    build tree's build.ninja (-o, --depfile, --stamp, --target, --emit-web, ...), run in place;
  - the same catalogue writing its header only: the same command without the --emit-*
    options, its -o, --depfile and --stamp moved into a temporary directory;
their ratio, and the targets beside them (<= 20 ms median; every output <= 1.5x header only).
Each command runs once first (a stale build or a new tool build regenerates then), and then
--runs times. Prints a Markdown table; docs/shaderc.md quotes it.

    bench_noop_outputs.py --build build [--runs 9]
"""
import argparse
import os
import resource
import shlex
import statistics
import subprocess
import sys
import tempfile
import time

TARGET_NOOP_MS = 20.0
TARGET_RATIO = 1.5
EMIT_OPTIONS = ("--emit-web", "--emit-glsl", "--emit-spirv", "--emit-reflection")


def project_command(build):
    """(cwd, argv) of the build.ninja rule that writes prism/shaders.hpp."""
    with open(os.path.join(build, "build.ninja"), encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if line.startswith("COMMAND = cd ") and "--namespace prism::shaders " in line:
                step = line[len("COMMAND = "):].split(" && ")
                return step[0][len("cd "):], shlex.split(step[1])
    sys.exit("bench_noop_outputs: no prism-shaderc step for prism::shaders in %s/build.ninja" % build)


def header_only(argv, scratch):
    """The same catalogue without the --emit-* options, writing into `scratch`."""
    moved = {"-o": "shaders.hpp", "--depfile": "shaders.d", "--stamp": "shaders.stamp"}
    out, i = [argv[0]], 1
    while i < len(argv):
        if argv[i] in EMIT_OPTIONS:
            i += 2
            continue
        out.append(argv[i])
        if argv[i] in moved:
            out.append(os.path.join(scratch, moved[argv[i]]))
            i += 1
        i += 1
    return out


def cpu_s():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def median_ms(cwd, argv, runs):
    """Medians of wall and CPU (user + system) time of `runs` runs, after one that brings the
    outputs up to date. The CPU time stays meaningful on a loaded machine, the wall time not."""
    subprocess.run(argv, cwd=cwd, check=True, stdout=subprocess.DEVNULL)
    times, cpu = [], []
    for _ in range(runs):
        t0, c0 = time.perf_counter(), cpu_s()
        p = subprocess.run(argv + ["--stats"], cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        times.append((time.perf_counter() - t0) * 1000.0)
        cpu.append((cpu_s() - c0) * 1000.0)
        if p.returncode != 0 or p.stdout:  # --stats: a run that resolved says so
            sys.exit("bench_noop_outputs: not a quiet no-op (%d): %s\n%s" % (p.returncode, " ".join(argv), p.stdout))
    return statistics.median(times), statistics.median(cpu)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True, help="a configured and built Ninja build tree")
    parser.add_argument("--runs", type=int, default=9, help="timed runs of each command (at least 7)")
    args = parser.parse_args()
    if args.runs < 7:
        sys.exit("bench_noop_outputs: --runs must be at least 7")
    cwd, argv = project_command(args.build)
    emitted = [a for a in argv if a in EMIT_OPTIONS]
    with tempfile.TemporaryDirectory(prefix="prism-noop-") as scratch:
        every, every_cpu = median_ms(cwd, argv, args.runs)
        header, header_cpu = median_ms(cwd, header_only(argv, scratch), args.runs)
    ratio = every / header
    print("| no-op of the project catalogue (median of %d) | wall ms | CPU ms | target |" % args.runs)
    print("|---|---:|---:|---|")
    print("| every output, as build.ninja runs it (-o, %s) | %.1f | %.1f | <= %.0f ms |"
          % (", ".join(emitted) or "no emit", every, every_cpu, TARGET_NOOP_MS))
    print("| header only (the same command without --emit-*) | %.1f | %.1f | <= %.0f ms |"
          % (header, header_cpu, TARGET_NOOP_MS))
    print("| every output / header only | %.2fx | %.2fx | <= %.1fx |" % (ratio, every_cpu / header_cpu, TARGET_RATIO))
    met = every <= TARGET_NOOP_MS and header <= TARGET_NOOP_MS and ratio <= TARGET_RATIO
    print("\ntargets %s" % ("met" if met else "NOT met"))


if __name__ == "__main__":
    main()
