#!/usr/bin/env python3
"""Test helper for `water --fog-billboards`: runs the water example twice on the same terrain
and rain, with and without billboards, and checks that the billboards add fog to the ground
view: the mean absolute difference of the two ground.png images over the ground half is
above a threshold (the runs are otherwise identical: the CPU step is deterministic).
   billboards_show.py WATER_EXE OUT_DIR"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "report"))
from png_read import read_png  # noqa: E402

MIN_MEAN_DIFF = 0.5  # 8-bit units over the lower half of the image (the ground)


def render(exe, out, extra):
    args = [exe, "--grid", "64", "--steps", "30", "--rain", "cloudburst", "--fog", "0.02",
            "--width", "160", "--height", "120", "--out", out] + extra
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return read_png(os.path.join(out, "ground.png"))


def mean_diff(a, b, first_row, last_row):
    total, count = 0, 0
    for y in range(first_row, last_row):
        ra, rb = a[3][y], b[3][y]
        for i in range(0, len(ra), a[2]):
            total += sum(abs(ra[i + c] - rb[i + c]) for c in range(3))
            count += 3
    return total / count


def main():
    exe, out = sys.argv[1], sys.argv[2]
    plain = render(exe, os.path.join(out, "plain"), [])
    fogged = render(exe, os.path.join(out, "billboards"), ["--fog-billboards", "0.8"])
    height = plain[1]
    ground = mean_diff(plain, fogged, height // 2, height)
    print(f"billboards: mean difference on the ground half {ground:.2f} (needs > {MIN_MEAN_DIFF})")
    if ground <= MIN_MEAN_DIFF:
        print("FAIL: --fog-billboards drew nothing visible")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
