#!/usr/bin/env python3
"""Flags are never silently ignored (issue 15): runs prism-gallery, prism-rain and water with
flags that the chosen mode would not use and expects a usage error (exit 2) naming the flag;
runs the modes that do use them and expects their output. A coverage check reads each
program's --help and fails when one of its flags has no case here, so a new flag needs a
case. (prism-render, prism-bluenoise and prism-diffraction have their cases next to their
other CLI tests: tests/rendering, tests/bluenoise, tests/diffraction.)

    python3 tests/flags/check_flags.py --bin prism-gallery=PATH --bin prism-rain=PATH --bin water=PATH --tmp DIR
"""
import argparse
import os
import re
import shutil
import struct
import subprocess
import sys

# (program, arguments ({D} = a fresh output folder), exit status, stderr regex, files that must exist)
CASES = [
    # prism-gallery: every flag is used; bad values and unknown flags are usage errors.
    ("prism-gallery", ["--out", "{D}", "--size", "16", "--backend", "egl"], 0, "", ["{D}/gallery.png", "{D}/catalogue.tsv"]),
    ("prism-gallery", ["--out", "{D}", "--backend", "glfw"], 2, "--backend glfw: expected egl or osmesa", []),
    ("prism-gallery", ["--out", "{D}", "--size", "8"], 2, "--size", []),
    ("prism-gallery", ["--out", "{D}", "--bogus"], 2, "--bogus", []),
    # prism-rain: --intensity, --wind, --fog apply to --view, --sequence and --window only.
    ("prism-rain", ["--view", "1", "--intensity", "heavy", "--wind", "2", "--wind-direction", "90", "--fog",
                    "--fog-strength", "0.3", "--technique", "points", "--seed", "4", "--width", "32", "--height", "32",
                    "--warmup", "1", "--out", "{D}"], 0, "", ["{D}/rain.png"]),
    ("prism-rain", ["--sequence", "3", "--width", "32", "--height", "24", "--warmup", "1", "--out", "{D}"], 0, "",
     ["{D}/frame_00.png", "{D}/frame_02.png", "{D}/sequence.png"]),
    ("prism-rain", ["--intensity", "heavy", "--out", "{D}"], 2, "--intensity needs --view, --sequence or --window", []),
    ("prism-rain", ["--wind", "3", "--out", "{D}"], 2, "--wind needs --view", []),
    ("prism-rain", ["--fog", "--out", "{D}"], 2, "--fog needs --view", []),
    ("prism-rain", ["--view", "0", "--fog-strength", "0.3", "--out", "{D}"], 2, "--fog-strength needs --fog", []),
    ("prism-rain", ["--frames", "3", "--out", "{D}"], 2, "--frames needs --window", []),
    ("prism-rain", ["--demo-keys", "--out", "{D}"], 2, "--demo-keys needs --window", []),
    ("prism-rain", ["--window", "--sequence", "2"], 2, "--sequence does not apply to --window", []),
    ("prism-rain", ["--window", "--out", "{D}"], 2, "--out does not apply to --window", []),
    ("prism-rain", ["--window", "--view", "0"], 2, "--view does not apply to --window", []),
    ("prism-rain", ["--window", "--warmup", "3"], 2, "--warmup does not apply to --window", []),
    ("prism-rain", ["--window", "--intensity", "0.5"], 2, "with --window, --intensity must name a class", []),
    ("prism-rain", ["--sequence", "0", "--out", "{D}"], 2, "--sequence", []),
    # water: terrain, permeability and window flags only where they are used.
    ("water", ["--sequence", "3", "--grid", "16", "--cell", "0.5", "--steps", "6", "--dt", "1", "--rain", "heavy",
               "--fog", "0.01", "--width", "32", "--height", "24", "--out", "{D}"], 0, "",
     ["{D}/frame_00.png", "{D}/frame_02.png", "{D}/sequence.png"]),
    ("water", ["--grid", "16", "--steps", "2", "--gpu", "--width", "32", "--height", "24", "--out", "{D}"], 0, "",
     ["{D}/overview.png", "{D}/depth.png"]),
    ("water", ["--grid", "16", "--frames", "3", "--out", "{D}"], 2, "--frames needs --window", []),
    ("water", ["--grid", "16", "--height-scale", "3", "--out", "{D}"], 2, "--height-scale needs --heightmap", []),
    ("water", ["--grid", "16", "--permeability-max", "5", "--out", "{D}"], 2, "--permeability-max needs --permeability", []),
    ("water", ["--heightmap", "h.png", "--grid", "16", "--out", "{D}"], 2, "does not apply to --heightmap", []),
    ("water", ["--permeability", "p.png", "--grid", "16", "--out", "{D}"], 1, "p.png", []),
    ("water", ["--window", "--steps", "3"], 2, "--steps does not apply to --window", []),
    ("water", ["--window", "--out", "{D}"], 2, "--out does not apply to --window", []),
    ("water", ["--window", "--sequence", "2"], 2, "--sequence does not apply to --window", []),
    ("water", ["--window", "--dt", "2"], 2, "--dt with --window needs --frames", []),
]


def help_flags(binary):
    """The long flags a CLI11 program lists in --help, without --help itself."""
    out = subprocess.run([binary, "--help"], capture_output=True, text=True).stdout
    return set(re.findall(r"^\s+(?:-\w,)?(--[\w-]+)", out, re.M)) - {"--help"}


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return struct.unpack(">II", head[16:24]) if head[:8] == b"\x89PNG\r\n\x1a\n" else None


def main(argv=None):
    p = argparse.ArgumentParser()
    p.add_argument("--bin", action="append", default=[], help="NAME=PATH")
    p.add_argument("--tmp", required=True)
    a = p.parse_args(argv)
    bins = {k: os.path.abspath(v) for k, v in (b.split("=", 1) for b in a.bin)}
    failures = []
    for name, path in bins.items():
        covered = {arg for prog, args, *_ in CASES if prog == name for arg in args if arg.startswith("--")}
        for flag in sorted(help_flags(path) - covered):
            failures.append(f"{name} {flag}: no case in tests/flags/check_flags.py (add one that uses or refuses it)")
    for i, (name, args, rc, err_re, files) in enumerate(CASES):
        if name not in bins:
            continue
        d = os.path.join(a.tmp, f"case{i:02d}")
        shutil.rmtree(d, ignore_errors=True)
        argv_ = [bins[name]] + [x.replace("{D}", d) for x in args]
        proc = subprocess.run(argv_, capture_output=True, text=True, timeout=300, cwd=a.tmp)
        what = " ".join([name] + args)
        if proc.returncode != rc:
            failures.append(f"{what}: exit {proc.returncode}, expected {rc}\n{proc.stderr[-600:]}")
        elif err_re and not re.search(re.escape(err_re), proc.stderr):
            failures.append(f"{what}: stderr lacks '{err_re}':\n{proc.stderr[-600:]}")
        for f in files:
            path = f.replace("{D}", d)
            if not os.path.isfile(path) or (path.endswith(".png") and png_size(path) is None):
                failures.append(f"{what}: {f} was not written as a PNG")
        if rc == 2 and os.path.exists(d):
            failures.append(f"{what}: a refused run wrote {d}")
    for f in failures:
        print("check_flags: error:", f)
    print(f"check_flags: {len(CASES)} cases, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
