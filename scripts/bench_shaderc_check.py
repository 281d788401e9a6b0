#!/usr/bin/env python3
"""Validation speed of `prism-shaderc --check` against one glslangValidator process
over the same flattened stage files (issue 10 item 7; docs/shaderc-bench.md,
"Validation speed").

The project catalogue (shader_sources/*.vert|frag, modules/, modules/contract.json,
every variant) is copied to a scratch directory; `prism-shaderc --emit-glsl` writes
its flattened stages, which glslangValidator is given in one process. Cases, run
interleaved (one round runs each case once), timed as whole processes:

  (g)  glslangValidator FILES...          the reference, one process over all files
  (c2) prism-shaderc --check -j 2         cold: the validation cache is emptied first
  (c1) prism-shaderc --check -j 1         cold, one thread
  (rc) re-check after a code edit of modules/lighting.glsl (a new function, so every
       stage including it has a new token stream), cache warm from before the edit
  (rn) re-check after a comment-only edit of modules/lighting.glsl, cache warm

Prints a Markdown table with medians of wall-clock and CPU (user + sys) time and the
ratio (g)/case next to its target (the target is on wall-clock time).

  python3 scripts/bench_shaderc_check.py --shaderc build/shaderc_tool/prism-shaderc --runs 7 \
      [--baseline OLD/prism-shaderc]
"""
import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


CPU = [0.0]  # CPU seconds (user + sys) of the last run()'s process


def run(cmd, cwd=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    CPU[0] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return proc.returncode, proc.stdout, elapsed


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--shaderc", default=os.path.join(ROOT, "build/shaderc_tool/prism-shaderc"))
    ap.add_argument("--glslang", default=shutil.which("glslangValidator") or "glslangValidator")
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--keep", action="store_true", help="keep the scratch directory")
    ap.add_argument("--baseline", help="another prism-shaderc (e.g. built from an older commit) to time as "
                    "(b): `--check -j 2` without the cache flags")
    args = ap.parse_args()

    work = tempfile.mkdtemp(prefix="prism-bench-check-")
    try:
        shutil.copytree(os.path.join(ROOT, "modules"), os.path.join(work, "modules"))
        os.makedirs(os.path.join(work, "shaders"))
        src = os.path.join(ROOT, "shader_sources")
        for name in sorted(os.listdir(src)):
            if name.endswith((".vert", ".frag")):
                shutil.copy(os.path.join(src, name), os.path.join(work, "shaders", name))
        lighting = os.path.join(work, "modules", "lighting.glsl")
        with open(lighting) as f:
            lighting_text = f.read()
        cache = os.path.join(work, "cache")
        common = ["-I", "modules", "--contract", "modules/contract.json", "shaders"]

        rc, out, _ = run([args.shaderc, "--check", "--emit-glsl", "flat", "--cache-dir", "none"] + common, work)
        if rc != 0:
            sys.exit("prism-shaderc --emit-glsl failed:\n" + out)
        files = sorted(os.path.join("flat", f) for f in os.listdir(os.path.join(work, "flat")))
        rc, out, _ = run([args.glslang] + files, work)
        if rc != 0:
            sys.exit("glslangValidator rejects the flattened files:\n" + out[-2000:])

        check = lambda jobs: [args.shaderc, "--check", "--stats", "-j", str(jobs), "--cache-dir", cache] + common
        edit_no = [0]

        def edit(kind):
            edit_no[0] += 1
            n = edit_no[0]
            extra = (f"float prismBenchEdit{n}() {{ return {n}.0; }}\n" if kind == "code"
                     else f"// bench edit {n}\n")
            with open(lighting, "w") as f:
                f.write(lighting_text + extra)

        def restore():
            with open(lighting, "w") as f:
                f.write(lighting_text)

        stats = {}

        def case_g():
            return run([args.glslang] + files, work)

        def cold(jobs):
            shutil.rmtree(cache, ignore_errors=True)
            return run(check(jobs), work)

        def recheck(kind):
            restore()
            run(check(2), work)  # warm the cache for the unedited sources (untimed)
            edit(kind)
            result = run(check(2), work)
            restore()
            return result

        cases = [
            ("(g) glslangValidator, one process, all flattened files", case_g, None),
            ("(c2) prism-shaderc --check -j 2, cold cache", lambda: cold(2), 2.0),
            ("(c1) prism-shaderc --check -j 1, cold cache", lambda: cold(1), 2.0),
            ("(rc) re-check after a code edit of lighting.glsl", lambda: recheck("code"), 10.0),
            ("(rn) re-check after a comment-only edit of lighting.glsl", lambda: recheck("comment"), 10.0),
        ]
        if args.baseline:
            cases.insert(1, ("(b) baseline prism-shaderc --check -j 2 (--baseline)",
                             lambda: run([args.baseline, "--check", "-j", "2"] + common, work), None))
        times = {name: [] for name, _, _ in cases}
        cpu = {name: [] for name, _, _ in cases}
        for name, fn, _ in cases:  # warm-up round
            fn()
        for _ in range(args.runs):
            for name, fn, _ in cases:
                rc, out, elapsed = fn()
                if rc != 0:
                    sys.exit(f"{name} failed:\n{out[-2000:]}")
                times[name].append(elapsed)
                cpu[name].append(CPU[0])
                for line in out.splitlines():
                    if line.startswith("prism-shaderc: validated"):
                        stats[name] = line[len("prism-shaderc: "):]

        load = os.getloadavg()
        print(f"Catalogue: {len(files)} flattened stage files (shader_sources/, every variant); "
              f"{args.runs} interleaved runs per case after a warm-up; nproc = {os.cpu_count()}, "
              f"load average {load[0]:.2f}.")
        print()
        print("| case | median ms | min ms | (g) / case | target | met | CPU ms (median) | (g) / case, CPU | "
              "prism-shaderc --stats |")
        print("|---|---:|---:|---:|---:|---|---:|---:|---|")
        ref_cpu = statistics.median(cpu[cases[0][0]])
        ref = statistics.median(times[cases[0][0]])
        for name, _, target in cases:
            med = statistics.median(times[name])
            ratio = ref / med
            met = "" if target is None else ("yes" if ratio >= target else "**no**")
            tgt = "" if target is None else f"≥ {target:g}×"
            med_cpu = statistics.median(cpu[name])
            print(f"| {name} | {med * 1000:.1f} | {min(times[name]) * 1000:.1f} | {ratio:.2f}× | {tgt} | {met} | "
                  f"{med_cpu * 1000:.1f} | {ref_cpu / med_cpu:.2f}× | {stats.get(name, '')} |")
    finally:
        if args.keep:
            print(f"\nscratch directory kept: {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
