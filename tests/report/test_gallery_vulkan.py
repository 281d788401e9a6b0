#!/usr/bin/env python3
"""scripts/gallery_vulkan.py (report.vulkan_section, label unit): the "Vulkan and GL agree"
grid puts each image's largest difference in its shader's row and its mesh's column, and
names the worst; render_gallery runs prism-agreement for it."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import gallery_vulkan  # noqa: E402

TSV = ("shader\tvariant\tmesh\tmax\twithin2\tmean\n"
       "phong\t\tsphere\t0\t1\t0\n"
       "phong\t\ttorus\t1\t1\t0.0001\n"
       "phong\tBLINN=1\tsphere\t7\t0.99\t0.02\n"
       "phong\tBLINN=1\ttorus\t2\t1\t0\n")


class GridTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        os.makedirs(os.path.join(self.dir.name, "vulkan"))
        with open(os.path.join(self.dir.name, "vulkan", "agreement.tsv"), "w") as f:
            f.write(TSV)
        self.html = gallery_vulkan.grid_html(self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def test_rows_are_shader_variants_and_columns_meshes(self):
        self.assertIn("<th>sphere</th><th>torus</th>", self.html)
        self.assertIn("<tr><th>phong</th><td>0</td><td>1</td></tr>", self.html)
        self.assertIn("<tr><th>phong BLINN=1</th><td>7</td><td>2</td></tr>", self.html)

    def test_names_the_largest_difference(self):
        self.assertIn("Largest difference over all 4 images: 7/255.", self.html)

    def test_the_job_runs_prism_agreement_into_the_section(self):
        section, _, cmd, image = gallery_vulkan.job({"agreement": "/bin/prism-agreement"}, "out", True)
        self.assertEqual(section, gallery_vulkan.SECTION[0])
        self.assertEqual(cmd[:3], ["/bin/prism-agreement", "--out", os.path.join("out", "vulkan")])
        self.assertEqual(image["src"], gallery_vulkan.PAIR)


if __name__ == "__main__":
    unittest.main()
