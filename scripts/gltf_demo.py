#!/usr/bin/env python3
"""Writes firsthit's own animated glTF (make gltf-demo): a cart that drives
across a floor on two spinning wheels (a node hierarchy, LINEAR translation
and LINEAR rotation by slerp), a ball that bounces (CUBICSPLINE), a beacon
that hops from post to post (STEP), a tentacle that sways (a skin of three
joints), a blob that squashes (a morph target, its weight animated), a
camera on a node, a directional, a point and a spot light
(KHR_lights_punctual), a floor of textured tiles (a PNG repeated,
KHR_texture_transform; their rims bevelled by a normal texture) and a trellis whose bars are a cutout (alphaMode
MASK): the floor shows through its holes, and the sun throws the grid's
shadow; a pane of blue glass (alphaMode BLEND) before the blob, which
dims the light through it. One .gltf file, its buffer and images in data:
URIs; glTF is y-up.

    python3 scripts/gltf_demo.py OUT.gltf
"""
import base64
import json
import math
import struct
import sys
import zlib


def box(sx, sy, sz):
    """A box centred on the origin: 24 vertices (flat faces), 12 triangles."""
    pos, nrm, idx = [], [], []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0, 0, 0]
            n[axis] = sign
            u, v = [(axis + 1) % 3, (axis + 2) % 3]
            base = len(pos)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0, 0, 0]
                p[axis] = sign
                p[u], p[v] = a, b
                pos.append([p[0] * sx / 2, p[1] * sy / 2, p[2] * sz / 2])
                nrm.append(n)
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            idx += [base + q for q in quad]
    return pos, nrm, idx


def wheel(radius, width, sides=24):
    """A cylinder along z (the axle), flat caps, smooth sides."""
    pos, nrm, idx = [], [], []
    for i in range(sides + 1):
        a = 2 * math.pi * i / sides
        c, s = math.cos(a), math.sin(a)
        for z in (-width / 2, width / 2):
            pos.append([radius * c, radius * s, z])
            nrm.append([c, s, 0])
    for i in range(sides):
        a, b, c_, d = 2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3
        idx += [a, c_, b, b, c_, d]
    for z, sign in ((-width / 2, -1), (width / 2, 1)):
        centre = len(pos)
        pos.append([0, 0, z])
        nrm.append([0, 0, sign])
        for i in range(sides):
            a = 2 * math.pi * i / sides
            pos.append([radius * math.cos(a), radius * math.sin(a), z])
            nrm.append([0, 0, sign])
        for i in range(sides):
            p, q = centre + 1 + i, centre + 1 + (i + 1) % sides
            idx += [centre, p, q] if sign > 0 else [centre, q, p]
    return pos, nrm, idx


def sphere(radius, rings=16, segments=32):
    pos, nrm, idx = [], [], []
    for r in range(rings + 1):
        t = math.pi * r / rings
        for s in range(segments + 1):
            p = 2 * math.pi * s / segments
            n = [math.sin(t) * math.cos(p), math.cos(t), math.sin(t) * math.sin(p)]
            pos.append([radius * c for c in n])
            nrm.append(n)
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            idx += [a, a + 1, b, b, a + 1, b + 1]
    return pos, nrm, idx


def tube(radius, height, rings=24, segments=24):
    """An open cylinder along +y from the origin, smooth, rings + 1 circles."""
    pos, nrm, idx = [], [], []
    for r in range(rings + 1):
        y = height * r / rings
        for s in range(segments + 1):
            a = 2 * math.pi * s / segments
            pos.append([radius * math.cos(a), y, radius * math.sin(a)])
            nrm.append([math.cos(a), 0, math.sin(a)])
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nrm, idx


def quat_axis_angle(axis, angle):
    n = math.sqrt(sum(c * c for c in axis))
    s = math.sin(angle / 2)
    return [axis[0] / n * s, axis[1] / n * s, axis[2] / n * s, math.cos(angle / 2)]


def quat_look(eye, target):
    """The rotation taking a camera's -z to look from eye at target, +y up."""
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(c * c for c in f))
    f = [c / n for c in f]
    yaw = math.atan2(-f[0], -f[2])
    pitch = math.asin(f[1])
    qy = quat_axis_angle([0, 1, 0], yaw)
    qx = quat_axis_angle([1, 0, 0], pitch)
    x1, y1, z1, w1 = qy
    x2, y2, z2, w2 = qx
    return [w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2, w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2, w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2]


