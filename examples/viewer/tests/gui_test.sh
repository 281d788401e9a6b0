#!/usr/bin/env bash
# Driver of the viewer's gui-tier tests (tests/gui_tests.cmake): runs the viewer under
# xvfb-run (Mesa llvmpipe) and checks what it printed or drew.
#   gui_test.sh cli VIEWER                 --help/--version without a display; usage errors exit 2
#   gui_test.sh lit VIEWER WORK            first frame of the default view is lit
#   gui_test.sh panels VIEWER WORK         the controls column, its panels and the overlay
#   gui_test.sh script VIEWER WORK         switch_systems.script: shader, scene, rain intensity
#   gui_test.sh reference VIEWER WORK      the exact-sphere readout: phong beats flat
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
cli)
    out=$(env -u DISPLAY "$viewer" --help) || fail "--help exited $?"
    grep -q '^Usage: viewer' <<<"$out" || fail "--help printed no usage: $out"
    grep -q -- '--scene' <<<"$out" || fail "--help does not list --scene"
    out=$(env -u DISPLAY "$viewer" --version) || fail "--version exited $?"
    grep -q '^viewer (Prism) [0-9]' <<<"$out" || fail "--version printed '$out'"
    for bad in "--frames -1" "--subdivision 9" "--scene /nonexistent.json" "--variant BLINN" "--shader nosuch" \
               "--mesh nosuch" "extra"; do
        # shellcheck disable=SC2086
        env -u DISPLAY "$viewer" $bad >/dev/null 2>"$work/err.txt"
        status=$?
        [ "$status" -eq 2 ] || fail "'$bad' exited $status, not 2 (usage error)"
        grep -q '^viewer: error: ' "$work/err.txt" || fail "'$bad' printed no 'viewer: error:' line"
    done
    echo "gui_test cli: OK (--help, --version without DISPLAY; 7 usage errors exit 2)" ;;
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
*) fail "unknown mode" ;;
esac
