#!/usr/bin/env python3
"""Pixel checks of player-view pictures, on Python's standard library only
(no numpy or PIL on the test machines): a PNG reader for OpenCV's 8-bit RGB
or grey output, and a P5 reader for the map.

  view_pixels.py pixel FILE.png X Y
      prints "R G B" of pixel (X, Y), column and row from the top left
  view_pixels.py walls FILE.png MAP.pnm RESOLUTION CX CY SPAN
      the picture shows the map (negated, bottom-left corner at the origin)
      centred on (CX, CY) with SPAN metres across: wall pixels are black (or
      carry a laser point), free ones are not black, outside the map is
      grey, and the laser's points lie on walls (or the map's edge, where
      the simulated world ends). Prints the fractions; exit status 1 when one is off.
"""
import math
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (0, 2) or interlace:
                raise SystemExit(f"{path}: only 8-bit grey or RGB, not interlaced")
            channels = 3 if colour == 2 else 1
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous, at = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                pred = left if pa <= pb and pa <= pc else up if pb <= pc else corner
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        previous = line
    if channels == 1:
        rows = [bytearray(b for v in row for b in (v, v, v)) for row in rows]
    return width, height, rows


def read_pgm(path):
    data = open(path, "rb").read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    if fields[0] != b"P5" or int(fields[3]) != 255:
        raise SystemExit(f"{path}: only 8-bit P5")
    width, height = int(fields[1]), int(fields[2])
    return width, height, data[pos + 1:pos + 1 + width * height]


def pixel(rows, x, y):
    return tuple(rows[y][3 * x:3 * x + 3])


LASER = {(0, 60, 220), (255, 140, 0)}


def walls(png, pnm, resolution, cx, cy, span):
    width, height, rows = read_png(png)
    map_width, map_height, cells = read_pgm(pnm)
    ppm = width / span

    def state(x, y):
        """'wall', 'free', 'unknown' or None outside the map (negated image)."""
        col, row = int(x // resolution), int(y // resolution)
        if col < 0 or row < 0 or col >= map_width or row >= map_height:
            return None
        v = cells[(map_height - 1 - row) * map_width + col] / 255.0
        return "wall" if v > 0.65 else "free" if v < 0.196 else "unknown"

    counts = {"wall": 0, "wall_dark": 0, "free": 0, "free_black": 0, "outside": 0, "outside_grey": 0}
    laser_points = laser_on_walls = 0
    for py in range(height):
        for px in range(width):
            # The legend (top left) and the scale bar (bottom left) cover the map.
            if (px < 230 and py < 100) or (px < 200 and py >= height - 30):
                continue
            x = cx + (px + 0.5 - width / 2) / ppm
            y = cy - (py + 0.5 - height / 2) / ppm
            here, colour = state(x, y), pixel(rows, px, py)
            if here == "wall":
                counts["wall"] += 1
                counts["wall_dark"] += colour == (0, 0, 0) or colour in LASER
            elif here == "free":
                counts["free"] += 1
                counts["free_black"] += colour == (0, 0, 0)
            elif here is None:
                counts["outside"] += 1
                counts["outside_grey"] += colour == (205, 205, 205)
            if colour == LASER_POINT:
                laser_points += 1
                # Within 10 cm: a dot is 3 pixels wide (6 cm at 50 pixels a
                # metre), and the simulator's beams stop a few centimetres
                # short of the map's edge, where its world ends.
                laser_on_walls += any(state(x + 0.1 * math.cos(a * math.pi / 8), y + 0.1 * math.sin(a * math.pi / 8))
                                      in ("wall", None) or state(x, y) in ("wall", None) for a in range(16))
    fractions = {
        "walls drawn black": counts["wall_dark"] / max(1, counts["wall"]),
        "free drawn black": counts["free_black"] / max(1, counts["free"]),
        "outside drawn grey": counts["outside_grey"] / max(1, counts["outside"]),
        "laser points on walls": laser_on_walls / max(1, laser_points),
    }
    for name, value in fractions.items():
        print(f"{name}: {value:.3f}")
    print(f"pixels: {counts}, laser points: {laser_points}")
    ok = (counts["wall"] > 300 and fractions["walls drawn black"] > 0.8 and fractions["free drawn black"] < 0.01
          and (counts["outside"] == 0 or fractions["outside drawn grey"] > 0.95)
          and laser_points > 100 and fractions["laser points on walls"] > 0.9)
    return 0 if ok else 1


LASER_POINT = (0, 60, 220)

if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "pixel":
        _, _, rows = read_png(sys.argv[2])
        print(*pixel(rows, int(sys.argv[3]), int(sys.argv[4])))
    elif len(sys.argv) == 8 and sys.argv[1] == "walls":
        sys.exit(walls(sys.argv[2], sys.argv[3], *map(float, sys.argv[4:8])))
    else:
        sys.exit(__doc__)
