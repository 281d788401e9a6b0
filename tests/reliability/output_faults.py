#!/usr/bin/env python3
"""Output faults of prism-shaderc and prism-render (docs/reliability.md).

kill_while_writing: each tool is started again and again over an existing complete
output and killed with SIGKILL at random points of its run, and also the moment its
temp file appears (so the kill lands while it writes). After every kill the output
path must hold the old complete file or the new complete file, never a part; after
the next successful run no temp file may remain in the output directory.

write_failures: a full disk (a 32 KiB tmpfs) and a read-only directory (a read-only
bind mount, and a directory without write permission for a non-root user) must give
a clear error naming the file and the reason, a failing exit status, and leave
neither a partial output nor a temp file. Mounts are made in a private user and mount
namespace (unshare -Urm), so no root is needed; cases the machine cannot set up are
reported as skipped (exit 77 when all are).
"""
import argparse
import os
import random
import shutil
import signal
import subprocess
import sys
import time

SKIP = 77


def parse():
    p = argparse.ArgumentParser()
    p.add_argument("case", choices=["kill_while_writing", "write_failures"])
    p.add_argument("--shaderc", required=True)
    p.add_argument("--render", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--kills", type=int, default=16, help="random kills per tool")
    p.add_argument("--seed", type=int, default=int(time.time()))
    return p.parse_args()


class Tool:
    """One tool writing one output file, with an 'old' and a 'new' command line."""

    def __init__(self, name, out_name, command):
        self.name, self.out_name, self.command = name, out_name, command

    def run(self, out_dir, which, **kw):
        return subprocess.run(self.command(out_dir, which), capture_output=True, text=True, **kw)


def shaderc_tool(a):
    src = a.source
    stages = sorted(os.path.join(src, "shader_sources", f) for f in os.listdir(os.path.join(src, "shader_sources"))
                    if f.rsplit(".", 1)[-1] in ("vert", "frag", "geom", "comp"))

    def command(out_dir, which):
        return [a.shaderc, *stages, "-I", os.path.join(src, "modules"), "--contract",
                os.path.join(src, "modules", "contract.json"), "--namespace", "fault_" + which,
                "-o", os.path.join(out_dir, "shaders.hpp"), "-j", "1"]

    return Tool("prism-shaderc", "shaders.hpp", command)


def render_tool(a):
    def command(out_dir, which):
        color = "0.8,0.35,0.25" if which == "old" else "0.2,0.5,0.9"
        return [a.render, "--shader", "phong", "--mesh", "torus", "--size", "640x640", "--color", color,
                "--out", os.path.join(out_dir, "image.png")]

    return Tool("prism-render", "image.png", command)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def temps(out_dir, out_name):
    return [f for f in os.listdir(out_dir) if f.startswith(out_name + ".tmp")]


def stat_of(path):
    try:
        st = os.stat(path)
        return (st.st_ino, st.st_size, st.st_mtime_ns)
    except FileNotFoundError:
        return None


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def reference(tool, d):
    """The complete old and new outputs (written in `d` itself: prism-shaderc's banner
    names its output path) and the run time of a new run."""
    outputs = {}
    seconds = 0.0
    for which in ("old", "new"):
        started = time.monotonic()
        r = tool.run(d, which)
        seconds = time.monotonic() - started
        if r.returncode != 0:
            fail(f"{tool.name} {which} run failed: {r.stderr}")
        outputs[which] = read(os.path.join(d, tool.out_name))
    if outputs["old"] == outputs["new"]:
        fail(f"{tool.name}: old and new outputs are equal; the test could not tell them apart")
    return outputs, seconds


def kill_while_writing(a):
    rng = random.Random(a.seed)
    print(f"seed {a.seed}")
    for tool in (shaderc_tool(a), render_tool(a)):
        work = os.path.join(a.work, tool.name)
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        out_dir = os.path.join(work, "out")
        os.makedirs(out_dir)
        outputs, seconds = reference(tool, out_dir)
        out = os.path.join(out_dir, tool.out_name)
        seen = {"old": 0, "new": 0, "missing": 0}
        mid_write = 0  # kills that left a temp file: the kill landed while the tool wrote
        attempts = 0
        while attempts < a.kills or (mid_write == 0 and attempts < 4 * a.kills):
            attempts += 1
            first_run = attempts % 4 == 0  # sometimes no old file at all
            if first_run:
                if os.path.exists(out):
                    os.remove(out)
            else:
                with open(out, "wb") as f:
                    f.write(outputs["old"])
            p = subprocess.Popen(tool.command(out_dir, "new"), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            if attempts % 2:  # at a random point of the run
                time.sleep(rng.uniform(0.2, 1.1) * seconds)
            else:  # the moment the tool starts writing: a temp file appears or the output changes
                before = stat_of(out)
                deadline = time.monotonic() + 3 * seconds + 5
                while (p.poll() is None and not temps(out_dir, tool.out_name) and stat_of(out) == before
                       and time.monotonic() < deadline):
                    time.sleep(0.0002)
            p.send_signal(signal.SIGKILL)
            p.wait()
            if temps(out_dir, tool.out_name):
                mid_write += 1
            if not os.path.exists(out):
                if not first_run:
                    fail(f"{tool.name}: the old output vanished after a kill")
                seen["missing"] += 1
                continue
            content = read(out)
            if content == outputs["old"] and not first_run:
                seen["old"] += 1
            elif content == outputs["new"]:
                seen["new"] += 1
            else:
                fail(f"{tool.name}: after SIGKILL {out} holds {len(content)} bytes that are neither the old "
                     f"({len(outputs['old'])}) nor the new ({len(outputs['new'])}) complete output")
        if mid_write == 0:
            fail(f"{tool.name}: no kill in {attempts} landed while the temp file existed; the test proved nothing")
        left = temps(out_dir, tool.out_name)
        r = tool.run(out_dir, "new")
        if r.returncode != 0:
            fail(f"{tool.name}: the run after the kills failed: {r.stderr}")
        if read(out) != outputs["new"]:
            fail(f"{tool.name}: the run after the kills wrote a wrong output")
        if temps(out_dir, tool.out_name):
            fail(f"{tool.name}: temp files left after a successful run: {temps(out_dir, tool.out_name)}")
        # The next run has nothing to change (same content) and must still clean up.
        with open(os.path.join(out_dir, tool.out_name + (".tmp.999999999" if tool.name == "prism-shaderc"
                                                            else ".tmp-999999999")), "wb") as f:
            f.write(b"partial")
        if tool.run(out_dir, "new").returncode != 0 or temps(out_dir, tool.out_name):
            fail(f"{tool.name}: an unchanged-output run left a dead writer's temp file")
        print(f"{tool.name}: {attempts} kills ({mid_write} while the temp file existed): old complete "
              f"{seen['old']}, new complete {seen['new']}, no file yet {seen['missing']}; "
              f"{len(left)} temp files before the next run, 0 after")


def in_namespace(script, *args):
    """Runs a shell script as root of a private user+mount namespace."""
    return subprocess.run(["unshare", "-Urm", "sh", "-c", script, "sh", *args], capture_output=True, text=True)


def write_failures(a):
    ran = 0
    probe = os.path.join(a.work, "probe")
    os.makedirs(probe, exist_ok=True)
    namespaces = in_namespace('mount -t tmpfs -o size=32k tmpfs "$1"', probe).returncode == 0
    run_and_list = 'dir=$1; shift; "$@"; s=$?; echo; ls -A "$dir" | tr "\\n" " "; exit $s'
    for tool in (shaderc_tool(a), render_tool(a)):
        work = os.path.join(a.work, tool.name)
        shutil.rmtree(work, ignore_errors=True)
        out_dir = os.path.join(work, "out")
        os.makedirs(out_dir)
        cmd = tool.command(out_dir, "new")
        checks = []
        if namespaces:
            # Full disk: a 32 KiB tmpfs filled but for 4 KiB (the outputs are far larger).
            checks.append(("full disk", 'mount -t tmpfs -o size=32k tmpfs "$1" || exit 90; '
                           'dd if=/dev/zero of="$1/filler" bs=4k count=7 2>/dev/null; ' + run_and_list,
                           "No space left on device"))
            checks.append(("read-only bind mount",
                           'mount --bind "$1" "$1" && mount -o remount,bind,ro "$1" || exit 90; ' + run_and_list,
                           "Read-only file system"))
        for name, script, reason in checks:
            r = in_namespace(script, out_dir, *cmd)
            if r.returncode == 90:
                fail(f"{tool.name}, {name}: could not set up the mount: {r.stderr}")
            ran += 1
            listing = r.stdout.strip().splitlines()[-1].split() if r.stdout.strip() else []
            listing = [f for f in listing if f != "filler"]
            if r.returncode == 0:
                fail(f"{tool.name}, {name}: exit status 0")
            # prism-shaderc writes a header and its data file (shaders.cpp): either may be named.
            named = tool.out_name in r.stderr or (tool.name == "prism-shaderc" and "shaders.cpp" in r.stderr)
            if reason not in r.stderr or not named:
                fail(f"{tool.name}, {name}: the error does not name the file and '{reason}': {r.stderr!r}")
            if listing:
                fail(f"{tool.name}, {name}: left {listing} in the output directory")
            print(f"{tool.name}, {name}: exit {r.returncode}: {r.stderr.strip().splitlines()[-1]}")
        # A directory the (non-root) user may not write to.
        nobody = shutil.which("setpriv") and os.geteuid() == 0
        if nobody:
            locked = os.path.join(work, "locked")
            os.makedirs(locked)
            os.chmod(locked, 0o555)
            for d in (a.work, work):
                os.chmod(d, 0o755)
            r = subprocess.run(["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups", "--",
                                *tool.command(locked, "new")], capture_output=True, text=True)
            ran += 1
            if r.returncode == 0 or "Permission denied" not in r.stderr or tool.out_name not in r.stderr:
                fail(f"{tool.name}, no write permission: status {r.returncode}, error {r.stderr!r}")
            if os.listdir(locked):
                fail(f"{tool.name}, no write permission: left {os.listdir(locked)}")
            print(f"{tool.name}, no write permission (as nobody): exit {r.returncode}: "
                  f"{r.stderr.strip().splitlines()[-1]}")
    if ran == 0:
        print("SKIP: neither user namespaces (unshare -Urm) nor setpriv as root are available")
        sys.exit(SKIP)


def main():
    a = parse()
    a.work = os.path.abspath(a.work)
    os.makedirs(a.work, exist_ok=True)
    if a.case == "kill_while_writing":
        kill_while_writing(a)
    else:
        write_failures(a)


if __name__ == "__main__":
    main()
