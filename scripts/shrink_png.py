#!/usr/bin/env python3
"""Shrinks a PNG screenshot (8-bit RGB or RGBA, as the debugger writes it) to a 256-colour palette PNG.

    python3 scripts/shrink_png.py IN.png OUT.png [COLOURS]

Standard library only (no Pillow, pngquant or ImageMagick needed): median cut over the image's
distinct colours weighted by their pixel counts, each pixel mapped to its nearest palette colour
(no dithering: the UI's flat colours stay flat), written with zlib level 9. Alpha is dropped.
Used by scripts/screenshot.sh for docs/screenshot.png.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"shrink_png: {path}: not a PNG")
    pos, idat, hdr = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        typ, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if typ == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", body)
        elif typ == b"IDAT":
            idat += body
    w, h, depth, ctype, _, _, interlace = hdr
    if depth != 8 or ctype not in (2, 6) or interlace:
        sys.exit(f"shrink_png: {path}: only 8-bit RGB/RGBA, not interlaced (got {hdr})")
    bpp = 3 if ctype == 2 else 4
    raw, stride = zlib.decompress(idat), w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif f == 2:
            for i in range(stride):
                line[i] = (line[i] + prev[i]) & 255
        elif f == 3:
            for i in range(stride):
                line[i] = (line[i] + ((line[i - bpp] if i >= bpp else 0) + prev[i]) // 2) & 255
        elif f == 4:
            for i in range(stride):
                a, b = (line[i - bpp] if i >= bpp else 0), prev[i]
                c = prev[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([bytes(line[i:i + 3]) for i in range(0, stride, bpp)])
        prev = line
    return w, h, rows


def median_cut(hist, n):
    """hist: {rgb bytes: pixel count}; returns at most n colours, the count-weighted means of the boxes."""
    boxes = [[(tuple(c), k) for c, k in hist.items()]]

    def spread(box, k):
        return max(c[k] for c, _ in box) - min(c[k] for c, _ in box)

    def score(box):  # split wide boxes with many pixels first
        return -1 if len(box) < 2 else max(spread(box, k) for k in range(3)) * sum(m for _, m in box) ** 0.5

    scores = [score(boxes[0])]
    while len(boxes) < n:
        i = max(range(len(boxes)), key=scores.__getitem__)
        if scores[i] <= 0:
            break
        box = boxes[i]
        k = max(range(3), key=lambda k: spread(box, k))
        box.sort(key=lambda e: e[0][k])
        half, acc, cut = sum(m for _, m in box) / 2, 0, 1
        for j, (_, m) in enumerate(box):
            acc += m
            if acc >= half:
                cut = min(max(j, 1), len(box) - 1)
                break
        boxes[i:i + 1] = [box[:cut], box[cut:]]
        scores[i:i + 1] = [score(box[:cut]), score(box[cut:])]
    return [tuple(round(sum(c[k] * m for c, m in box) / sum(m for _, m in box)) for k in range(3))
            for box in boxes]


def chunk(typ, body):
    return struct.pack(">I", len(body)) + typ + body + struct.pack(">I", zlib.crc32(typ + body))


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: shrink_png.py IN.png OUT.png [COLOURS (2..256, default 256)]")
    colours = int(sys.argv[3]) if len(sys.argv) == 4 else 256
    w, h, rows = read_png(sys.argv[1])
    hist = {}
    for row in rows:
        for px in row:
            hist[px] = hist.get(px, 0) + 1
    pal = median_cut(hist, max(2, min(colours, 256)))
    index = {}
    for px in hist:
        r, g, b = px
        index[px] = min(range(len(pal)),
                        key=lambda i: (pal[i][0] - r) ** 2 + (pal[i][1] - g) ** 2 + (pal[i][2] - b) ** 2)
    raw = b"".join(b"\0" + bytes(index[px] for px in row) for row in rows)
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 3, 0, 0, 0))
           + chunk(b"PLTE", b"".join(bytes(c) for c in pal)) + chunk(b"IDAT", zlib.compress(raw, 9))
           + chunk(b"IEND", b""))
    with open(sys.argv[2], "wb") as f:
        f.write(png)


if __name__ == "__main__":
    main()
