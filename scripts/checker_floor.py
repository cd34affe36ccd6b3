#!/usr/bin/env python3
"""Writes a glTF of a checkerboard floor that recedes to the horizon: the
scene where one sample a pixel aliases most, for measuring what mipmaps
give: `firsthit accuracy` on it, and on the file written with
--no-mipmaps (docs/gltf.md, "Textures"). A 200 x 200 square at y = 0 carries a
256 x 256 texture of 8 x 8-texel squares (sRGB 230 and a dark blue),
repeated 25 times each way; the camera stands 1.5 above it, 20 from its
near edge, looking 11.5 degrees down. Its PNG, buffer and all are in
data: URIs; glTF is y-up.

    python3 scripts/checker_floor.py OUT.gltf [--no-mipmaps]

--no-mipmaps gives its sampler minFilter LINEAR (9729): the image itself,
however far away, as before firsthit had mipmaps.
"""
import base64
import json
import math
import struct
import sys
import zlib


def png(width, height, rows):
    """An 8-bit RGB PNG of these rows (bytes, 3 a texel)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = b"".join(b"\0" + row for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def uri(mime, data):
    return "data:" + mime + ";base64," + base64.b64encode(data).decode()


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out, sharp = sys.argv[1], "--no-mipmaps" in sys.argv[2:]
    n, square = 256, 8
    light, dark = bytes([230, 230, 230]), bytes([20, 20, 60])
    rows = [b"".join(light if (x // square + y // square) % 2 else dark for x in range(n)) for y in range(n)]
    half, repeats = 100.0, 25.0
    positions = [-half, 0, -half, half, 0, -half, half, 0, half, -half, 0, half]
    uvs = [0, 0, repeats, 0, repeats, repeats, 0, repeats]
    indices = [0, 2, 1, 0, 3, 2]  # facing +y
    buffer = struct.pack("<12f", *positions) + struct.pack("<8f", *uvs) + struct.pack("<6H", *indices) + b"\0\0"
    tilt = math.radians(11.5)  # about x, looking down
    sampler = {"wrapS": 10497, "wrapT": 10497}
    if sharp:
        sampler["minFilter"] = 9729
    gltf = {
        "asset": {"version": "2.0", "generator": "firsthit scripts/checker_floor.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "floor", "mesh": 0},
                  {"name": "camera", "camera": 0, "translation": [0, 1.5, 20],
                   "rotation": [-math.sin(tilt / 2), 0, 0, math.cos(tilt / 2)]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "aspectRatio": 16 / 9, "znear": 0.1}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"name": "checker", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "metallicFactor": 0, "roughnessFactor": 1}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [sampler],
        "images": [{"uri": uri("image/png", png(n, n, rows))}],
        "buffers": [{"byteLength": len(buffer), "uri": uri("application/octet-stream", buffer)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [-half, 0, -half], "max": [half, 0, half]},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
