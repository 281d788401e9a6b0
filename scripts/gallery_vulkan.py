"""The main job's "Vulkan and GL agree" section (scripts/render_gallery.py calls it):
prism-agreement renders every gallery job through GL and through Vulkan into gallery/vulkan/,
and this module turns its agreement.tsv into a grid of shader x mesh holding the largest
channel difference of each, next to the side-by-side pair of the job that differs most.
"""
import csv
import html
import os

SECTION = ("vulkan", "Vulkan and GL agree",
           "Every catalogue shader and variant on the gallery meshes, drawn through GL (llvmpipe) and through "
           "Vulkan from the catalogue's SPIR-V (lavapipe) by prism-agreement. The grid gives the largest channel "
           "difference of each image in 1/255; the pair is the image that differs most (docs/vulkan.md).")
PAIR = "vulkan/agreement-pair.png"


def job(bins, out, quick):
    """(section, label, command, image dict), as render_gallery's other jobs."""
    cmd = [bins["agreement"], "--out", os.path.join(out, "vulkan"), "--size", "96" if quick else "256"]
    return (SECTION[0], "Vulkan vs GL agreement", cmd,
            {"src": PAIR, "note": "GL | Vulkan | difference x8, the largest difference", "wide": True})


def grid_html(out):
    """The shader x mesh grid from gallery/vulkan/agreement.tsv: max difference per image."""
    with open(os.path.join(out, "vulkan", "agreement.tsv"), newline="") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))
    shaders = list(dict.fromkeys((r["shader"] + " " + r["variant"]).strip() for r in rows))
    cell = {((r["shader"] + " " + r["variant"]).strip(), r["mesh"]): r for r in rows}
    head = "".join(f"<th>{html.escape(m)}</th>" for m in meshes)
    body = []
    for s in shaders:
        cells = "".join(f"<td>{html.escape(cell[(s, m)]['max'])}</td>" if (s, m) in cell else "<td></td>"
                        for m in meshes)
        body.append(f"<tr><th>{html.escape(s)}</th>{cells}</tr>")
    worst = max(int(r["max"]) for r in rows) if rows else 0
    return (f'<table class="agreement"><tr><th>largest difference (1/255)</th>{head}</tr>{"".join(body)}</table>'
            f"<p>Largest difference over all {len(rows)} images: {worst}/255.</p>")
