#!/bin/bash
# Issue 25's targets bench (docs/shaderc-bench.md, "Targets"): the per-file chain a user would
# otherwise script, `glslc` per stage to SPIR-V and then `spirv-cross --es --version 300` per
# stage, over the flattened stages of the project catalogue, beside one
# `prism-shaderc --check --target gl,es300,spirv` process over the same catalogue; and that
# three-target check beside the gl-only one. CPU time (user + system, children included),
# median of RUNS runs each, interleaved. Prints both ratios with their targets.
#
#   bench/shaderc/bench_targets_chain.sh build/shaderc_tool/prism-shaderc [RUNS]
set -euo pipefail

tool=$(realpath "${1:?usage: $0 <prism-shaderc> [runs]}")
runs=${2:-5}
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
trap 'echo "$0: failed at line $LINENO" >&2' ERR
for program in glslc spirv-cross; do
    command -v "$program" >/dev/null || { echo "$0: $program not found (scripts/setup.sh installs it)" >&2; exit 2; }
done

check=(--check --cache-dir none -j1 -I "$source_dir/modules" --contract "$source_dir/modules/contract.json"
       "$source_dir/shader_sources")
# The chain starts from the stages as Prism flattens them (includes resolved, one file per
# variant and stage): what it would be handed. Not timed.
"$tool" "${check[@]}" --emit-glsl "$work/stages" >/dev/null
stages=$(find "$work/stages" -type f | wc -l)

cat >"$work/chain.sh" <<'CHAIN'
set -e  # a stage the chain cannot take stops the bench
# glslc has no relaxed Vulkan rules, so loose uniforms need its OpenGL environment.
for f in "$1"/*; do
    out="$2/${f##*/}"
    glslc --target-env=opengl -fauto-map-locations -fauto-bind-uniforms -fshader-stage="${f##*.}" -c "$f" -o "$out.spv"
    spirv-cross --es --version 300 "$out.spv" --output "$out.es"
done
CHAIN

cpu() {  # CPU seconds (user + system, children included) of the command
    /usr/bin/time -o "$work/time" -f "%U %S" "$@" >/dev/null 2>&1
    awk '{ printf "%.3f\n", $1 + $2 }' "$work/time"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

: >"$work/gl"; : >"$work/all"; : >"$work/chain"
for ((i = 0; i < runs; ++i)); do
    cpu "$tool" "${check[@]}" --target gl >>"$work/gl"
    cpu "$tool" "${check[@]}" --target gl,es300,spirv >>"$work/all"
    mkdir -p "$work/out"
    cpu bash "$work/chain.sh" "$work/stages" "$work/out" >>"$work/chain"
done
gl=$(median <"$work/gl"); all=$(median <"$work/all"); chain=$(median <"$work/chain")
echo "stages: $stages (project catalogue, every variant); CPU seconds, median of $runs"
echo "| what | CPU s |"
echo "|---|---|"
echo "| glslc + spirv-cross --es --version 300, per stage | $chain |"
echo "| prism-shaderc --check --target gl,es300,spirv | $all |"
echo "| prism-shaderc --check --target gl | $gl |"
awk -v c="$chain" -v a="$all" -v g="$gl" 'BEGIN {
    printf "chain / three-target check: %.1fx (target: >= 10x)\n", c / a
    printf "three-target check / gl check: %.1fx (target: <= 2x)\n", a / g
}'
