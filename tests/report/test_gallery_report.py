#!/usr/bin/env python3
"""Unit tests of scripts/gallery_report.py, scripts/gallery_live.py and scripts/render_gallery.py's pure parts (CTest
report.generator, label unit): the page's header, sections, captions, plots, tables, docs
links, escaping, offline-ness, and the version read from CMakeLists.txt."""
import html.parser
import json
import os
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_links  # noqa: E402
import gallery_live  # noqa: E402
import gallery_report  # noqa: E402
import render_gallery  # noqa: E402


def manifest():
    return {"version": "9.8.7", "renderer": "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6",
            "date": "2026-11-22 19:00 UTC", "total_seconds": 12.5,
            "sections": [
                {"id": "catalogue", "title": "Classic", "intro": "shaders", "thumb_width": 160, "images": [
                    {"src": "phong.BLINN-1-torus.png", "shader": "phong", "variant": "BLINN=1", "mesh": "torus",
                     "seconds": 0.123}]},
                {"id": "water", "title": "Water", "images": [
                    {"src": "scenes/water.png", "scene": "examples/scenes/water.json", "seconds": 1.25},
                    {"src": "water-sequence/sequence.png", "frames": "8", "wide": True, "seconds": 2.0}]},
                {"id": "odd", "title": "A <b> & \"quote\"", "images": [
                    {"src": "a b.png", "scene": "<script>", "seconds": 0.5}]},
            ]}


class Elements(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.tags = []

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))


def parse(page):
    e = Elements()
    e.feed(page)
    return e.tags


class BuildHtml(unittest.TestCase):
    def setUp(self):
        self.page = gallery_report.build_html(manifest(), [("plots/t.svg", "Read the front.")],
                                              [("t.csv", "<table></table>", "Rows on the front.")],
                                              [("../docs/rain.md", "rain")])
        self.tags = parse(self.page)

    def test_header_names_renderer_date_and_version(self):
        self.assertIn("llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6", self.page)
        self.assertIn("2026-11-22 19:00 UTC", self.page)
        self.assertIn("Prism 9.8.7", self.page)

    def test_one_section_per_system_in_order(self):
        ids = [a["id"] for tag, a in self.tags if tag == "section"]
        self.assertEqual(ids, ["catalogue", "water", "odd", "trades", "docs"])

    def test_captions_name_shader_variant_mesh_scene_and_time(self):
        self.assertIn("<figcaption>shader phong, variant BLINN=1, mesh torus, 0.12 s</figcaption>", self.page)
        self.assertIn("<figcaption>scene examples/scenes/water.json, 1.25 s</figcaption>", self.page)

    def test_every_image_links_to_itself_and_thumbnails_take_the_section_width(self):
        imgs = [a for tag, a in self.tags if tag == "img"][3:]  # after the header's one per system
        self.assertEqual([i["src"] for i in imgs], ["phong.BLINN-1-torus.png", "scenes/water.png",
                                                    "water-sequence/sequence.png", "a b.png", "plots/t.svg"])
        self.assertEqual(imgs[0].get("width"), "160")
        self.assertIsNone(imgs[2].get("width"))  # a wide strip keeps its size
        hrefs = [a["href"] for tag, a in self.tags if tag == "a"]
        for i in imgs:
            self.assertIn(i["src"], hrefs)

    def test_header_shows_one_image_per_system_linking_to_its_section(self):
        glance = [a for tag, a in self.tags if tag == "img"][:3]
        self.assertEqual([i["src"] for i in glance], ["phong.BLINN-1-torus.png", "scenes/water.png", "a b.png"])
        for sid in ("catalogue", "water", "odd"):
            self.assertIn(f'<a href="#{sid}"><img', self.page)

    def test_plots_tables_and_docs_with_their_sentences(self):
        self.assertIn("Read the front.", self.page)
        self.assertIn("Rows on the front.", self.page)
        self.assertIn('href="../docs/rain.md"', self.page)

    def test_text_is_escaped(self):
        self.assertNotIn("<script>", self.page)
        self.assertNotIn("A <b>", self.page)
        self.assertIn("&lt;script&gt;", self.page)
        self.assertIn("A &lt;b&gt; &amp; &quot;quote&quot;", self.page)

    def test_nothing_from_the_network(self):
        for tag, attrs in self.tags:
            for name in ("src", "href"):
                self.assertFalse(attrs.get(name, "").startswith(("http:", "https:", "//")), (tag, attrs))