def png(width, height, texel):
    """An 8-bit RGBA PNG of texel(x, y) -> (r, g, b, a), rows from the top."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in texel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def tile(x, y):
    """Floor tiles: two greys in a checker of 16-texel squares, a darker grout line."""
    if x % 16 == 0 or y % 16 == 0:
        return (70, 70, 78, 255)
    return (200, 196, 186, 255) if (x // 16 + y // 16) % 2 == 0 else (150, 160, 175, 255)


def tile_bumps(x, y):
    """The tiles' normal texture: each tile's rim, 3 texels wide, slopes down
    to the grout around it (a normal turned 45 degrees out of the tile: +x
    along u, +y up the image); the grout and the tile's top are flat."""
    def slope(i):  # -1 on a tile's first texels, +1 on its last, 0 between and on the grout
        k = i % 16
        return -1 if 1 <= k <= 3 else 1 if k >= 13 else 0
    sx, sy = slope(x), -slope(y)  # rows run down the image; +y is up
    n = (sx, sy, 1.0)
    length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
    return tuple(round((c / length * 0.5 + 0.5) * 255) for c in n) + (255,)


def trellis(x, y):
    """A trellis: wooden bars 4 texels wide every 16, see-through between (alpha 0)."""
    if x % 16 < 4 or y % 16 < 4:
        return (150, 100, 55, 255)
    return (0, 0, 0, 0)


def quad(sx, sz):
    """A horizontal square facing up (+y), centred on the origin, with texture coordinates 0..1."""
    pos = [[-sx / 2, 0, -sz / 2], [sx / 2, 0, -sz / 2], [sx / 2, 0, sz / 2], [-sx / 2, 0, sz / 2]]
    return pos, [[0, 1, 0]] * 4, [0, 2, 1, 0, 3, 2], [[0, 0], [1, 0], [1, 1], [0, 1]]


