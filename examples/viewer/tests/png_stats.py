#!/usr/bin/env python3
"""Pixel statistics of a viewer --screenshot PNG for the gui tests (no third-party
modules): mean Rec. 709 luminance, distinct colours, and the panel layout.

  png_stats.py lit FILE MIN_LUMA MIN_COLOURS     the first frame is lit
  png_stats.py panels FILE PANEL_WIDTH MIN_HEADERS   the controls column and overlay are there
Prints what it measured; exits 1 when a check fails."""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), "expected 8-bit RGB or RGBA"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def luma(p):
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]


def lit(path, min_luma, min_colours):
    w, h, rows = read_png(path)
    pixels = [p for row in rows for p in row]
    mean = sum(luma(p) for p in pixels) / len(pixels)
    colours = len(set(pixels))
    print(f"lit: {w}x{h}, mean luminance {mean:.2f} (need > {min_luma}), {colours} colours (need > {min_colours})")
    return mean > min_luma and colours > min_colours


VIEW_BACKGROUND = (13, 15, 20)  # (0.05, 0.06, 0.08) in 8 bits


def is_header(p):  # ImGui's blue collapsing-header bar
    return p[2] > p[0] + 25 and p[2] > 60


def panels(path, panel_width, min_headers):
    w, h, rows = read_png(path)
    def view_share(x):  # pixels of the 3D view's clear colour (RenderJob::background)
        return sum(rows[y][x] == VIEW_BACKGROUND for y in range(0, h, 2)) / len(range(0, h, 2))
    edge = next((x for x in range(w) if view_share(x) > 0.2), w)
    headers, inside = 0, False
    for y in range(h):
        row = rows[y][10:min(300, w)]
        band = sum(is_header(p) for p in row) > 0.6 * len(row)
        headers += band and not inside
        inside = band
    ox0, ox1 = max(edge, w - 480), w - 8
    text = sum(luma(rows[y][x]) > 150 for y in range(8, 60) for x in range(ox0, ox1))
    print(f"panels: {w}x{h}, controls column {edge} px wide (expect {panel_width} +- 6), "
          f"{headers} panel headers (need >= {min_headers}), {text} light overlay pixels (need > 200)")
    return abs(edge - panel_width) <= 6 and headers >= min_headers and text > 200


if __name__ == "__main__":
    mode, path = sys.argv[1], sys.argv[2]
    ok = lit(path, float(sys.argv[3]), int(sys.argv[4])) if mode == "lit" else \
        panels(path, int(sys.argv[3]), int(sys.argv[4]))
    sys.exit(0 if ok else 1)
