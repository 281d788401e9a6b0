#!/usr/bin/env python3
"""The main job's render step (scripts/run-gallery.sh): renders every Prism system into a
gallery folder, prints one progress line per image ("[12/60] water scene 1.2 s"), writes
gallery/manifest.json and then gallery/index.html (scripts/gallery_report.py).

    python3 scripts/render_gallery.py [--build-dir build] [--out gallery] [--quick]

--quick renders small images and short sequences (the browser test's fixture).
Systems: the classic catalogue (prism-gallery), every examples/scenes/*.json
(prism-render), the blue-noise samplers at 1 spp and accumulated (prism-bluenoise), and
8-frame rain and water sequences shown as strips (prism-rain, water), and every catalogue
image through GL and Vulkan compared (prism-agreement, scripts/gallery_vulkan.py).
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gallery_live  # noqa: E402
import gallery_report  # noqa: E402
import gallery_vulkan  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Scene file prefix -> the system section it shows (anything else: "scenes").
SCENE_SECTIONS = [("diffraction", "diffraction"), ("rain", "rain"), ("puddles", "water"), ("water", "water"),
                  ("soft_shadows", "bluenoise")]

SECTIONS = [
    ("catalogue", "Classic shader catalogue",
     "Every catalogue shader and its boolean variants on a sphere, a torus, a cube and a trefoil (prism-gallery); "
     "the contact sheet gallery.png has them all."),
    ("scenes", "Scenes: lights and fog", "JSON scenes of examples/scenes/ rendered by prism-render --scene."),
    ("rain", "Rain", "Camera-following particles with light-dependent streaks (docs/rain.md)."),
    ("water", "Water", "Rain-fed shallow water on a height-map terrain (docs/water.md)."),
    ("diffraction", "Diffraction", "Stam's diffraction shader on gratings, a CD and snake skin (docs/diffraction.md)."),
    ("bluenoise", "Blue-noise sampling",
     "The soft-shadow demo with white noise, a blue-noise mask and sorted (retargeted) seeds, at 1 spp "
     "(frame 0) and accumulated over frames (docs/bluenoise.md)."),
    gallery_vulkan.SECTION,
]


def version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        m = re.search(r"project\(\s*Prism\s+VERSION\s+([0-9.]+)", f.read())
    return m.group(1) if m else "unknown"


class Progress:
    def __init__(self, total):
        self.total, self.done, self.start = total, 0, time.monotonic()

    def line(self, label, seconds):
        self.done += 1
        print(f"[{self.done}/{self.total}] {label} {seconds:.2f} s", flush=True)


def run_timed(cmd):
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(f"render_gallery: {' '.join(cmd)} exited {proc.returncode}\n{proc.stdout}{proc.stderr}")
        sys.exit(1)
    return time.monotonic() - start


def scene_summary(path):
    """The first sentence of a scene file's "comment" (what it shows), or ""."""
    with open(path) as f:
        comment = str(json.load(f).get("comment", ""))
    first = re.split(r"(?<=\.)\s", comment, maxsplit=1)[0].rstrip(".")
    return first if len(first) <= 160 else first[:157] + "..."


def jobs_after_catalogue(a, bins, out):
    """(section, label, command, image dict) for everything but the catalogue."""
    jobs = []
    bn_size = "64x64" if a.quick else "256x256"
    accumulated = 4 if a.quick else 32
    for frames in (1, accumulated):  # a row at 1 spp, then a row accumulated
        for sampler in ("white", "bluenoise", "sorted"):
            src = f"bluenoise/{sampler}-{frames}.png"
            cmd = [bins["bluenoise"], "render", "--sampler", sampler, "--spp", "1", "--size", bn_size,
                   "--out", os.path.join(out, src)]
            if frames > 1:
                cmd += ["--frames", str(frames)]
            elif sampler in gallery_live.BLUENOISE_SAMPLERS:  # the live view's record of this frame
                cmd += ["--live-record", os.path.join(out, gallery_live.bluenoise_record(src))]
            label = "1 spp, frame 0" if frames == 1 else f"1 spp, mean of {frames} frames"
            jobs.append(("bluenoise", f"bluenoise {sampler} {label}", cmd,
                         {"src": src, "sampler": sampler, "note": label}))
    scenes = sorted(f for f in os.listdir(os.path.join(ROOT, "examples", "scenes")) if f.endswith(".json"))
    size = "160x120" if a.quick else None
    for name in scenes:
        stem = name[:-5]
        section = next((s for prefix, s in SCENE_SECTIONS if stem.startswith(prefix)), "scenes")
        cmd = [bins["render"], "--scene", os.path.join(ROOT, "examples", "scenes", name),
               "--out", os.path.join(out, "scenes", stem + ".png")]
        if size:
            cmd += ["--size", size]
        jobs.append((section, f"{stem} scene", cmd, {"src": f"scenes/{stem}.png", "scene": f"examples/scenes/{name}",
                                                     "note": scene_summary(os.path.join(ROOT, "examples", "scenes", name))}))
    n, w, h = (4, 96, 72) if a.quick else (8, 240, 180)
    jobs.append(("rain", f"rain sequence of {n} frames",
                 [bins["rain"], "--sequence", str(n), "--intensity", "heavy", "--width", str(w), "--height", str(h),
                  "--out", os.path.join(out, "rain-sequence")],
                 {"src": "rain-sequence/sequence.png", "scene": "prism-rain view 0, heavy rain",
                  "frames": f"{n} at 1/30 s", "wide": True}))
    jobs.append(("water", f"water sequence of {n} frames",
                 [bins["water"], "--sequence", str(n), "--grid", "64" if a.quick else "128", "--steps",
                  str(8 * n), "--width", str(w), "--height", str(h), "--out", os.path.join(out, "water-sequence")],
                 {"src": "water-sequence/sequence.png", "scene": "water overview, cloudburst on a procedural terrain",
                  "frames": f"{n}, 8 steps of 1 s apart", "wide": True}))
    return jobs


