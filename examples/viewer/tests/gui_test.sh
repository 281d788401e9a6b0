#!/usr/bin/env bash
# Driver of the viewer's gui-tier tests (tests/gui_tests.cmake): runs the viewer under
# xvfb-run (Mesa llvmpipe) and checks what it printed or drew.
#   gui_test.sh lit VIEWER WORK            first frame of the default view is lit
#   gui_test.sh panels VIEWER WORK         the controls column, its panels and the overlay
#   gui_test.sh script VIEWER WORK         switch_systems.script: shader, scene, rain intensity
#   gui_test.sh reference VIEWER WORK      the exact-sphere readout: phong beats flat
#   gui_test.sh sampling VIEWER WORK       the soft-shadow readout: blue noise and spp pay off
set -u
mode=$1 viewer=$2 work=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "gui_test $mode: FAIL: $*"; exit 1; }
run() {  # run NAME ARGS...: the viewer under xvfb-run, output in $work/NAME.log
    local name=$1; shift
    LP_NUM_THREADS=2 LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x1024x24" "$viewer" "$@" \
        >"$work/$name.log" 2>&1
    local status=$?
    cat "$work/$name.log"
    return $status
}
[ -n "$work" ] && { rm -rf "$work"; mkdir -p "$work"; }
case $mode in
lit)
    run lit --frames 3 --no-panels --width 400 --height 400 --screenshot "$work/lit.png" || fail "viewer exited $?"
    # Thresholds: the lit default measures luminance ~78 and ~5000 colours; the unlit
    # DIRECTIONAL_LIGHTS=0 variant (the old default) 19 and 2 colours.
    python3 "$here/png_stats.py" lit "$work/lit.png" 40 200 || fail "the first frame is not lit" ;;
panels)
    run panels --frames 3 --width 1100 --height 760 --screenshot "$work/panels.png" || fail "viewer exited $?"
    # The controls column is kPanelWidth (330) px wide with 8 panel headers + the window title bar.
    python3 "$here/png_stats.py" panels "$work/panels.png" 330 8 || fail "the panel layout is off" ;;
script)
    run script --script "$here/switch_systems.script" --screenshot "$work/script.png" || fail "viewer exited $?"
    log=$work/script.log
    grep -q '^viewer: program gouraud ' "$log" || fail "the shader switch to gouraud never ran gouraud"
    heavy=$(grep -o 'rain gs-quads ([0-9]* particles)' "$log" | sed -n 1p | tr -dc 0-9)
    drizzle=$(grep -o 'rain gs-quads ([0-9]* particles)' "$log" | sed -n 2p | tr -dc 0-9)
    [ -n "$heavy" ] && [ -n "$drizzle" ] || fail "the rain scene's program line never named two rain draws"
    [ "$drizzle" -lt "$heavy" ] || fail "drizzle draws $drizzle particles, heavy rain $heavy"
    grep -q '^viewer: error: .*rain: wind strength must be a finite number' "$log" ||
        fail "the rejected wind was not reported"
    sed -n '/script line [0-9]*: scene none/,$p' "$log" | grep -q '^viewer: program phong BLINN=1,' ||
        fail "closing the scene did not bring back the catalogue program"
    echo "gui_test script: OK (heavy rain $heavy particles, drizzle $drizzle)" ;;
reference)
    run reference --script "$here/reference.script" || fail "viewer exited $?"
    means=$(grep -o 'vs exact sphere ([0-9x]*): mean [0-9.]*' "$work/reference.log" | sed 's/.* //')
    phong=$(sed -n 2p <<<"$means") flat=$(sed -n 3p <<<"$means")
    [ -n "$phong" ] && [ -n "$flat" ] || fail "no readouts for phong and flat at subdivision 4"
    python3 -c "import sys; p, f = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if p < 0.5 and f > 3 * p else 1)" \
        "$phong" "$flat" || fail "phong's mean error $phong is not below 0.5 and a third of flat's $flat"
    grep -q 'no reference for mesh torus' "$work/reference.log" || fail "the torus got an exact-sphere readout"
    echo "gui_test reference: OK (mean error phong $phong, flat $flat 8-bit units)" ;;
sampling)
    run sampling --script "$here/sampling.script" || fail "viewer exited $?"
    log=$work/sampling.log
    rms() { awk -v n="script line $1:" 'index($0, n) { on = 1; next } /script line/ { on = 0 } on' "$log" | grep -o 'RMS [0-9.]*, blurred RMS [0-9.]*' | head -1; }
    white=$(rms 5) blue=$(rms 7) blue16=$(rms 9)  # the lines of sampling.script
    [ -n "$white" ] && [ -n "$blue" ] && [ -n "$blue16" ] || fail "missing readouts: '$white' '$blue' '$blue16'"
    python3 - "$white" "$blue" "$blue16" <<'PY' || fail "the readouts do not show the samplers' trade"
import re, sys
white, blue, blue16 = ([float(v) for v in re.findall(r"[0-9]+[.][0-9]+", a)] for a in sys.argv[1:4])
print(f"white 1 spp {white}, blue noise 1 spp {blue}, blue noise 16 spp {blue16} (RMS, blurred RMS)")
# Blue noise moves the error to high frequencies: blurred, it is well below white noise's.
# 16 spp cut the plain RMS by about 4 (sqrt 16) or more.
sys.exit(0 if blue[1] * 1.5 < white[1] and blue16[0] * 4 < blue[0] else 1)
PY
    grep -q ', 1 sampling references rendered' "$log" || fail "the reference was not rendered exactly once"
    echo "gui_test sampling: OK" ;;
*) fail "unknown mode" ;;
esac
