#!/usr/bin/env python3
"""Measures the live views' agreement with every llvmpipe PNG of the classic catalogue, not
only the ones the browser tier checks: for each view, it sets the page's own controls (mesh
and variant axes) to each PNG's combination in turn, waits for the view to measure, and
prints one line per PNG and the worst case per figure. The thresholds of
tests/report/check_in_browser.py (docs/web.md, "Agreement") come from its output.

    python3 tests/report/measure_live_agreement.py GALLERY_DIR
"""
import json
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from check_in_browser import chromium  # noqa: E402

# Walks every view record through the controls, one at a time, and writes the figures.
PROBE = """<script>
window.addEventListener('load', function () {
  var out = [], jobs = [];
  PrismGalleryLive.views.forEach(function (r) { jobs.push(r); });
  function set(view, r) {
    var mesh = r.mesh.split('.')[0];
    view.querySelectorAll('select, input[type=checkbox]').forEach(function (c) {
      var axis = c.getAttribute('data-axis');
      if (!axis && c.tagName === 'SELECT' && c.querySelector('option[value="' + mesh + '"]')) c.value = mesh;
      else if (c.type === 'checkbox') c.checked = r.defines[axis] === '1';
      else if (axis) c.value = r.defines[axis];
      c.dispatchEvent(new Event('change'));
    });
  }
  var pre = document.createElement('pre'); pre.id = 'measure'; document.body.appendChild(pre);
  function next() {
    pre.textContent = out.join('\\n');
    var r = jobs.shift();
    if (!r) return;
    var view = document.getElementById('live-' + r.shader);
    set(view, r);
    (function wait(tries) {
      var s = view.getAttribute('data-agreement-state');
      if ((s === 'done' && view.getAttribute('data-agreement-png') === r.png) || tries > 400) {
        out.push(JSON.stringify({png: r.png, state: s, max: view.getAttribute('data-agreement-max'),
                                 mean: view.getAttribute('data-agreement-mean'),
                                 within: view.getAttribute('data-agreement-within')}));
        next();
      } else setTimeout(function () { wait(tries + 1); }, 50);
    })(0);
  }
  window.onerror = function (m) { out.push(JSON.stringify({png: 'error ' + m, state: 'error'})); };
  setTimeout(next, 500);
});
</script>"""


def main(argv):
    gallery = argv[1]
    page = os.path.abspath(os.path.join(gallery, "index.html"))
    with open(page, encoding="utf-8") as f:
        text = f.read()
    probe = os.path.join(os.path.dirname(page), "index.measure-probe.html")
    with open(probe, "w", encoding="utf-8") as f:
        f.write(text.replace("</body>", PROBE + "</body>"))
    try:
        with tempfile.TemporaryDirectory() as profile:
            dom = chromium("chromium", profile, "--virtual-time-budget=120000", "--dump-dom", "file://" + probe)
    finally:
        os.remove(probe)
    m = re.search(r'<pre id="measure">(.*?)</pre>', dom.stdout, re.S)
    if not m:
        print(f"measure_live_agreement: no figures (chromium exit {dom.returncode})")
        return 1
    rows = [json.loads(line) for line in m.group(1).strip().splitlines()]
    for r in rows:
        print(f"{r['png']}: {r['state']} max {r['max']} mean {r['mean']} within {r['within']}")
    done = [r for r in rows if r["state"] == "done"]
    if done:
        print(f"worst of {len(done)}/{len(rows)}: max {max(int(r['max']) for r in done)}, "
              f"mean {max(float(r['mean']) for r in done):.4f}, within {min(float(r['within']) for r in done):.5f}")
    return 0 if len(done) == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
