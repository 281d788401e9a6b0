#!/usr/bin/env python3
"""Opens the gallery report in headless Chromium and checks what a reader would see:
every <img> loaded (naturalWidth > 0, recorded into the DOM by a probe copy of the page
and read back with --dump-dom), every system's section present with its images, and a
screenshot of the page that is not blank.

    python3 tests/report/check_in_browser.py GALLERY_DIR --screenshot OUT.png
        [--chromium chromium] [--scale 1.0]
Exit 0 when all hold; 1 listing each failure.
"""
import argparse
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png_read  # noqa: E402

# Appended to a copy of the page: after 'load', one line per <img> and per <section>.
PROBE = """<script>
window.addEventListener('load', function () {
  var lines = [];
  document.querySelectorAll('img').forEach(function (img) {
    lines.push('img ' + (img.complete ? img.naturalWidth : 0) + ' ' + img.getAttribute('src'));
  });
  document.querySelectorAll('section').forEach(function (s) {
    var imgs = s.querySelectorAll('img'), loaded = 0;
    imgs.forEach(function (img) { if (img.complete && img.naturalWidth > 0) loaded++; });
    lines.push('section ' + s.id + ' ' + imgs.length + ' ' + loaded);
  });
  var pre = document.createElement('pre');
  pre.id = 'browser-probe';
  pre.textContent = lines.join('\\n');
  document.body.appendChild(pre);
});
</script>"""


class ImgCounter(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images = 0

    def handle_starttag(self, tag, attrs):
        self.images += tag == "img"


def chromium(binary, profile, *args):
    cmd = [binary, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
           f"--user-data-dir={profile}", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=180)


def check(gallery, screenshot, binary="chromium", scale=1.0):
    """The list of failures (empty: the page is fine in the browser)."""
    page = os.path.abspath(os.path.join(gallery, "index.html"))
    with open(page, encoding="utf-8") as f:
        text = f.read()
    with open(os.path.join(gallery, "manifest.json")) as f:
        systems = [s["id"] for s in json.load(f)["sections"]]
    counter = ImgCounter()
    counter.feed(text)
    failures = []
    probe = os.path.join(os.path.dirname(page), "index.browser-probe.html")
    with open(probe, "w", encoding="utf-8") as f:
        f.write(text.replace("</body>", PROBE + "</body>"))
    profile = tempfile.mkdtemp(prefix="prism-chromium-")
    try:
        dom = chromium(binary, profile, "--virtual-time-budget=30000", "--dump-dom", "file://" + probe)
        m = re.search(r'<pre id="browser-probe">(.*?)</pre>', dom.stdout, re.S)
        if not m:
            return [f"chromium --dump-dom gave no probe output (exit {dom.returncode}): {dom.stderr[-500:]}"]
        lines = [line.split(" ", 3) for line in m.group(1).strip().splitlines()]
        imgs = [(int(w), src) for kind, w, src in (line[:3] for line in lines if line[0] == "img")]
        sections = {line[1]: (int(line[2]), int(line[3])) for line in lines if line[0] == "section"}
        if len(imgs) != counter.images:
            failures.append(f"the page has {counter.images} <img> but the browser saw {len(imgs)}")
        failures += [f"image did not load in the browser (naturalWidth 0): {src}" for w, src in imgs if w == 0]
        for sid in systems + ["trades", "docs"]:
            if sid not in sections:
                failures.append(f"section '{sid}' is missing")
            elif sid in systems and sections[sid][1] == 0:
                failures.append(f"section '{sid}' shows no loaded image")
        shot = chromium(binary, profile, "--window-size=1000,1300", f"--force-device-scale-factor={scale}",
                        f"--screenshot={os.path.abspath(screenshot)}", "file://" + page)
        if not os.path.exists(screenshot):
            failures.append(f"chromium --screenshot wrote nothing (exit {shot.returncode})")
        else:
            colours, busy = png_read.distinct_colours(screenshot)
            if colours < 64 or busy < 0.05:
                failures.append(f"{screenshot} looks blank: {colours} colours, {busy:.1%} of pixels off the background")
        print(f"browser: {len(imgs)} images, {sum(w > 0 for w, _ in imgs)} loaded; sections "
              + ", ".join(f"{k} ({v[1]}/{v[0]})" for k, v in sections.items()))
    finally:
        os.remove(probe)
        shutil.rmtree(profile, ignore_errors=True)
    return failures


def main(argv=None):
    p = argparse.ArgumentParser(description="check the gallery report in headless Chromium")
    p.add_argument("gallery")
    p.add_argument("--screenshot", required=True)
    p.add_argument("--chromium", default="chromium")
    p.add_argument("--scale", type=float, default=1.0, help="device scale factor of the screenshot")
    a = p.parse_args(argv)
    if not shutil.which(a.chromium):
        print(f"check_in_browser: error: {a.chromium} not found; run scripts/setup.sh (Debian package chromium)")
        return 1
    failures = check(a.gallery, a.screenshot, a.chromium, a.scale)
    for f in failures:
        print(f"{a.gallery}/index.html: error: {f}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
