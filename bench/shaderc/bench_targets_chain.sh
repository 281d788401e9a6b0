#!/bin/bash
# Issue 25's targets bench (docs/shaderc-bench.md, "Targets"): the per-file chain a user would
# otherwise script, `glslc` per stage to SPIR-V and then `spirv-cross --es --version 300` per
# stage, over the flattened stages of the project catalogue, beside one
# `prism-shaderc --check --target gl,es300,spirv` process over the same catalogue; and that
# three-target check beside the gl-only one. Then the loop a user repeats: a re-check after
# an edit of one stage file, with the validation cache (--cache-dir) warm, three targets
# beside gl. CPU time (user + system, children included), median of RUNS runs each,
# interleaved. Prints the ratios with their targets.
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
# What bounds the second ratio: the CPU time of SPIRV-Tools' validator alone in the
# three-target check (its --stats line), beside the whole gl check.
: >"$work/validator"
for ((i = 0; i < runs; ++i)); do
    "$tool" "${check[@]}" --target gl,es300,spirv --stats 2>&1 >/dev/null |
        sed -n 's/.*SPIRV-Tools validated \([0-9]*\) modules in \([0-9]*\) ms of CPU/\1 \2/p' >>"$work/validator"
done
modules=$(awk 'NR == 1 { print $1 }' "$work/validator")
validator=$(awk '{ print $2 / 1000 }' "$work/validator" | median)
awk -v v="$validator" -v g="$gl" -v m="$modules" 'BEGIN {
    printf "SPIRV-Tools validator alone in the three-target check: %.3f CPU s over %d modules, %.2fx the whole gl check\n", v, m, v / g
}'

# A re-check after an edit: a copy of the catalogue, each target list's cache warmed once;
# then per round one token-changing line appended to phong.frag (60 of the 152 programs
# include it), and each target list checks it once, with its own cache pack.
cp -r "$source_dir/shader_sources" "$source_dir/modules" "$work/"
edit=(--check --cache-dir "$work/cache" -j1 -I "$work/modules" --contract "$work/modules/contract.json"
      "$work/shader_sources")
"$tool" "${edit[@]}" --target gl >/dev/null
"$tool" "${edit[@]}" --target gl,es300,spirv >/dev/null
: >"$work/gl_edit"; : >"$work/all_edit"
for ((i = 0; i < runs; ++i)); do
    echo "const float benchEdit$i = 1.0;" >>"$work/shader_sources/phong.frag"
    cpu "$tool" "${edit[@]}" --target gl >>"$work/gl_edit"
    cpu "$tool" "${edit[@]}" --target gl,es300,spirv >>"$work/all_edit"
done
gl_edit=$(median <"$work/gl_edit"); all_edit=$(median <"$work/all_edit")
echo
echo "a re-check after editing phong.frag (60 of 152 programs), cache warm; CPU seconds, median of $runs"
echo "| what | CPU s |"
echo "|---|---|"
echo "| prism-shaderc --check --target gl,es300,spirv | $all_edit |"
echo "| prism-shaderc --check --target gl | $gl_edit |"
awk -v a="$all_edit" -v g="$gl_edit" 'BEGIN {
    printf "three-target re-check / gl re-check: %.1fx (target: <= 2x)\n", a / g
}'
