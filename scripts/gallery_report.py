#!/usr/bin/env python3
"""Writes the gallery report gallery/index.html from gallery/manifest.json (issue 15).

The page is static and self-contained: no script from the network, no framework, every
link relative to the gallery folder. It has a header (renderer string, date, Prism
version), one section per system with captioned images (shader, variant, mesh or scene,
render time), the trade plots and tables the benches committed (copied into
gallery/plots/), each with a sentence on how to read it, and links to the docs pages.

    python3 scripts/gallery_report.py gallery        # reads gallery/manifest.json
"""
import csv
import html
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gallery_live  # noqa: E402

# The benches' committed plots: (file in the repository, what to read from it).
PLOTS = [
    ("docs/tradeoffs.svg",
     "Median frame time against mean error per shader and subdivision level (log-log); left against the full "
     "reference with the Pareto front: a point on the front is the cheapest way to reach its error."),
    ("docs/diffraction_bench.svg",
     "Diffraction cost (frame time relative to Phong) against mean colour error (CIE dE2000) for the three paths "
     "and their settings; filled points form the Pareto front, so pick the cheapest filled point below the "
     "error you can accept."),
    ("docs/bluenoise/bluenoise_convergence.svg",
     "RMS error against accumulated frames per sampler: the per-pixel RMS starts alike at 1 spp (about 0.33), "
     "but the blurred RMS (what a viewer sees) of blue noise is 2.4x lower than white noise's, and the gap "
     "grows with frames."),
    ("docs/bluenoise/bluenoise_spectra.svg",
     "Radially averaged power spectra of the masks: a blue-noise mask has almost no energy near zero frequency, "
     "white noise is flat."),
    ("bench/rain/results/rain_bench.svg",
     "Milliseconds per rain frame against particle count per streak technique (dashed: the compute update "
     "alone); where a line crosses the 30 and 60 FPS marks is the largest drop count for that frame rate."),
    ("bench/water/results/water-bench.svg",
     "CPU step, GPU (compute) step and scene render time against grid size (log-log): a slope of one means "
     "the cost grows linearly with the number of cells."),
]


def rain_and_water_trade_plots():
    """The speed/accuracy trades of rain and water (prism_bench_rain --trade,
    prism_bench_water --trade): cost against error, Pareto front filled."""
    return [
        ("bench/water/results/water-trade.svg",
         "Water: wall time per simulated second against the mean depth error after resampling onto a common 64x64 "
         "grid, per grid size, substep and smoothing kernel, against a 512x512 reference with a quarter of the stable "
         "substep; filled points form the Pareto front."),
        ("bench/rain/results/rain_trade.svg",
         "Rain: frame time against the mean error of the time-averaged rain layer (light added per pixel) per particle "
         "count, LOD rings and streak technique, against a dense reference without LOD; filled points form the "
         "Pareto front."),
    ]


PLOTS.extend(rain_and_water_trade_plots())

# The benches' committed tables: (CSV in the repository, columns shown, what to read).
TABLES = [
    ("docs/tradeoffs.csv", ["shader", "level", "triangles", "median_ms", "mean_err", "pareto_full"],
     "Per shader and level: median frame time and mean error against the exact sphere; "
     "pareto_full = 1 marks the rows on the front."),
    ("docs/bluenoise/bluenoise_tradeoff.csv", ["sampler", "spp", "frames", "ms_per_frame", "rms"],
     "Per sampler: cost per frame and the RMS error left after so many frames at so many samples."),
    ("docs/shaderc_bench.csv", ["case", "label", "stage_files", "median_wall_ms", "speedup_a_over_case"],
     "Shader validation wall time per tool setup; the last column is the speed-up over one "
     "glslangValidator process per stage file."),
]

DOCS = [
    ("docs/runtime.md", "runtime: shaders, meshes, offscreen rendering"),
    ("docs/scenes.md", "scenes: the JSON scene format"),
    ("docs/rain.md", "rain"),
    ("docs/water.md", "water"),
    ("docs/diffraction.md", "diffraction"),
    ("docs/bluenoise.md", "blue-noise sampling"),
    ("docs/tradeoffs.md", "speed against accuracy"),
    ("docs/variants.md", "minimal variants against an uber-shader"),
    ("docs/vulkan.md", "Vulkan: the catalogue's SPIR-V, checked against GL"),
    ("docs/architecture.md", "architecture"),
]

STYLE = """body{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222}
header{border-bottom:1px solid #ccc;margin-bottom:1em}
.live-view canvas{width:256px;height:256px;border:1px solid #ccc;cursor:grab}
.live-controls{font-size:12px;max-width:256px}.live-controls label{display:block}
.live-controls label.missing{color:#aaa}.agreement{font-size:12px;max-width:256px}
body.live-only>*:not(#live){display:none}
figure{display:inline-block;margin:.4em;vertical-align:top;max-width:100%}
figure img{max-width:100%;height:auto;border:1px solid #ccc;background:#000}
figcaption{font-size:13px;max-width:320px}
figure.wide figcaption{max-width:none}
table{border-collapse:collapse;font-size:12px;margin:.5em 0}
td,th{border:1px solid #ccc;padding:2px 6px}
.glance figure{width:128px}
.glance img{width:128px;height:96px;object-fit:cover}"""


def esc(text):
    return html.escape(str(text), quote=True)


