#!/bin/bash
# End-to-end check of `viewer --watch` (CTest example.viewer_watch): on a private Xvfb
# display, the viewer watches a temp copy of modules/ and shader_sources/; a broken
# module edit must be printed as `path:line:col: error:` and shown in the overlay, and
# undoing the edit must reload the shader and clear the overlay.
#   watch_smoke.sh VIEWER SOURCE_DIR WORK_DIR
set -u
viewer=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
cp -r "$source/modules" "$source/shader_sources" "$work/" || exit 1
log=$work/viewer.log
material=$work/modules/material.glsl
cp "$material" "$work/material.orig"

xvfb_pid='' viewer_pid=''
cleanup() {
    [ -n "$viewer_pid" ] && kill "$viewer_pid" 2>/dev/null
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
}
trap cleanup EXIT
fail() {
    echo "watch_smoke: FAIL: $*"
    echo "--- viewer log ---"
    cat "$log"
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

exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
exec 3>&-
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { echo "watch_smoke: Xvfb did not start"; cat "$work/xvfb.log"; exit 1; }

DISPLAY=":$(cat "$work/display")" "$viewer" --watch --source-root "$work" --screenshot "$work/last.png" \
    >"$log" 2>&1 &
viewer_pid=$!
wait_for '^viewer: watching [0-9]+ files' 60

# flat (the first shader shown) includes material.glsl; line 6 is new and broken.
printf 'vec3 broken = ;\n' >>"$material"
wait_for 'material\.glsl:6:[0-9]+: error: ' 30
wait_for '^viewer: overlay shows: modules/material\.glsl:6:' 5
grep -q '^viewer: reloaded' "$log" && fail "a broken edit was swapped in"

cp "$work/material.orig" "$material"
wait_for '^viewer: reloaded flat' 30
wait_for '^viewer: overlay cleared' 5

kill -TERM "$viewer_pid"
wait "$viewer_pid"
status=$?
viewer_pid=''
[ "$status" -eq 0 ] || fail "the viewer exited with status $status"
[ -s "$work/last.png" ] || fail "no screenshot written on SIGTERM"
echo "watch_smoke: OK"
cat "$log"
