#!/usr/bin/env python3
"""The gallery report's live WebGL2 views (issue 27; docs/web.md), the Python side.

write_live_data(gallery, build_dir) turns prism-gallery's gallery/live-views.json into plain
scripts: gallery/live/data.js, the view records with their uniforms, and one
gallery/live/mesh-<name>.js per mesh, its vertex arrays as base64 float32/uint32 and the PNGs
drawn on it as data: URIs (a canvas refuses to be read after drawing a file:// image, a data:
URI it accepts), which the page loads when a view first shows the mesh. It copies beside them the web
catalogue that prism_add_shaders(... WEB) wrote (build/web/prism_shaders.js) and the page's
scripts (scripts/web/). For the blue-noise soft-shadow view it writes gallery/live/bluenoise.js
from the records `prism-bluenoise render --live-record` wrote beside bluenoise/{white,bluenoise}-1.png
(the shader's uniforms and mask) and copies the blue-noise web catalogue
(build/web/prism_bluenoise_shaders.js). live_html(gallery) is the report's "live" section for them, or ""
when there is no gallery/live/.

    python3 scripts/gallery_live.py GALLERY_DIR BUILD_DIR   # what render_gallery.py calls
"""
import base64
import json
import os
import shutil
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = ["prism_web.js", "live_draw.js", "gallery_live.js", "live_bluenoise.js"]  # scripts/web/, in load order
CATALOGUE = "prism::shaders"
DEFAULT_MESH = "torus"
# The blue-noise soft-shadow view: the samplers whose frame-0 PNGs get a record
# (prism-bluenoise render --live-record), and its catalogue and program.
BLUENOISE_SAMPLERS = ("white", "bluenoise")
BLUENOISE_CATALOGUE = "prism::bluenoise_shaders"
BLUENOISE_PROGRAM = "soft_shadows"


def bluenoise_record(png):
    """The record prism-bluenoise writes beside `png` (bluenoise/white-1.png -> bluenoise/white-1.live.json)."""
    return png[:-len(".png")] + ".live.json"


def packed(values, fmt):
    return base64.b64encode(struct.pack("<%d%s" % (len(values), fmt), *values)).decode("ascii")


def png_uri(path):
    with open(path, "rb") as f:
        return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")


def mesh_name(key):
    return key.split(".")[0]  # prism-gallery's keys: "torus", "torus.1" (the same mesh prepared otherwise)


def mesh_parts(gallery, record):
    """{mesh name: {"meshes": {key: base64 arrays}, "pngs": {file: data URI}}}, one file each."""
    parts = {}
    for key, m in record["meshes"].items():
        part = parts.setdefault(mesh_name(key), {"meshes": {}, "pngs": {}})
        part["meshes"][key] = {"positions": packed(m["positions"], "f"), "normals": packed(m["normals"], "f"),
                               "indices": packed(m["indices"], "I")}
    for v in record["views"]:
        parts[mesh_name(v["mesh"])]["pngs"][v["png"]] = png_uri(os.path.join(gallery, v["png"]))
    return parts


def write_script(path, comment, text):
    with open(path, "w") as f:
        f.write(f"// Written by scripts/gallery_live.py: {comment}\n{text}\n")


def write_data(gallery, live, record):
    """live/data.js (the views, loaded with the page) and live/mesh-<name>.js per mesh (its
    meshes and PNGs, loaded when a view first shows that mesh)."""
    parts = mesh_parts(gallery, record)
    files = {name: f"mesh-{name}.js" for name in parts}
    data = {"catalogue": CATALOGUE, "defaultMesh": DEFAULT_MESH, "shaders": sorted({v["shader"] for v in record["views"]}),
            "meshNames": list(parts), "meshFiles": files, "meshes": {}, "pngs": {}, "loaded": {},
            "views": record["views"]}
    write_script(os.path.join(live, "data.js"), "the gallery's views for the live views (docs/web.md).",
                 "var PrismGalleryLive = " + json.dumps(data, separators=(",", ":")) + ";")
    for name, part in parts.items():
        write_script(os.path.join(live, files[name]), f"the {name} meshes and their PNGs for the live views.",
                     f"PrismGalleryLive.addMesh({json.dumps(name)}, {json.dumps(part, separators=(',', ':'))});")