class Builder:
    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def accessor(self, values, kind, component=5126, target=None):
        """Floats (5126) or unsigned shorts/ints as a new buffer view and accessor."""
        while len(self.data) % 4:
            self.data.append(0)
        flat = [c for v in values for c in (v if isinstance(v, list) else [v])]
        fmt = {5126: "f", 5123: "H", 5125: "I"}[component]
        start = len(self.data)
        self.data += struct.pack("<%d%s" % (len(flat), fmt), *flat)
        view = {"buffer": 0, "byteOffset": start, "byteLength": len(self.data) - start}
        if target:
            view["target"] = target
        self.views.append(view)
        acc = {"bufferView": len(self.views) - 1, "componentType": component, "count": len(values), "type": kind}
        if kind == "VEC3" and component == 5126:
            acc["min"] = [min(v[i] for v in values) for i in range(3)]
            acc["max"] = [max(v[i] for v in values) for i in range(3)]
        if kind == "SCALAR" and component == 5126:
            acc["min"], acc["max"] = [min(values)], [max(values)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def mesh(self, shape, material, extra=None, targets=None):
        pos, nrm, idx = shape
        attributes = {"POSITION": self.accessor(pos, "VEC3", target=34962),
                      "NORMAL": self.accessor(nrm, "VEC3", target=34962)}
        attributes.update(extra or {})
        primitive = {"attributes": attributes, "indices": self.accessor(idx, "SCALAR", 5123, 34963),
                     "material": material}
        if targets:
            primitive["targets"] = [{"POSITION": self.accessor(t, "VEC3")} for t in targets]
        return {"primitives": [primitive]}


def main(out):
    b = Builder()
    materials = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.62, 0.7, 1], "metallicFactor": 0, "roughnessFactor": 0.9}},
        {"name": "cart", "pbrMetallicRoughness": {"baseColorFactor": [0.85, 0.15, 0.1, 1], "metallicFactor": 0, "roughnessFactor": 0.4}},
        {"name": "tyre", "pbrMetallicRoughness": {"baseColorFactor": [0.12, 0.12, 0.14, 1], "metallicFactor": 0, "roughnessFactor": 0.8}},
        {"name": "chrome", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.85, 0.95, 1], "metallicFactor": 1, "roughnessFactor": 0.15}},
        {"name": "beacon", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.85, 0.2, 1], "metallicFactor": 0, "roughnessFactor": 0.5},
         "emissiveFactor": [1, 0.75, 0.1]},
        {"name": "post", "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.5, 0.3, 1], "metallicFactor": 0, "roughnessFactor": 0.7}},
        {"name": "tentacle", "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.25, 0.75, 1], "metallicFactor": 0, "roughnessFactor": 0.35}},
        {"name": "blob", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.75, 0.6, 1], "metallicFactor": 0, "roughnessFactor": 0.3}},
        {"name": "trellis", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 1}, "metallicFactor": 0, "roughnessFactor": 0.9}},
        {"name": "glass", "alphaMode": "BLEND", "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.6, 1, 0.4], "metallicFactor": 0, "roughnessFactor": 0.1}},
    ]
    # The floor's tiles: 64 x 64 texels repeated, a tile a unit (a texture
    # transform scales the floor's coordinates, 1 a unit, by 0.25).
    materials[0]["pbrMetallicRoughness"]["baseColorFactor"] = [1, 1, 1, 1]
    materials[0]["pbrMetallicRoughness"]["baseColorTexture"] = {
        "index": 0, "extensions": {"KHR_texture_transform": {"scale": [0.25, 0.25]}}}
    # Their rims bevelled by a normal texture on the same coordinates.
    materials[0]["normalTexture"] = {
        "index": 2, "extensions": {"KHR_texture_transform": {"scale": [0.25, 0.25]}}}
    images = [{"uri": "data:image/png;base64," + base64.b64encode(png(64, 64, tile)).decode()},
              {"uri": "data:image/png;base64," + base64.b64encode(png(64, 64, trellis)).decode()},
              {"uri": "data:image/png;base64," + base64.b64encode(png(64, 64, tile_bumps)).decode()}]
    textures = [{"sampler": 0, "source": 0}, {"sampler": 1, "source": 1}, {"sampler": 0, "source": 2}]
    samplers = [{"magFilter": 9729, "wrapS": 10497, "wrapT": 10497},
                {"magFilter": 9728, "wrapS": 33071, "wrapT": 33071}]
    floor = box(14, 0.2, 8)
    floor_uv = b.accessor([[p[0], p[2]] for p in floor[0]], "VEC2")
    meshes = [b.mesh(floor, 0, {"TEXCOORD_0": floor_uv}), b.mesh(box(2.2, 0.8, 1.3), 1), b.mesh(wheel(0.45, 0.3), 2),
              b.mesh(sphere(0.6), 3), b.mesh(box(0.4, 0.4, 0.4), 4), b.mesh(box(0.3, 1.2, 0.3), 5)]
    nodes = [
        {"name": "floor", "mesh": 0, "translation": [0, -0.1, 0]},
        {"name": "cart", "mesh": 1, "translation": [-4, 0.85, 1.5], "children": [2, 3, 13, 14]},
        {"name": "front wheel", "mesh": 2, "translation": [0.75, -0.4, 0.75]},
        {"name": "back wheel", "mesh": 2, "translation": [-0.75, -0.4, 0.75]},
        {"name": "ball", "mesh": 3, "translation": [2.5, 0.6, -1.5]},
        {"name": "beacon", "mesh": 4, "translation": [-3, 1.4, -2.5]},
        {"name": "camera", "camera": 0, "translation": [0, 5.5, 11], "rotation": quat_look([0, 5.5, 11], [0, 0.5, 0])},
        {"name": "sun", "rotation": quat_look([0, 0, 0], [-0.5, -1, -0.8]), "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "lamp", "translation": [3, 4, 2], "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"name": "spot", "translation": [0, 1.0, 0], "rotation": quat_axis_angle([1, 0, 0], -math.pi / 2),
         "extensions": {"KHR_lights_punctual": {"light": 2}}},
    ]
    for x in (-3, 0, 3):  # the beacon's posts
        nodes.append({"name": "post %d" % x, "mesh": 5, "translation": [x, 0.6, -2.5]})
    nodes.append({"name": "front wheel (far side)", "mesh": 2, "translation": [0.75, -0.4, -0.75]})
    nodes.append({"name": "back wheel (far side)", "mesh": 2, "translation": [-0.75, -0.4, -0.75]})
    nodes[5]["children"] = [9]  # the spot shines down from the beacon
    scene_nodes = [0, 1, 4, 5, 6, 7, 8, 10, 11, 12]

    # The trellis: a 2.4-unit square roof at 1.9 over the right of the floor, which the cart drives under.
    pos, nrm, idx, uv = quad(2.4, 2.4)
    meshes.append(b.mesh((pos, nrm, idx), 8, {"TEXCOORD_0": b.accessor(uv, "VEC2")}))
    nodes.append({"name": "trellis", "mesh": len(meshes) - 1, "translation": [3.6, 1.9, 2.6]})
    scene_nodes.append(len(nodes) - 1)

    # A pane of blue glass (alphaMode BLEND, alpha 0.4: see-through, its
    # shadow 0.6 of the light) standing on the floor before the blob.
    pos, nrm, idx, uv = quad(2.0, 1.6)
    meshes.append(b.mesh((pos, nrm, idx), 9))
    nodes.append({"name": "glass", "mesh": len(meshes) - 1, "translation": [-4.6, 0.8, -0.9],
                  "rotation": quat_axis_angle([1, 0, 0], math.pi / 2)})
    scene_nodes.append(len(nodes) - 1)

    # A skin: a tube 2.4 tall standing at (5, 0, -2), its joints at heights
    # 0, 0.8 and 1.6, each vertex weighted between the two nearest (a tent
    # function of its height); the inverse bind matrices undo each joint's
    # place. The tube's own node stays at the origin: a skin's joints place it.
    base = [5, 0, -2]
    pos, nrm, idx = tube(0.28, 2.4)
    joints, weights = [], []
    for p in pos:
        h = p[1] / 0.8  # 0 .. 3 in joint spacings
        k = min(int(h), 1)
        f = min(h - k, 1.0)
        joints.append([k, k + 1, 0, 0])
        weights.append([1 - f, f, 0, 0])
    pos = [[p[0] + base[0], p[1] + base[1], p[2] + base[2]] for p in pos]
    extra = {"JOINTS_0": b.accessor(joints, "VEC4", 5123), "WEIGHTS_0": b.accessor(weights, "VEC4")}
    meshes.append(b.mesh((pos, nrm, idx), 6, extra))
    first_joint = len(nodes)
    nodes.append({"name": "tentacle", "mesh": len(meshes) - 1, "skin": 0})
    nodes.append({"name": "tentacle base", "translation": base, "children": [first_joint + 2]})
    nodes.append({"name": "tentacle middle", "translation": [0, 0.8, 0], "children": [first_joint + 3]})
    nodes.append({"name": "tentacle top", "translation": [0, 0.8, 0]})
    scene_nodes += [first_joint, first_joint + 1]
    binds = [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -base[0], -base[1] - 0.8 * j, -base[2], 1] for j in range(3)]
    skins = [{"name": "tentacle", "joints": [first_joint + 1, first_joint + 2, first_joint + 3],
              "inverseBindMatrices": b.accessor(binds, "MAT4")}]

    # A morph target: a sphere on the floor at (-5, 0.6, -2) that squashes,
    # half as tall and 1.3 times as wide, its bottom staying put.
    ball = sphere(0.6)
    squash = [[0.3 * p[0], -0.5 * (p[1] + 0.6), 0.3 * p[2]] for p in ball[0]]
    meshes.append(b.mesh(ball, 7, targets=[squash]))
    meshes[-1]["weights"] = [0]
    blob = len(nodes)
    nodes.append({"name": "blob", "mesh": len(meshes) - 1, "translation": [-5, 0.6, -2]})
    scene_nodes.append(blob)

    # LINEAR: the cart drives across in 4 s; its wheels turn (slerp through
    # four quarter turns a second: keys 90 degrees apart, the shorter arc).
    times = [i * 0.25 for i in range(17)]
    drive = b.accessor([[-4 + 2 * t, 0.85, 1.5] for t in times], "VEC3")
    spin = b.accessor([quat_axis_angle([0, 0, 1], -math.pi / 2 * i) for i in range(17)], "VEC4")
    t_in = b.accessor(times, "SCALAR")
    # CUBICSPLINE: three bounces; at each landing the ball leaves upward
    # (out-tangent +), at each top it is still (tangent 0).
    bounce_t = [0, 0.6, 1.2, 1.8, 2.4, 3.0, 3.6]
    heights = [0.6, 2.6, 0.6, 2.0, 0.6, 1.4, 0.6]
    v = 6.0  # units a second at a landing
    keys = []
    for i, h in enumerate(heights):
        landing = i % 2 == 0
        inn = [0, -v if landing else 0, 0]
        out_ = [0, v if landing and i < len(heights) - 1 else 0, 0]
        keys += [inn, [2.5, h, -1.5], out_]
    bounce_in = b.accessor(bounce_t, "SCALAR")
    bounce = b.accessor(keys, "VEC3")
    # STEP: the beacon hops post to post each second.
    hop_t = b.accessor([0, 1, 2, 3, 4], "SCALAR")
    hop = b.accessor([[-3, 1.4, -2.5], [0, 1.4, -2.5], [3, 1.4, -2.5], [0, 1.4, -2.5], [-3, 1.4, -2.5]], "VEC3")
    # The skin: the middle and top joints lean 25 degrees one way, then the
    # other (LINEAR, a key a second).
    sway = b.accessor([quat_axis_angle([0, 0, 1], a) for a in (0, 0.44, 0, -0.44, 0)], "VEC4")
    # The morph: squashed at each half second, round at each whole (LINEAR).
    squash_t = b.accessor([i * 0.5 for i in range(9)], "SCALAR")
    squash_w = b.accessor([i % 2 for i in range(9)], "SCALAR")
    animation = {
        "name": "drive",
        "samplers": [{"input": t_in, "output": drive, "interpolation": "LINEAR"},
                     {"input": t_in, "output": spin, "interpolation": "LINEAR"},
                     {"input": bounce_in, "output": bounce, "interpolation": "CUBICSPLINE"},
                     {"input": hop_t, "output": hop, "interpolation": "STEP"},
                     {"input": hop_t, "output": sway, "interpolation": "LINEAR"},
                     {"input": squash_t, "output": squash_w, "interpolation": "LINEAR"}],
        "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}},
                     {"sampler": 1, "target": {"node": 2, "path": "rotation"}},
                     {"sampler": 1, "target": {"node": 3, "path": "rotation"}},
                     {"sampler": 1, "target": {"node": 13, "path": "rotation"}},
                     {"sampler": 1, "target": {"node": 14, "path": "rotation"}},
                     {"sampler": 2, "target": {"node": 4, "path": "translation"}},
                     {"sampler": 3, "target": {"node": 5, "path": "translation"}},
                     {"sampler": 4, "target": {"node": first_joint + 2, "path": "rotation"}},
                     {"sampler": 4, "target": {"node": first_joint + 3, "path": "rotation"}},
                     {"sampler": 5, "target": {"node": blob, "path": "weights"}}],
    }
    gltf = {
        "asset": {"version": "2.0", "generator": "firsthit scripts/gltf_demo.py"},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_texture_transform"],
        "scene": 0,
        "scenes": [{"nodes": scene_nodes}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "images": images,
        "textures": textures,
        "samplers": samplers,
        "skins": skins,
        "cameras": [{"name": "front", "type": "perspective", "perspective": {"yfov": 0.75, "aspectRatio": 16 / 9, "znear": 0.1}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "sun", "type": "directional", "color": [1, 0.95, 0.85], "intensity": 1.2},
            {"name": "lamp", "type": "point", "color": [0.8, 0.9, 1], "intensity": 6},
            {"name": "spot", "type": "spot", "color": [1, 0.8, 0.3], "intensity": 8, "spot": {"outerConeAngle": 0.7}}]}},
        "animations": [animation],
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": [{"byteLength": len(b.data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(b.data)).decode()}],
    }
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    if len(sys.argv) != 2 or sys.argv[1].startswith("-"):
        sys.exit(__doc__)
    main(sys.argv[1])
