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

# Appended to a copy of the page: after 'load', one line per <img> and per <section>; then,
# once every live view has measured its agreement, one "live first {...}" line per view, a
# click on each view's first enabled variant checkbox (the page's own control), and, once
# measured again, one "live toggled {...}" line per view.
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
  var views = Array.prototype.slice.call(document.querySelectorAll('.live-view'));
  var status = document.getElementById('live-status');
  if (status) lines.push('livestatus ' + status.textContent);
  function settled() {
    return views.every(function (v) {
      var s = v.getAttribute('data-agreement-state');
      return v.hasAttribute('data-live-error') || (s && s !== 'pending');
    });
  }
  function record(tag) {
    views.forEach(function (v) {
      var r = {};
      Array.prototype.forEach.call(v.attributes, function (a) { r[a.name] = a.value; });
      lines.push('live ' + tag + ' ' + JSON.stringify(r));
    });
  }
  function then(next, tries) {
    if (settled() || tries > 600) next(); else setTimeout(function () { then(next, tries + 1); }, 50);
  }
  then(function () {
    record('first');
    views.forEach(function (v) {
      var box = v.querySelector('input[type=checkbox][data-axis]:not([disabled])');
      if (box) box.click();
    });
    then(function () {
      record('toggled');
      var pre = document.createElement('pre');
      pre.id = 'browser-probe';
      pre.textContent = lines.join('\\n');
      document.body.appendChild(pre);
    }, 0);
  }, 0);
});
</script>"""

# The live views' thresholds against the llvmpipe PNGs (docs/web.md, "Agreement"): measured
# over all 44 PNGs of a --quick and of a full gallery (measure_live_agreement.py), then set just
# above the worst case (max 204/255, mean 0.1103/255, 98.644 % within 2/255).
LIVE_MAX = 210
LIVE_MEAN = 0.12
LIVE_WITHIN = 0.986
# The blue-noise soft-shadow view (scripts/web/live_bluenoise.js) against prism-bluenoise's
# CPU PNGs, frame 0 of the white and bluenoise samplers: the samples are the same integers on
# both sides and the shading agreed to the last bit in every run measured (docs/web.md), so
# its limits allow a rounding step and no more.
BLUENOISE_VIEW = "soft_shadows"
BLUENOISE_LIMITS = (2, 0.005, 0.999)  # max, mean (1/255), share within 2/255
LIVE_MIN_COLOURS = 2  # not one flat colour (unicolor draws two: its colour and the background)
LIVE_MIN_COVERED = 0.05  # share of the canvas off the background


def live_failures(records, shaders):
    """What is wrong with the live views: `records` maps ("first"|"toggled", shader) to the
    view's attributes; `shaders` maps each view's data-shader (the classic catalogue's shaders,
    and BLUENOISE_VIEW when the page has it) to its limits (max, mean, share within 2/255)."""
    failures = []
    for shader, limits in shaders.items():
        first, toggled = records.get(("first", shader)), records.get(("toggled", shader))
        if first is None:
            failures.append(f"live view of '{shader}' is missing")
            continue
        for tag, r in (("first", first), ("toggled", toggled)):
            failures += view_failures(f"live view '{shader}' ({tag})", r, limits)
        if toggled.get("data-live-checksum") == first.get("data-live-checksum"):
            failures.append(f"live view '{shader}': toggling {toggled.get('data-live-variant')} did not change the picture")
        if toggled.get("data-agreement-png") == first.get("data-agreement-png"):
            failures.append(f"live view '{shader}': after the toggle it still compares with {first.get('data-agreement-png')}")
    return failures


def view_failures(what, r, limits):
    if r.get("data-live-error"):
        return [f"{what}: {r['data-live-error']}"]
    failures = []
    if r.get("data-live-float-precision") != "highp":  # SwiftShader runs mediump at 32 bits: no pixel shows it
        failures.append(f"{what}: its fragment stage defaults floats to {r.get('data-live-float-precision')}, not highp")
    if int(r.get("data-live-colours", 0)) < LIVE_MIN_COLOURS or float(r.get("data-live-covered", 0)) < LIVE_MIN_COVERED:
        failures.append(f"{what} looks blank: {r.get('data-live-colours')} colours, "
                        f"{float(r.get('data-live-covered', 0)):.1%} off the background")
    if r.get("data-agreement-state") != "done":
        return failures + [f"{what}: no agreement measured (state {r.get('data-agreement-state')})"]
    m, mean, within = int(r["data-agreement-max"]), float(r["data-agreement-mean"]), float(r["data-agreement-within"])
    max_limit, mean_limit, within_limit = limits
    if m > max_limit or mean > mean_limit or within < within_limit:
        failures.append(f"{what} disagrees with {r['data-agreement-png']}: max {m}/255 (limit {max_limit}), mean "
                        f"{mean:.4f}/255 (limit {mean_limit}), {within:.3%} within 2/255 (limit {within_limit:.3%})")
    return failures


class ImgCounter(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images = 0

    def handle_starttag(self, tag, attrs):
        self.images += tag == "img"


def check_live(raw, manifest, gallery):
    """The live views' failures, from the probe's lines; prints each view's figures."""
    classic = (LIVE_MAX, LIVE_MEAN, LIVE_WITHIN)
    shaders = {i["shader"]: classic for s in manifest["sections"] if s["id"] == "catalogue"
               for i in s["images"] if i.get("shader")}
    if os.path.exists(os.path.join(gallery, "live", "bluenoise.js")):
        shaders[BLUENOISE_VIEW] = BLUENOISE_LIMITS
    records = {}
    for line in raw:
        if line.startswith("livestatus "):
            print("live:", line[len("livestatus "):])
        if line.startswith("live "):
            _, tag, body = line.split(" ", 2)
            r = json.loads(body)
            records[(tag, r.get("data-shader"))] = r
            print(f"live {tag} {r.get('data-shader')} {r.get('data-live-variant')}: against "
                  f"{r.get('data-agreement-png')} max {r.get('data-agreement-max')} mean {r.get('data-agreement-mean')} "
                  f"within {r.get('data-agreement-within')}; {r.get('data-live-colours')} colours")
    return live_failures(records, shaders)


def chromium(binary, profile, *args):
    # WebGL2 on SwiftShader through ANGLE: recent Chromium no longer falls back to it unasked.
    cmd = [binary, "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
           "--hide-scrollbars",
           f"--user-data-dir={profile}", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=180)


def check(gallery, screenshot, binary="chromium", scale=1.0):
    """The list of failures (empty: the page is fine in the browser)."""
    page = os.path.abspath(os.path.join(gallery, "index.html"))
    with open(page, encoding="utf-8") as f:
        text = f.read()
    with open(os.path.join(gallery, "manifest.json")) as f:
        manifest = json.load(f)
    systems = [s["id"] for s in manifest["sections"]]
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
        raw = html.unescape(m.group(1)).strip().splitlines()
        lines = [line.split(" ", 3) for line in raw]
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
        if os.path.exists(os.path.join(gallery, "live-views.json")):
            failures += check_live(raw, manifest, gallery)
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
