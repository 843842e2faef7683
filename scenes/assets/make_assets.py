#!/usr/bin/env python3
"""Regenerates the corpus's own assets (no third-party files):

  uv_grid.png      256x256 sRGB test grid: hue varies with u, brightness with
                   v, dark lines every 1/8, a white marker in the (u,v)=(0,0)
                   corner so orientation mistakes show.
  knot.obj/.mtl    a (2,3) torus knot tube with texture coordinates, normals
                   and two MTL materials (alternate segments).

Pure Python (zlib + struct), deterministic output: run it from this folder.
"""
import colorsys
import math
import struct
import zlib


def write_png(path, width, height, pixel):
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter: none
        for x in range(width):
            rows.extend(pixel(x, y))

    def chunk(tag, data):
        body = tag + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", header))
        f.write(chunk(b"sRGB", b"\x00"))
        f.write(chunk(b"IDAT", zlib.compress(bytes(rows), 9)))
        f.write(chunk(b"IEND", b""))


def uv_grid(x, y, size=256):
    u = (x + 0.5) / size
    v = 1.0 - (y + 0.5) / size  # image row 0 is v = 1
    if u < 0.08 and v < 0.08:
        return (255, 255, 255)
    r, g, b = colorsys.hsv_to_rgb(u, 0.75, 0.35 + 0.6 * v)
    if (x % 32) in (0, 31) or (y % 32) in (0, 31):
        r, g, b = r * 0.25, g * 0.25, b * 0.25
    return tuple(int(round(c * 255)) for c in (r, g, b))


def torus_knot(path_obj, path_mtl, p=2, q=3, segments=180, sides=12, tube=0.18):
    def centre(t):
        r = 0.8 + 0.35 * math.cos(q * t)
        return (r * math.cos(p * t), 0.35 * math.sin(q * t), r * math.sin(p * t))

    def sub(a, b): return tuple(x - y for x, y in zip(a, b))
    def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
    def norm(a):
        n = math.sqrt(sum(x * x for x in a))
        return tuple(x / n for x in a)

    vertices, normals, uvs = [], [], []
    for i in range(segments + 1):
        t = 2 * math.pi * i / segments
        c0, c1 = centre(t), centre(t + 1e-3)
        tangent = norm(sub(c1, c0))
        side = norm(cross(tangent, (0.0, 1.0, 0.0)))
        up = cross(side, tangent)
        for j in range(sides + 1):
            a = 2 * math.pi * j / sides
            n = tuple(math.cos(a) * s + math.sin(a) * u for s, u in zip(side, up))
            vertices.append(tuple(c + tube * k for c, k in zip(c0, n)))
            normals.append(n)
            uvs.append((i / segments * 8.0, j / sides))
    with open(path_mtl, "w") as f:
        f.write("# two materials for knot.obj, made by make_assets.py\n")
        f.write("newmtl copper\nKd 0.80 0.42 0.25\nKs 0.30 0.30 0.30\nNs 60\n\n")
        f.write("newmtl teal\nKd 0.15 0.55 0.55\nKs 0.10 0.10 0.10\nNs 20\n")
    with open(path_obj, "w") as f:
        f.write("# (2,3) torus knot tube, made by make_assets.py\nmtllib knot.mtl\n")
        for v in vertices: f.write("v %.4f %.4f %.4f\n" % v)
        for n in normals: f.write("vn %.4f %.4f %.4f\n" % n)
        for t in uvs: f.write("vt %.4f %.4f\n" % t)
        stride = sides + 1
        for i in range(segments):
            f.write("usemtl %s\n" % ("copper" if (i // 20) % 2 == 0 else "teal"))
            for j in range(sides):
                a = i * stride + j + 1
                b, c, d = a + stride, a + stride + 1, a + 1
                f.write("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a, a, a, b, b, b, c, c, c))
                f.write("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a, a, a, c, c, c, d, d, d))


if __name__ == "__main__":
    write_png("uv_grid.png", 256, 256, uv_grid)
    torus_knot("knot.obj", "knot.mtl")
