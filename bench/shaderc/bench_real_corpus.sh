#!/bin/bash
# Issue 36's corpus bench: the wall time of checking the real corpus's Vulkan programs
# (tests/shaderc/fixtures/real_corpus, the programs Prism and glslc both accept, broken_* copies left out)
# three ways, interleaved, median of RUNS: one prism-shaderc process per program; grouped runs, one
# process per codebase, include folders and target env, each program a --program; and glslc per stage
# (what a build calls today). Prints the table and the ratios with their targets.
#
#   bench/shaderc/bench_real_corpus.sh build/shaderc_tool/prism-shaderc [RUNS]
set -euo pipefail

tool=$(realpath "${1:?usage: $0 <prism-shaderc> [runs]}")
runs=${2:-5}
corpus=$(cd "$(dirname "$0")/../../tests/shaderc/fixtures/real_corpus" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
trap 'echo "$0: failed at line $LINENO" >&2' ERR
for program in glslc python3; do
    command -v "$program" >/dev/null || { echo "$0: $program not found (scripts/setup.sh installs it)" >&2; exit 2; }
done

# Three scripts from the case.json files, every path absolute. Not timed. Programs either tool refuses
# are left out, so each way checks the same programs.
python3 - "$tool" "$corpus" "$work" <<'PY'
import json, os, shlex, subprocess, sys
tool, corpus, work = sys.argv[1:]
single, glslc, groups, kept = [], [], {}, 0
for codebase in sorted(os.listdir(corpus)):
    if not os.path.isdir(os.path.join(corpus, codebase)): continue
    for name in sorted(os.listdir(os.path.join(corpus, codebase))):
        folder = os.path.join(corpus, codebase, name)
        if name == 'source' or name.startswith('broken_'): continue
        case = json.load(open(os.path.join(folder, 'case.json')))
        if case['client'] != 'vulkan': continue
        env = case['reference'].split('=')[1]
        stages = [os.path.normpath(os.path.join(folder, s)) for s in case['stages']]
        incs = [os.path.normpath(os.path.join(folder, d)) for d in case.get('include_dirs', [])]
        inc_args = [a for d in incs for a in ('-I', d)]
        per_stage = [['glslc', '--target-env=' + env] + inc_args + ['-c', '-o', '/dev/null', s] for s in stages]
        program = ['--program', codebase + '_' + name + '=' + ','.join(stages)]
        prism = [tool, '--check', '-j1', '--cache-dir', 'none', '--client', 'vulkan', '--target-env', env] + inc_args
        ok = subprocess.run(prism + program, capture_output=True).returncode == 0 and \
            all(subprocess.run(c, capture_output=True).returncode == 0 for c in per_stage)
        if not ok: continue
        kept += 1
        single.append(prism + program)
        glslc += per_stage
        groups.setdefault((codebase, env, tuple(incs)), prism[:]).extend(program)
write = lambda f, cmds: open(os.path.join(work, f), 'w').write('set -e\n' + ''.join(shlex.join(c) + ' >/dev/null\n' for c in cmds))
write('single.sh', single); write('glslc.sh', glslc); write('grouped.sh', groups.values())
open(os.path.join(work, 'counts'), 'w').write('%d %d %d\n' % (kept, len(glslc), len(groups)))
PY
read -r programs stages processes <"$work/counts"

wall() {  # wall-clock seconds of the command
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    end=$(date +%s.%N)
    awk -v s="$start" -v e="$end" 'BEGIN { printf "%.3f\n", e - s }'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

: >"$work/t_single"; : >"$work/t_grouped"; : >"$work/t_glslc"
for ((i = 0; i < runs; ++i)); do
    wall bash "$work/single.sh" >>"$work/t_single"
    wall bash "$work/grouped.sh" >>"$work/t_grouped"
    wall bash "$work/glslc.sh" >>"$work/t_glslc"
done
single=$(median <"$work/t_single"); grouped=$(median <"$work/t_grouped"); glslc=$(median <"$work/t_glslc")
echo "real corpus: $programs Vulkan programs both tools accept, $stages stages; wall seconds, median of $runs"
echo "| what | processes | wall s |"
echo "|---|---:|---:|"
echo "| glslc, one process per stage | $stages | $glslc |"
echo "| prism-shaderc --check -j1, one process per program | $programs | $single |"
echo "| prism-shaderc --check -j1, grouped (--program per program) | $processes | $grouped |"
awk -v g="$glslc" -v s="$single" -v p="$grouped" 'BEGIN {
    printf "glslc per stage / grouped prism-shaderc: %.1fx (target: >= 5x, issue 36)\n", g / p
    printf "glslc per stage / prism-shaderc per program: %.1fx (target: >= 1x)\n", g / s
}'
