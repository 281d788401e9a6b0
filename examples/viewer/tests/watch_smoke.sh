#!/bin/bash
# End-to-end check of `viewer --watch` (CTest example.viewer_watch): on a private Xvfb
# display. Without --source-root the viewer watches the tree the catalogue was built from;
# in the runs that edit, it watches a temp copy of modules/ and shader_sources/.
#   1. A broken module edit is printed as `path:line:col: error:` and put in the overlay;
#      undoing the edit reloads the shader and clears the overlay; the last frame (written
#      on SIGTERM) has no overlay.
#   2. In a second run, the last frame after a broken edit shows the overlay's red strip.
#   watch_smoke.sh VIEWER SOURCE_DIR WORK_DIR
set -u
viewer=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
cp -r "$source/modules" "$source/shader_sources" "$work/" || exit 1
material=$work/modules/material.glsl
cp "$material" "$work/material.orig"
log='' xvfb_pid='' viewer_pid=''

cleanup() {
    [ -n "$viewer_pid" ] && kill "$viewer_pid" 2>/dev/null
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
}
trap cleanup EXIT
fail() {
    echo "watch_smoke: FAIL: $*"
    [ -n "$log" ] && { echo "--- $log ---"; cat "$log"; }
    exit 1
}
# Waits up to $2 seconds for the extended regex $1 in the log.
wait_for() {
    for _ in $(seq $(($2 * 10))); do
        grep -Eq "$1" "$log" && return 0
        kill -0 "$viewer_pid" 2>/dev/null || fail "the viewer exited while waiting for /$1/"
        sleep 0.1
    done
    fail "no /$1/ within $2 s"
}
start_viewer() {  # $1: name of the run; the rest: more options
    local name=$1
    shift
    log=$work/$name.log
    DISPLAY=":$(cat "$work/display")" "$viewer" --watch "$@" --screenshot "$work/$name.png" >"$log" 2>&1 &
    viewer_pid=$!
    wait_for '^viewer: watching [0-9]+ files' 60
}
stop_viewer() {
    kill -TERM "$viewer_pid"
    wait "$viewer_pid"
    local status=$?
    viewer_pid=''
    [ "$status" -eq 0 ] || fail "the viewer exited with status $status"
}
# Prints the top-left pixel of an 8-bit RGB(A) PNG as "r g b" (row 0's first pixel is
# stored unfiltered whatever the row's filter type).
top_left_pixel() {
    python3 - "$1" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
pos, idat, colour_type = 8, b"", None
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR":
        colour_type = body[9]
        assert body[8] == 8 and colour_type in (2, 6), "expected an 8-bit RGB or RGBA PNG"
    elif kind == b"IDAT":
        idat += body
    pos += 12 + length
raw = zlib.decompressobj().decompress(idat, 16)
print(raw[1], raw[2], raw[3])
PY
}

exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
exec 3>&-
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { echo "watch_smoke: Xvfb did not start"; cat "$work/xvfb.log"; exit 1; }

overlay_red="110 16 16"  # error_overlay.cpp's strip colour

# 0. Without --source-root the viewer watches the tree its catalogue records (kSourceTree):
#    the checkout it was built from. Nothing is edited there.
start_viewer recorded
watched=$(sed -n 's/^viewer: watching [0-9]* files under //p' "$log")
[ "$watched" = "$source" ] || fail "--watch watches '$watched', not the catalogue's recorded tree '$source'"
stop_viewer
echo "watch_smoke: run 0 OK (--watch alone watches the recorded tree $watched)"

# 1. phong (the first shader shown) includes material.glsl; line 6 is new and broken.
start_viewer recover --source-root "$work"
printf 'vec3 broken = ;\n' >>"$material"
wait_for 'material\.glsl:6:[0-9]+: error: ' 30
wait_for '^viewer: overlay shows: modules/material\.glsl:6:' 5
grep -q '^viewer: reloaded' "$log" && fail "a broken edit was swapped in"
cp "$work/material.orig" "$material"
wait_for '^viewer: reloaded phong' 30
wait_for '^viewer: overlay cleared' 5
stop_viewer
pixel=$(top_left_pixel "$work/recover.png") || fail "cannot read $work/recover.png"
[ "$pixel" != "$overlay_red" ] || fail "the overlay is still drawn after the fix"
echo "watch_smoke: run 1 OK (error printed and overlaid, fix reloaded, overlay gone: top-left pixel $pixel)"

# 2. The overlay is really drawn in the window.
start_viewer overlay --source-root "$work"
printf 'vec3 broken = ;\n' >>"$material"
wait_for '^viewer: overlay shows: ' 30
sleep 0.5  # a few frames with the overlay
stop_viewer
pixel=$(top_left_pixel "$work/overlay.png") || fail "cannot read $work/overlay.png"
[ "$pixel" = "$overlay_red" ] || fail "top-left pixel $pixel, not the overlay's $overlay_red"
echo "watch_smoke: run 2 OK (the window's top-left pixel is the overlay's $pixel)"
cat "$work/recover.log"
