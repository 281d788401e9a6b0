#!/usr/bin/env python3
"""Flags are never silently ignored (issue 15): runs every app (prism-render, prism-gallery,
prism-bluenoise, prism-diffraction, prism-rain, water) with flags that the chosen mode
would not use and expects a usage error (exit 2) naming the flag, and with the modes that
do use them and expects their output. A coverage check reads each program's (and each
subcommand's) --help and fails when one of its flags has no case here, so a new flag
needs a case. (More refusal cases sit next to each app's other CLI tests:
tests/rendering, tests/bluenoise, tests/diffraction.)

    python3 tests/flags/check_flags.py --bin prism-render=PATH --bin prism-gallery=PATH ... --tmp DIR
{D} in a case is a fresh path for that case (a folder, or a file prefix: {D}.png);
{T} is the --tmp folder, shared by the cases in order.
"""
import argparse
import glob
import os
import re
import shutil
import struct
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (program, arguments ({D} = a fresh output folder), exit status, stderr regex, files that must exist)
CASES = [
    # prism-render: catalogue flags describe a --shader render; --scene takes --size and its
    # "stochastic" overrides.
    ("prism-render", ["--shader", "phong", "--variant", "BLINN=1", "--mesh", "torus", "--subdiv", "1", "--shininess",
                      "8", "--specular", "0.3", "--color", "1,0,0", "--light-dir", "0,-1,0", "--scale", "1,1,1",
                      "--size", "32x24", "--backend", "egl", "--out", "{D}.png"], 0, "", ["{D}.png"]),
    ("prism-render", ["--shader", "flat", "--size", "16x16", "--check-finite"], 0, "", []),
    ("prism-render", ["--scene", "{S}/soft_shadows.json", "--size", "24x16", "--spp", "2", "--sampler", "white",
                      "--frames", "2", "--out", "{D}.png"], 0, "", ["{D}.png"]),
    ("prism-render", ["--scene", "{S}/soft_shadows.json", "--size", "24x16", "--frame", "1", "--out", "{D}.png"], 0, "",
     ["{D}.png"]),
    ("prism-render", ["--scene", "{S}/one_light.json", "--mesh", "cube", "--out", "{D}.png"], 2,
     "--mesh describes a --shader render", []),
    ("prism-render", ["--scene", "{S}/one_light.json", "--spp", "2", "--out", "{D}.png"], 2, "no \"stochastic\"", []),
    ("prism-render", ["--scene", "{S}/soft_shadows.json", "--backend", "egl", "--out", "{D}.png"], 2,
     "is drawn on the CPU", []),
    ("prism-render", ["--scene", "{S}/one_light.json", "--check-finite", "--out", "{D}.png"], 2, "--check-finite works with --shader", []),
    ("prism-render", ["--shader", "phong", "--mesh", "cube", "--subdiv", "2", "--out", "{D}.png"], 2,
     "--subdiv: mesh cube has no subdivision levels", []),
    ("prism-render", ["--shader", "phong", "--sampler", "white", "--out", "{D}.png"], 2, "only with --scene", []),
    # prism-bluenoise: sampler settings only for the samplers (and the render) that use them.
    ("prism-bluenoise generate", ["--size", "16x16", "--depth", "1", "--sigma", "1.5", "--seed", "2", "--bits", "8",
                                  "--out", "{T}/mask.png"], 0, "", ["{T}/mask.png"]),
    ("prism-bluenoise generate", ["--size", "8x8", "--depth", "2", "--spatiotemporal", "--sigma-time", "1.5",
                                  "--out", "{D}"], 0, "", ["{D}/slice_001.png"]),
    ("prism-bluenoise generate", ["--size", "8x8", "--sigma-time", "1.5", "--out", "{D}.png"], 2,
     "--sigma-time needs --spatiotemporal", []),
    ("prism-bluenoise measure", ["{T}/mask.png", "--json", "--spectrum-svg", "{D}.svg"], 0, "", ["{D}.svg"]),
    ("prism-bluenoise render", ["--sampler", "sorted", "--spp", "1", "--frames", "2", "--size", "16x16", "--mask-size",
                                "16", "--block", "4", "--schedule", "inverse", "--epochs", "1", "--retarget-cache",
                                "{D}.bin", "--scene", "black", "--out", "{D}.png"], 0, "", ["{D}.png", "{D}.bin"]),
    ("prism-bluenoise render", ["--sampler", "stack", "--stack-depth", "2", "--mask-size", "8", "--size", "8x8",
                                "--frame", "1", "--out", "{D}.png"], 0, "", ["{D}.png"]),
    ("prism-bluenoise render", ["--sampler", "sorted", "--a-posteriori", "--size", "8x8", "--out", "{D}.png"], 0, "",
     ["{D}.png"]),
    ("prism-bluenoise render", ["--sampler", "sorted", "--no-retarget", "--frames", "2", "--size", "8x8",
                                "--out", "{D}.png"], 0, "", ["{D}.png"]),
    ("prism-bluenoise render", ["--reference", "4", "--size", "8x8", "--out", "{D}.png"], 0, "", ["{D}.png"]),
    ("prism-bluenoise render", ["--reference", "4", "--sampler", "white", "--out", "{D}.png"], 2,
     "--sampler: --reference renders", []),
    ("prism-bluenoise render", ["--sampler", "white", "--block", "8", "--out", "{D}.png"], 2,
     "--block: only for --sampler sorted", []),
    ("prism-bluenoise render", ["--sampler", "white", "--mask-size", "8", "--out", "{D}.png"], 2,
     "--mask-size: the white sampler uses no mask", []),
    ("prism-bluenoise render", ["--sampler", "bluenoise", "--stack-depth", "2", "--out", "{D}.png"], 2,
     "--stack-depth: only for --sampler stack", []),
    ("prism-bluenoise render", ["--sampler", "sorted", "--epochs", "2", "--out", "{D}.png"], 2,
     "--epochs: this render does not retarget", []),
    ("prism-bluenoise render", ["--frame", "1", "--frames", "2", "--out", "{D}.png"], 2,
     "--frame: --frames K renders the mean", []),
    # prism-diffraction: grating shape flags for the gratings, PNG flags for png, Taylor flags
    # for the Taylor path.
    ("prism-diffraction peaks", ["--height-field", "blazed", "--period-nm", "2500", "--amplitude-nm", "100",
                                 "--incidence-deg", "10", "--wavelengths-nm", "550", "--terms", "12", "--periods", "8",
                                 "--samples-per-period", "16", "--json"], 0, "", []),
    ("prism-diffraction peaks", ["--periods", "8", "--samples-per-period", "16", "--wavelengths-nm", "550",
                                 "--tolerance", "1e-3"], 0, "", []),
    ("prism-diffraction peaks", ["--periods", "8", "--samples-per-period", "16", "--wavelengths-nm", "550", "--exact"],
     0, "", []),
    ("prism-diffraction peaks", ["--height-field", "png", "--png", "{T}/mask.png", "--nm-per-pixel", "200",
                                 "--height-scale-nm", "50", "--wavelengths-nm", "550"], 0, "", []),
    ("prism-diffraction peaks", ["--wavelengths-nm", "550", "--png", "{T}/mask.png"], 2,
     "--png needs --height-field png", []),
    ("prism-diffraction peaks", ["--wavelengths-nm", "550", "--height-field", "cd", "--amplitude-nm", "9"], 2,
     "--amplitude-nm shapes the sinusoid", []),
    ("prism-diffraction peaks", ["--wavelengths-nm", "550", "--exact", "--terms", "9"], 2,
     "--terms: --exact uses no Taylor series", []),
    ("prism-diffraction bound", ["--max-height-nm", "150", "--wavelength-nm", "380", "--tolerance", "1e-6"], 0, "", []),
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
    ("water", ["--grid", "16", "--steps", "2", "--fog", "0.02", "--fog-billboards", "0.5", "--width", "32",
               "--height", "24", "--out", "{D}"], 0, "", ["{D}/overview.png", "{D}/ground.png"]),
    ("water", ["--grid", "16", "--fog-billboards", "0.5", "--out", "{D}"], 2, "--fog-billboards needs --fog", []),
    ("water", ["--grid", "16", "--height-scale", "3", "--out", "{D}"], 2, "--height-scale needs --heightmap", []),
    ("water", ["--grid", "16", "--permeability-max", "5", "--out", "{D}"], 2, "--permeability-max needs --permeability", []),
    ("water", ["--heightmap", "h.png", "--grid", "16", "--out", "{D}"], 2, "does not apply to --heightmap", []),
    ("water", ["--permeability", "p.png", "--grid", "16", "--out", "{D}"], 1, "p.png", []),
    ("water", ["--window", "--steps", "3"], 2, "--steps does not apply to --window", []),
    ("water", ["--window", "--out", "{D}"], 2, "--out does not apply to --window", []),
    ("water", ["--window", "--sequence", "2"], 2, "--sequence does not apply to --window", []),
    ("water", ["--window", "--dt", "2"], 2, "--dt with --window needs --frames", []),
]