def write_bluenoise_data(gallery, build_dir, live):
    """live/bluenoise.js (the soft-shadow view's records, its mask and PNGs) and the blue-noise
    web catalogue, when the gallery has records; returns whether it wrote them."""
    pngs = [f"bluenoise/{s}-1.png" for s in BLUENOISE_SAMPLERS]
    records = [bluenoise_record(p) for p in pngs if os.path.exists(os.path.join(gallery, bluenoise_record(p)))]
    if not records:
        return False
    web = os.path.join(build_dir, "web", "prism_bluenoise_shaders.js")
    if not os.path.exists(web):
        sys.exit(f"gallery_live: {web} is missing; build the prism_bluenoise_shaders target (prism_add_shaders ... WEB)")
    views = []
    for path in records:
        with open(os.path.join(gallery, path)) as f:
            r = json.load(f)
        r["png"] = os.path.join(os.path.dirname(path), r["png"])
        views.append(r)
    mask = views[0]["mask"]
    if any(v["mask"] != mask for v in views):
        sys.exit(f"gallery_live: {', '.join(records)} were rendered with different blue-noise masks")
    data = {"catalogue": BLUENOISE_CATALOGUE, "program": BLUENOISE_PROGRAM,
            "mask": {"width": mask["width"], "height": mask["height"], "values": packed(mask["values"], "I")},
            "views": [{k: v[k] for k in ("png", "width", "height", "uniforms")} for v in views],
            "pngs": {v["png"]: png_uri(os.path.join(gallery, v["png"])) for v in views}}
    write_script(os.path.join(live, "bluenoise.js"), "the blue-noise soft-shadow view's frames and mask.",
                 "PrismGalleryLive.bluenoise = " + json.dumps(data, separators=(",", ":")) + ";")
    shutil.copyfile(web, os.path.join(live, "prism_bluenoise_shaders.js"))
    return True


def write_live_data(gallery, build_dir):
    """Writes gallery/live/; returns its path, or None when prism-gallery wrote no record."""
    record_path = os.path.join(gallery, "live-views.json")
    web = os.path.join(build_dir, "web", "prism_shaders.js")
    if not os.path.exists(record_path):
        return None
    if not os.path.exists(web):
        sys.exit(f"gallery_live: {web} is missing; build the prism_shaders target (prism_add_shaders ... WEB)")
    live = os.path.join(gallery, "live")
    os.makedirs(live, exist_ok=True)
    with open(record_path) as f:
        write_data(gallery, live, json.load(f))
    shutil.copyfile(web, os.path.join(live, "prism_shaders.js"))
    write_bluenoise_data(gallery, build_dir, live)
    for name in SCRIPTS:
        shutil.copyfile(os.path.join(HERE, "web", name), os.path.join(live, name))
    return live


def live_html(gallery):
    """The report's live section and its scripts, or "" without gallery/live/data.js."""
    if not os.path.exists(os.path.join(gallery, "live", "data.js")):
        return ""
    data = ["prism_shaders.js", "data.js"]
    if os.path.exists(os.path.join(gallery, "live", "bluenoise.js")):
        data += ["prism_bluenoise_shaders.js", "bluenoise.js"]
    scripts = "".join(f'<script src="live/{name}"></script>' for name in data + SCRIPTS)
    return ('<section id="live"><h2>Live in the browser (WebGL2)</h2>'
            '<p id="live-status">The live views need JavaScript.</p>'
            "<p>Each classic shader drawn by this browser from the web catalogue that prism-shaderc emitted "
            "(docs/web.md), on the gallery's meshes: pick variant axes (greyed: combinations the catalogue lacks), "
            "light, material and colour, and drag to rotate; then the blue-noise soft shadows, one frame of the "
            "GPU shader with its mask.</p></section>" + scripts)


def main(argv):
    if len(argv) != 3:
        print("usage: gallery_live.py GALLERY_DIR BUILD_DIR", file=sys.stderr)
        return 2
    print(write_live_data(argv[1], argv[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
