#!/usr/bin/env python3
"""Shows that the report's checks fail when the report is broken (CTest
report.browser_detects_breakage): on copies of a good gallery it corrupts one PNG, drops
a system's section, blanks the page, and deletes a linked file, and expects
check_in_browser.py / check_links.py to fail naming the fault. It also opens the page with
WebGL disabled and expects the live section's one line saying so (docs/web.md).

    python3 tests/report/mutation_check.py GALLERY_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from check_in_browser import chromium  # noqa: E402


def run(script, *args):
    proc = subprocess.run([sys.executable, os.path.join(HERE, script), *args], capture_output=True, text=True)
    return proc.returncode, proc.stdout + proc.stderr


def expect_failure(name, rc, output, needle):
    if rc == 0 or needle not in output:
        print(f"mutation '{name}' was not caught (exit {rc}; expected a message with '{needle}'):\n{output}")
        return False
    print(f"mutation '{name}' caught: exit {rc}")
    return True


def main(argv):
    gallery = argv[1]
    ok = True
    with tempfile.TemporaryDirectory() as tmp:
        def fresh(name):  # without the live views, whose checks these faults do not concern (and cost time)
            copy = os.path.join(tmp, name)
            shutil.copytree(gallery, copy, ignore=shutil.ignore_patterns("live", "live-views.json"))
            return copy

        g = fresh("broken-image")
        with open(os.path.join(g, "scenes", "fog.png"), "wb") as f:
            f.write(b"not a png")
        rc, out = run("check_in_browser.py", g, "--screenshot", os.path.join(tmp, "a.png"))
        ok &= expect_failure("corrupt scenes/fog.png", rc, out, "scenes/fog.png")

        g = fresh("no-water")
        page = os.path.join(g, "index.html")
        with open(page) as f:
            text = f.read()
        with open(page, "w") as f:
            f.write(re.sub(r'<section id="water".*?</section>', "", text, flags=re.S))
        rc, out = run("check_in_browser.py", g, "--screenshot", os.path.join(tmp, "b.png"))
        ok &= expect_failure("water section removed", rc, out, "section 'water' is missing")

        g = fresh("blank")
        with open(os.path.join(g, "index.html"), "w") as f:
            f.write("<!DOCTYPE html><html><body></body></html>\n")
        rc, out = run("check_in_browser.py", g, "--screenshot", os.path.join(tmp, "c.png"))
        ok &= expect_failure("blank page", rc, out, "looks blank")

        # Without WebGL2 the live section says so in one line (and the PNGs are static <img>).
        dom = chromium("chromium", os.path.join(tmp, "profile"), "--disable-3d-apis", "--virtual-time-budget=10000",
                       "--dump-dom", "file://" + os.path.abspath(os.path.join(gallery, "index.html"))).stdout
        line = "This browser has no WebGL2, so the live views are off; every PNG below still shows."
        if os.path.exists(os.path.join(gallery, "live-views.json")) and line not in dom:
            print(f"without WebGL2 the page does not say '{line}'")
            ok = False
        else:
            print("without WebGL2: the page says so")

        g = fresh("missing-file")
        os.remove(os.path.join(g, "gallery.png"))
        rc, out = run("check_links.py", os.path.join(g, "index.html"))
        ok &= expect_failure("gallery.png deleted", rc, out, "gallery.png does not exist")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