class WriteReport(unittest.TestCase):
    def test_plots_are_copied_and_every_link_resolves(self):
        with tempfile.TemporaryDirectory() as tmp:
            gallery = os.path.join(tmp, "gallery")
            os.makedirs(os.path.join(gallery, "scenes"))
            os.makedirs(os.path.join(gallery, "water-sequence"))
            m = manifest()
            m["sections"].pop()  # "a b.png" is not made here
            for s in m["sections"]:
                for i in s["images"]:
                    open(os.path.join(gallery, i["src"]), "wb").close()
            with open(os.path.join(gallery, "manifest.json"), "w") as f:
                json.dump(m, f)
            page = gallery_report.write_report(gallery, ROOT)
            problems, count = check_links.bad_links(page)
            self.assertEqual(problems, [])
            copied = os.listdir(os.path.join(gallery, "plots"))
            self.assertEqual(len(copied), len(gallery_report.PLOTS))  # every committed plot exists
            with open(page) as f:
                text = f.read()
            for _, sentence in gallery_report.PLOTS:
                self.assertIn(gallery_report.esc(sentence), text)
            self.assertGreater(text.count("<table>"), 2)
            self.assertGreater(count, 10)


class RenderGallery(unittest.TestCase):
    def test_version_is_cmakes_project_version(self):
        with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
            self.assertIn(f"project(Prism VERSION {render_gallery.version()}", f.read())

    def test_every_example_scene_is_rendered_into_a_system_section(self):
        class A:
            quick = True
        jobs = render_gallery.jobs_after_catalogue(A(), {k: k for k in ("render", "bluenoise", "rain", "water")},
                                                   "out")
        scenes = sorted(f for f in os.listdir(os.path.join(ROOT, "examples", "scenes")) if f.endswith(".json"))
        rendered = [j[3]["scene"] for j in jobs if j[2][0] == "render"]
        self.assertEqual(rendered, [f"examples/scenes/{s}" for s in scenes])
        sections = {s for s, _, _ in render_gallery.SECTIONS}
        self.assertTrue(all(j[0] in sections for j in jobs))
        self.assertEqual(sorted({j[3]["sampler"] for j in jobs if j[0] == "bluenoise" and "sampler" in j[3]}),
                         ["bluenoise", "sorted", "white"])
        self.assertTrue(any("diffraction" in j[3]["scene"] for j in jobs if j[0] == "diffraction"))

    def test_scene_captions_carry_the_first_sentence_of_the_scene_comment(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "s.json")
            with open(path, "w") as f:
                json.dump({"comment": "Fog: every shader with FOG=1. More text here."}, f)
            self.assertEqual(render_gallery.scene_summary(path), "Fog: every shader with FOG=1")
            with open(path, "w") as f:
                json.dump({"comment": "A lit torus. Second sentence."}, f)
            self.assertEqual(render_gallery.scene_summary(path), "A lit torus")
            with open(path, "w") as f:
                json.dump({"camera": {}}, f)
            self.assertEqual(render_gallery.scene_summary(path), "")


class GalleryLive(unittest.TestCase):
    """The live views' data: one plain script per mesh with its exact float32 arrays and its
    PNGs as data: URIs, and the section placed right after the catalogue's."""

    def test_mesh_parts_keep_the_floats_exactly_and_embed_each_png(self):
        import base64
        import struct
        record = {"meshes": {"torus": {"positions": [0.1, -2.5, 3.0], "normals": [0.0, 1.0, 0.0], "indices": [0]},
                             "torus.1": {"positions": [1.0, 2.0, 3.0], "normals": [], "indices": [0]}},
                  "views": [{"png": "p.png", "mesh": "torus.1"}]}
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "p.png"), "wb") as f:
                f.write(b"\x89PNG-bytes")
            parts = gallery_live.mesh_parts(d, record)
        self.assertEqual(list(parts), ["torus"])
        floats = struct.unpack("<3f", base64.b64decode(parts["torus"]["meshes"]["torus"]["positions"]))
        self.assertEqual(floats, struct.unpack("<3f", struct.pack("<3f", 0.1, -2.5, 3.0)))
        self.assertEqual(parts["torus"]["pngs"]["p.png"],
                         "data:image/png;base64," + base64.b64encode(b"\x89PNG-bytes").decode())

    def test_live_section_follows_the_catalogue(self):
        page = gallery_report.build_html(manifest(), live='<section id="live"></section>')
        self.assertLess(page.index('<section id="catalogue"'), page.index('<section id="live"'))
        self.assertLess(page.index('<section id="live"'), page.index('<section id="water"'))

    def test_no_live_section_without_its_data(self):
        with tempfile.TemporaryDirectory() as d:
            self.assertEqual(gallery_live.live_html(d), "")


if __name__ == "__main__":
    unittest.main()
