"""A minimal PNG reader for the report's browser test: 8-bit grey, RGB, grey+alpha and RGBA,
non-interlaced (what Chromium's --screenshot writes), decoded into rows of pixel tuples."""
import struct
import zlib

CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def read_png(path):
    """(width, height, channels, rows): rows is a list of bytearrays of width*channels bytes."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG file")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in CHANNELS or interlace:
        raise ValueError(f"{path}: only 8-bit non-interlaced grey/RGB(A) PNGs are read here")
    ch = CHANNELS[colour]
    raw, stride = zlib.decompress(idat), width * ch
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - ch] if i >= ch else 0
            up, upleft = prev[i], prev[i - ch] if i >= ch else 0
            pred = (0, left, up, (left + up) // 2, _paeth(left, up, upleft))[kind]
            line[i] = (line[i] + pred) & 0xFF
        rows.append(line)
        prev = line
    return width, height, ch, rows


def distinct_colours(path, step=4):
    """Distinct RGB colours on a grid of every step-th pixel, and the share of sampled pixels
    that differ from the most common one."""
    width, height, ch, rows = read_png(path)
    counts = {}
    for y in range(0, height, step):
        row = rows[y]
        for x in range(0, width, step):
            key = bytes(row[x * ch:x * ch + min(ch, 3)])
            counts[key] = counts.get(key, 0) + 1
    total = sum(counts.values())
    return len(counts), 1.0 - max(counts.values()) / total