def help_flags(cmd):
    """The long flags a CLI11 program (or subcommand) lists in --help, without --help itself."""
    out = subprocess.run(cmd + ["--help"], capture_output=True, text=True).stdout
    return set(re.findall(r"^\s+(?:-\w,)?(--[\w-]+)", out, re.M)) - {"--help"}


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return struct.unpack(">II", head[16:24]) if head[:8] == b"\x89PNG\r\n\x1a\n" else None


def main(argv=None):
    p = argparse.ArgumentParser()
    p.add_argument("--bin", action="append", default=[], help="NAME=PATH")
    p.add_argument("--tmp", required=True)
    p.add_argument("--scenes", default=os.path.join(ROOT, "examples", "scenes"))
    a = p.parse_args(argv)
    bins = {k: os.path.abspath(v) for k, v in (b.split("=", 1) for b in a.bin)}
    tmp = os.path.abspath(a.tmp)
    os.makedirs(tmp, exist_ok=True)

    def command(program):  # "prism-bluenoise render" -> [binary, "render"]
        exe, *sub = program.split()
        return [bins[exe]] + sub if exe in bins else None

    failures = []
    for program in sorted({c[0] for c in CASES}):
        cmd = command(program)
        if cmd is None:
            continue
        covered = {arg for prog, args, *_ in CASES if prog == program for arg in args if arg.startswith("--")}
        for flag in sorted(help_flags(cmd) - covered):
            failures.append(f"{program} {flag}: no case in tests/flags/check_flags.py (add one that uses or refuses it)")
    for exe in bins:
        if not any(c[0].split()[0] == exe for c in CASES):
            failures.append(f"{exe}: no cases")
    ran = 0
    for i, (program, args, rc, err_re, files) in enumerate(CASES):
        cmd = command(program)
        if cmd is None:
            continue
        ran += 1
        d = os.path.join(tmp, f"case{i:02d}")
        for old in glob.glob(d + "*"):
            shutil.rmtree(old) if os.path.isdir(old) else os.remove(old)

        def expand(x):
            return x.replace("{D}", d).replace("{T}", tmp).replace("{S}", a.scenes)

        proc = subprocess.run(cmd + [expand(x) for x in args], capture_output=True, text=True, timeout=300, cwd=tmp)
        what = " ".join([program] + args)
        if proc.returncode != rc:
            failures.append(f"{what}: exit {proc.returncode}, expected {rc}\n{proc.stderr[-600:]}")
        elif err_re and err_re not in proc.stderr:
            failures.append(f"{what}: stderr lacks '{err_re}':\n{proc.stderr[-600:]}")
        for f in files:
            path = expand(f)
            if not os.path.isfile(path) or (path.endswith(".png") and png_size(path) is None):
                failures.append(f"{what}: {f} was not written")
        if rc == 2 and glob.glob(d + "*"):
            failures.append(f"{what}: a refused run wrote {glob.glob(d + '*')}")
    for f in failures:
        print("check_flags: error:", f)
    print(f"check_flags: {ran} cases run, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
