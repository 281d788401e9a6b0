#!/usr/bin/env python3
"""Opens docs/web.md's example page (examples/web/index.html) in headless Chromium with the
project's web catalogue and prism_web.js beside it, as docs/web.md tells a reader to, and
checks that it drew Phong with Blinn highlights: "drew BLINN=1,... with N colours", N >= 64.

    python3 tests/report/check_web_example.py BUILD_DIR
Exit 0 when it drew; 1 naming what it saw.
"""
import os
import re
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from check_in_browser import chromium  # noqa: E402  (the one way the tier starts Chromium)


def main(argv):
    build = argv[1]
    with tempfile.TemporaryDirectory(prefix="prism-web-example-") as tmp:
        shutil.copyfile(os.path.join(ROOT, "examples", "web", "index.html"), os.path.join(tmp, "index.html"))
        shutil.copyfile(os.path.join(ROOT, "scripts", "web", "prism_web.js"), os.path.join(tmp, "prism_web.js"))
        shutil.copyfile(os.path.join(build, "web", "prism_shaders.js"), os.path.join(tmp, "prism_shaders.js"))
        dom = chromium("chromium", os.path.join(tmp, "profile"), "--dump-dom", "file://" + os.path.join(tmp, "index.html"))
    m = re.search(r'<pre id="result">drew (\S+) with (\d+) colours</pre>', dom.stdout)
    if not m or "BLINN=1" not in m.group(1) or int(m.group(2)) < 64:
        seen = re.search(r'<pre id="result">(.*?)</pre>', dom.stdout, re.S)
        print(f"examples/web/index.html: error: the example did not draw Blinn-Phong: "
              f"{seen.group(1) if seen else 'no result'} (chromium exit {dom.returncode}) {dom.stderr[-300:]}")
        return 1
    print(f"examples/web/index.html: drew {m.group(1)} with {m.group(2)} colours")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