def render_catalogue(bins, out, quick, progress_total_rest):
    """Runs prism-gallery, re-printing its [k/N] lines with the whole job's counter."""
    cmd = [bins["gallery"], "--out", out] + (["--size", "96"] if quick else [])
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True)
    renderer, progress = "unknown", None
    for line in proc.stdout:
        if line.startswith("renderer: "):
            renderer = line[len("renderer: "):].strip()
        m = re.match(r"\[(\d+)/(\d+)\] (.*) ([0-9.]+) s$", line.strip())
        if m:
            if progress is None:
                progress = Progress(int(m.group(2)) + progress_total_rest)
            progress.line("catalogue " + m.group(3), float(m.group(4)))
    if proc.wait() != 0:
        sys.exit(f"render_gallery: {' '.join(cmd)} exited {proc.returncode}")
    images = []
    with open(os.path.join(out, "catalogue.tsv")) as f:
        next(f)
        for row in f:
            file, shader, variant, mesh, seconds = row.rstrip("\n").split("\t")
            images.append({"src": file, "shader": shader, "variant": variant or "default", "mesh": mesh,
                           "seconds": float(seconds)})
    return renderer, progress or Progress(progress_total_rest), images


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build-dir", default="build")
    p.add_argument("--out", default="gallery")
    p.add_argument("--quick", action="store_true", help="small images and short sequences (tests)")
    a = p.parse_args(argv)
    b = a.build_dir
    bins = {"gallery": f"{b}/apps/prism-gallery", "render": f"{b}/apps/prism-render",
            "bluenoise": f"{b}/apps/prism-bluenoise/prism-bluenoise", "rain": f"{b}/examples/rain/prism-rain",
            "water": f"{b}/examples/water/water", "agreement": f"{b}/apps/prism-agreement"}
    missing = [path for path in bins.values() if not os.access(path, os.X_OK)]
    if missing:
        sys.exit("render_gallery: build these first: " + ", ".join(missing))
    start = time.monotonic()
    for sub in ("scenes", "bluenoise"):
        os.makedirs(os.path.join(a.out, sub), exist_ok=True)
    jobs = jobs_after_catalogue(a, bins, a.out) + [gallery_vulkan.job(bins, a.out, a.quick)]
    accumulated = 4 if a.quick else 32
    renderer, progress, catalogue = render_catalogue(bins, a.out, a.quick, len(jobs))
    sections = {sid: {"id": sid, "title": t, "intro": i, "images": []} for sid, t, i in SECTIONS}
    sections["catalogue"]["images"] = catalogue + [
        {"src": "gallery.png", "note": "contact sheet of the catalogue", "wide": True}]
    glance = {"catalogue": "phong.BLINN-1-torus.png", "scenes": "scenes/four_lights.png",
              "rain": "scenes/rain.png", "water": "scenes/puddles_closeup.png",
              "diffraction": "scenes/diffraction_cd.png", "bluenoise": f"bluenoise/sorted-{accumulated}.png",
              "vulkan": gallery_vulkan.PAIR}
    for sid in sections:  # the header's one image per system
        sections[sid]["glance"] = glance[sid]
    for sid in sections:  # thumbnails; wide strips keep their size
        sections[sid]["thumb_width"] = {"catalogue": 160, "bluenoise": 256}.get(sid, 320)
    for section, label, cmd, image in jobs:
        seconds = run_timed(cmd)
        progress.line(label, seconds)
        sections[section]["images"].append(dict(image, seconds=seconds))
    gallery_live.write_live_data(a.out, b)
    sections["vulkan"]["html"] = gallery_vulkan.grid_html(a.out)
    manifest = {"version": version(), "renderer": renderer,
                "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
                "total_seconds": time.monotonic() - start, "sections": [sections[sid] for sid, _, _ in SECTIONS]}
    with open(os.path.join(a.out, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1)
    page = gallery_report.write_report(a.out, ROOT)
    print(f"done: {progress.done} images in {time.monotonic() - start:.1f} s; open {os.path.abspath(page)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