def caption_text(image):
    """One caption line: the keys the manifest gives, then the render time."""
    parts = [f"{key} {image[key]}" for key in ("shader", "variant", "mesh", "scene", "sampler", "frames")
             if image.get(key) not in (None, "")]
    if image.get("note"):
        parts.append(image["note"])
    if image.get("seconds") is not None:
        parts.append(f"{image['seconds']:.2f} s")
    return ", ".join(parts)


def image_html(image, width=None):
    cls = ' class="wide"' if image.get("wide") else ""
    w = f' width="{int(width)}"' if width and not image.get("wide") else ""
    fw = f' style="width:{int(width)}px"' if w else ""
    return (f'<figure{cls}{fw}><a href="{esc(image["src"])}"><img src="{esc(image["src"])}" alt="{esc(caption_text(image))}"'
            f'{w} loading="eager"></a><figcaption>{esc(caption_text(image))}</figcaption></figure>')


def table_html(path, columns):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    head = "".join(f"<th>{esc(c)}</th>" for c in columns)
    body = "".join("<tr>" + "".join(f"<td>{esc(r.get(c, ''))}</td>" for c in columns) + "</tr>" for r in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def build_html(manifest, plots=(), tables=(), docs=(), live=""):
    """The page as a string. plots: (gallery-relative src, sentence); tables: (name, html,
    sentence); docs: (href, title); live: the live views' section (gallery_live.py)."""
    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           f"<title>Prism {esc(manifest['version'])} gallery</title><style>{STYLE}</style></head><body>",
           f"<header><h1>Prism {esc(manifest['version'])}: what it renders</h1>",
           f"<p>Renderer: <b id=\"renderer\">{esc(manifest['renderer'])}</b>; rendered {esc(manifest['date'])}; "
           f"{len([i for s in manifest['sections'] for i in s['images']])} images in "
           f"{manifest['total_seconds']:.1f} s.</p><nav>"]
    out.append(" | ".join(f'<a href="#{esc(s["id"])}">{esc(s["title"])}</a>' for s in manifest["sections"]))
    out.append(' | <a href="#trades">trade-offs</a> | <a href="#docs">docs</a></nav>')
    out.append('<div class="glance">')  # one image per system, linking to its section
    for section in manifest["sections"]:
        pick = next((i for i in section["images"] if i["src"] == section.get("glance")), None)
        pick = pick or (section["images"][0] if section["images"] else None)
        if pick:
            out.append(f'<figure><a href="#{esc(section["id"])}"><img src="{esc(pick["src"])}" alt="{esc(section["title"])}">'
                       f'</a><figcaption>{esc(section["title"])}</figcaption></figure>')
    out.append("</div></header>")
    for section in manifest["sections"]:
        out.append(f'<section id="{esc(section["id"])}" class="system"><h2>{esc(section["title"])}</h2>')
        if section.get("intro"):
            out.append(f"<p>{esc(section['intro'])}</p>")
        width = section.get("thumb_width")
        out.extend(image_html(i, width) for i in section["images"])
        out.append(section.get("html", ""))  # a section's own markup (the Vulkan grid)
        out.append("</section>")
        if section["id"] == "catalogue" and live:  # the live views next to the catalogue's PNGs
            out.append(live)
    out.append('<section id="trades"><h2>Trade-offs measured by the benches</h2>')
    for src, sentence in plots:
        out.append(f'<figure class="wide"><a href="{esc(src)}"><img src="{esc(src)}" alt="{esc(src)}" width="720">'
                   f"</a><figcaption>{esc(sentence)}</figcaption></figure>")
    for name, table, sentence in tables:
        out.append(f"<h3>{esc(name)}</h3><p>{esc(sentence)}</p>{table}")
    out.append('</section><section id="docs"><h2>Documentation</h2><ul>')
    out.extend(f'<li><a href="{esc(href)}">{esc(title)}</a></li>' for href, title in docs)
    out.append("</ul></section></body></html>")
    return "\n".join(out) + "\n"


def write_report(gallery, repo_root):
    """Copies the plots into gallery/plots/ and writes gallery/index.html; returns its path."""
    with open(os.path.join(gallery, "manifest.json")) as f:
        manifest = json.load(f)
    os.makedirs(os.path.join(gallery, "plots"), exist_ok=True)
    plots = []
    for rel, sentence in PLOTS:
        src = os.path.join(repo_root, rel)
        if os.path.exists(src):
            name = os.path.basename(rel)
            shutil.copyfile(src, os.path.join(gallery, "plots", name))
            plots.append(("plots/" + name, sentence))
    tables = [(os.path.basename(rel), table_html(os.path.join(repo_root, rel), cols), sentence)
              for rel, cols, sentence in TABLES if os.path.exists(os.path.join(repo_root, rel))]
    docs = [(os.path.relpath(os.path.join(repo_root, rel), gallery), title) for rel, title in DOCS
            if os.path.exists(os.path.join(repo_root, rel))]
    page = build_html(manifest, plots, tables, docs, gallery_live.live_html(gallery))
    path = os.path.join(gallery, "index.html")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(page)
    os.replace(tmp, path)
    return path


def main(argv):
    if len(argv) != 2:
        print("usage: gallery_report.py GALLERY_DIR", file=sys.stderr)
        return 2
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    print(write_report(argv[1], root))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
