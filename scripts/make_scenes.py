#!/usr/bin/env python3
"""Generate relt's scene suite (glTF 2.0 + external .bin) and scenes/README.md.

Usage (from the repository root):
    python3 scripts/make_scenes.py [--out scenes]      generate every scene, then check them
    python3 scripts/make_scenes.py --check [--out DIR] only check the files already in DIR
    python3 scripts/make_scenes.py --only ring         generate (and check) a subset

Python standard library only. The output is deterministic: byte-identical on every run.

Conventions (DESIGN.md section 5; repeated in scenes/README.md):
  * Y up, metres-ish. One scene. Scene extras carry width/height/max_depth/bench_width/bench_height.
  * The camera is a node with a perspective camera, looking down its local -Z with +Y up.
  * Triangles only (mode 4), indexed; POSITION always (with min/max), NORMAL only on smooth meshes.
  * Front face = side of cross(v1 - v0, v2 - v0). Dielectrics: that side is the OUTSIDE, so every
    glass/water mesh is closed and wound outwards (checked below). Emitters emit from their front
    face only (no doubleSided here).
  * Geometry is stored in world coordinates (identity mesh nodes); only the camera node is transformed.
"""
import argparse
import hashlib
import json
import math
import struct
import sys
from pathlib import Path

# --------------------------------------------------------------------------------------------
# Small vector helpers (tuples of floats)
# --------------------------------------------------------------------------------------------


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    n = length(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def rot_y(p, angle):
    """Rotate p about the +Y axis by angle (radians, right-handed: +X turns towards -Z)."""
    c, s = math.cos(angle), math.sin(angle)
    return (c * p[0] + s * p[2], p[1], -s * p[0] + c * p[2])


def f32(x):
    """The value x becomes once stored as a 32-bit float."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def look_at_quaternion(eye, target, up=(0.0, 1.0, 0.0)):
    """Unit quaternion [x, y, z, w] turning a glTF camera (looking down -Z, +Y up) towards target."""
    back = normalize(sub(eye, target))  # camera +Z
    right = normalize(cross(up, back))  # camera +X
    upv = cross(back, right)  # camera +Y
    m00, m01, m02 = right[0], upv[0], back[0]
    m10, m11, m12 = right[1], upv[1], back[1]
    m20, m21, m22 = right[2], upv[2], back[2]
    tr = m00 + m11 + m22
    if tr > 0.0:
        s = 0.5 / math.sqrt(tr + 1.0)
        w, x, y, z = 0.25 / s, (m21 - m12) * s, (m02 - m20) * s, (m10 - m01) * s
    elif m00 > m11 and m00 > m22:
        s = 2.0 * math.sqrt(1.0 + m00 - m11 - m22)
        w, x, y, z = (m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s
    elif m11 > m22:
        s = 2.0 * math.sqrt(1.0 + m11 - m00 - m22)
        w, x, y, z = (m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s
    else:
        s = 2.0 * math.sqrt(1.0 + m22 - m00 - m11)
        w, x, y, z = (m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s
    n = math.sqrt(x * x + y * y + z * z + w * w)
    if w < 0.0:  # canonical sign, purely cosmetic
        n = -n
    return [x / n, y / n, z / n, w / n]


def quat_rotate(q, v):
    x, y, z, w = q
    u = (x, y, z)
    t = mul(cross(u, v), 2.0)
    return add(add(v, mul(t, w)), cross(u, t))


# --------------------------------------------------------------------------------------------
# Mesh building
# --------------------------------------------------------------------------------------------


class MeshData:
    """Positions, optional per-vertex normals, triangles (index triples)."""

    def __init__(self, smooth=False):
        self.p = []
        self.n = [] if smooth else None
        self.t = []

    def vert(self, p, n=None):
        self.p.append(tuple(float(c) for c in p))
        if self.n is not None:
            self.n.append(normalize(n))
        return len(self.p) - 1

    def tri(self, a, b, c):
        self.t.append((a, b, c))

    def tri_facing(self, a, b, c, direction):
        """Triangle a b c, flipped if needed so that its front faces `direction`."""
        g = cross(sub(self.p[b], self.p[a]), sub(self.p[c], self.p[a]))
        if dot(g, direction) < 0.0:
            b, c = c, b
        self.tri(a, b, c)

    def tri_smooth(self, a, b, c):
        """Triangle oriented to agree with the mean of its vertex normals."""
        nm = add(add(self.n[a], self.n[b]), self.n[c])
        self.tri_facing(a, b, c, nm)

    def quad_facing(self, a, b, c, d, direction):
        """Planar convex quad a b c d (in order around it), front facing `direction`."""
        g = cross(sub(self.p[b], self.p[a]), sub(self.p[c], self.p[a]))
        if dot(g, direction) < 0.0:
            a, b, c, d = a, d, c, b
        self.tri(a, b, c)
        self.tri(a, c, d)

    def flip(self):
        self.t = [(a, c, b) for (a, b, c) in self.t]
        return self

    def append(self, other):
        off = len(self.p)
        self.p.extend(other.p)
        if self.n is not None:
            self.n.extend(other.n)
        self.t.extend((a + off, b + off, c + off) for (a, b, c) in other.t)
        return self

    def signed_volume(self):
        v = 0.0
        for a, b, c in self.t:
            v += dot(self.p[a], cross(self.p[b], self.p[c]))
        return v / 6.0


def quad(corners, facing):
    """A flat quad (2 triangles, no normals) from 4 corners in order around it."""
    m = MeshData()
    ids = [m.vert(c) for c in corners]
    m.quad_facing(*ids, facing)
    return m


def rect_y(x0, x1, z0, z1, y, facing_up):
    """Horizontal rectangle at height y, front facing +Y (facing_up) or -Y."""
    return quad([(x0, y, z0), (x1, y, z0), (x1, y, z1), (x0, y, z1)], (0.0, 1.0 if facing_up else -1.0, 0.0))


def rect_x(x, y0, y1, z0, z1, facing_pos):
    return quad([(x, y0, z0), (x, y1, z0), (x, y1, z1), (x, y0, z1)], (1.0 if facing_pos else -1.0, 0.0, 0.0))


def rect_z(z, x0, x1, y0, y1, facing_pos):
    return quad([(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)], (0.0, 0.0, 1.0 if facing_pos else -1.0))


def facing_quad(center, u, v, facing):
    """Quad centred at `center` spanned by half-edge vectors u, v, front towards `facing`."""
    corners = [add(add(center, mul(u, su)), mul(v, sv)) for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return quad(corners, facing)


def quad_towards(center, target, half, up=(0.0, 1.0, 0.0)):
    """Square of half-size `half` centred at `center`, its front facing `target` (a small light aimed at
    the objects); `up` must not be parallel to the direction to the target."""
    to_target = normalize(sub(target, center))
    u = normalize(cross(to_target, up))
    v = cross(u, to_target)
    return facing_quad(center, mul(u, half), mul(v, half), to_target)


def box(center, half, angle=0.0, open_bottom=False):
    """Closed box (8 shared vertices, 12 triangles, outward), rotated about Y by angle.
    open_bottom drops the -Y face (for opaque blocks standing on a floor, like the classic Cornell box)."""
    m = MeshData()
    for i in range(8):
        local = (half[0] * (1 if i & 1 else -1), half[1] * (1 if i & 2 else -1), half[2] * (1 if i & 4 else -1))
        m.vert(add(center, rot_y(local, angle)))
    faces = [(0, 4, 6, 2), (1, 3, 7, 5), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
    if not open_bottom:
        faces.append((0, 1, 5, 4))
    for a, b, c, d in faces:
        m.tri(a, b, c)
        m.tri(a, c, d)
    return m


def prism(top, y0, y1, open_bottom=True):
    """Vertical prism over the convex polygon `top` (list of (x, z)), outward faces.
    Used for the classic Cornell blocks, whose data give only the top and the four sides."""
    m = MeshData()
    k = len(top)
    lo = [m.vert((x, y0, z)) for x, z in top]
    hi = [m.vert((x, y1, z)) for x, z in top]
    cx = sum(x for x, _ in top) / k
    cz = sum(z for _, z in top) / k
    m.tri_facing(hi[0], hi[1], hi[2], (0, 1, 0))
    m.tri_facing(hi[0], hi[2], hi[3], (0, 1, 0))
    if not open_bottom:
        m.tri_facing(lo[0], lo[1], lo[2], (0, -1, 0))
        m.tri_facing(lo[0], lo[2], lo[3], (0, -1, 0))
    for i in range(k):
        j = (i + 1) % k
        mx = 0.5 * (top[i][0] + top[j][0]) - cx
        mz = 0.5 * (top[i][1] + top[j][1]) - cz
        m.quad_facing(lo[i], lo[j], hi[j], hi[i], (mx, 0.0, mz))
    return m


ICO_T = (1.0 + math.sqrt(5.0)) / 2.0
ICO_V = [(-1, ICO_T, 0), (1, ICO_T, 0), (-1, -ICO_T, 0), (1, -ICO_T, 0),
         (0, -1, ICO_T), (0, 1, ICO_T), (0, -1, -ICO_T), (0, 1, -ICO_T),
         (ICO_T, 0, -1), (ICO_T, 0, 1), (-ICO_T, 0, -1), (-ICO_T, 0, 1)]
ICO_F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
         (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
         (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
         (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]


def icosphere(center, radius, level, smooth):
    """Subdivided icosahedron, 20 * 4^level triangles, outward, shared vertices (watertight).
    smooth: with NORMAL (exact sphere normals)."""
    dirs = [normalize(v) for v in ICO_V]
    faces = list(ICO_F)
    for _ in range(level):
        cache = {}
        nf = []

        def mid(a, b):
            key = (a, b) if a < b else (b, a)
            if key not in cache:
                dirs.append(normalize(mul(add(dirs[a], dirs[b]), 0.5)))
                cache[key] = len(dirs) - 1
            return cache[key]

        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = nf
    m = MeshData(smooth)
    for d in dirs:
        m.vert(add(center, mul(d, radius)), d if smooth else None)
    for a, b, c in faces:
        m.tri_facing(a, b, c, add(add(dirs[a], dirs[b]), dirs[c]))
    return m


def torus(center, major, minor, nu, nv):
    """Smooth torus around the Y axis (lying flat), with NORMAL, outward."""
    m = MeshData(smooth=True)
    idx = {}
    for i in range(nu):
        u = 2.0 * math.pi * i / nu
        for j in range(nv):
            v = 2.0 * math.pi * j / nv
            n = (math.cos(v) * math.cos(u), math.sin(v), math.cos(v) * math.sin(u))
            ring = (math.cos(u) * major, 0.0, math.sin(u) * major)
            idx[i, j] = m.vert(add(center, add(ring, mul(n, minor))), n)
    for i in range(nu):
        for j in range(nv):
            a, b = idx[i, j], idx[(i + 1) % nu, j]
            c, d = idx[(i + 1) % nu, (j + 1) % nv], idx[i, (j + 1) % nv]
            m.tri_smooth(a, b, c)
            m.tri_smooth(a, c, d)
    return m


def faceted_ring(center, r_out, r_in, height, facets):
    """Closed annular band (a finger ring lying flat, axis vertical) with flat facets, no normals."""
    m = MeshData()
    ot, ob, it, ib = [], [], [], []
    for i in range(facets):
        a = 2.0 * math.pi * i / facets
        c, s = math.cos(a), math.sin(a)
        ob.append(m.vert(add(center, (r_out * c, 0.0, r_out * s))))
        ot.append(m.vert(add(center, (r_out * c, height, r_out * s))))
        ib.append(m.vert(add(center, (r_in * c, 0.0, r_in * s))))
        it.append(m.vert(add(center, (r_in * c, height, r_in * s))))
    for i in range(facets):
        j = (i + 1) % facets
        a = 2.0 * math.pi * (i + 0.5) / facets
        radial = (math.cos(a), 0.0, math.sin(a))
        m.quad_facing(ob[i], ob[j], ot[j], ot[i], radial)  # outer wall
        m.quad_facing(ib[i], ib[j], it[j], it[i], mul(radial, -1.0))  # inner wall (faces the axis)
        m.quad_facing(ot[i], ot[j], it[j], it[i], (0.0, 1.0, 0.0))  # top rim
        m.quad_facing(ob[i], ob[j], ib[j], ib[i], (0.0, -1.0, 0.0))  # bottom rim
    return m


def water_body(x0, x1, z0, z1, y_bottom, height_fn, grad_fn, n):
    """Closed water volume: a smooth (NORMAL) wavy top surface y = height_fn(x, z) over an n x n grid,
    flat vertical sides following the wavy rim and a flat bottom. Outward. The sides and the bottom
    have their own vertex copies (flat normals); positions along the rim are bit-identical, so the
    solid is watertight once vertices are welded by position."""
    m = MeshData(smooth=True)
    xs = [x0 + (x1 - x0) * i / n for i in range(n + 1)]
    zs = [z0 + (z1 - z0) * j / n for j in range(n + 1)]
    top = {}
    for j in range(n + 1):
        for i in range(n + 1):
            x, z = xs[i], zs[j]
            gx, gz = grad_fn(x, z)
            top[i, j] = m.vert((x, height_fn(x, z), z), (-gx, 1.0, -gz))
    for j in range(n):
        for i in range(n):
            a, b, c, d = top[i, j], top[i + 1, j], top[i + 1, j + 1], top[i, j + 1]
            m.tri_facing(a, b, c, (0, 1, 0))
            m.tri_facing(a, c, d, (0, 1, 0))
    # rim loop in grid coordinates (each face is oriented explicitly, so the loop direction does not matter)
    rim = [(i, 0) for i in range(n)] + [(n, j) for j in range(n)] + \
          [(i, n) for i in range(n, 0, -1)] + [(0, j) for j in range(n, 0, -1)]
    sides = [((0.0, 0.0, -1.0), lambda i, j: j == 0),
             ((1.0, 0.0, 0.0), lambda i, j: i == n),
             ((0.0, 0.0, 1.0), lambda i, j: j == n),
             ((-1.0, 0.0, 0.0), lambda i, j: i == 0)]
    for normal, on_side in sides:
        pts = [(i, j) for (i, j) in rim + [rim[0]] if on_side(i, j)]
        pts = sorted(set(pts))
        upper = [m.vert((xs[i], height_fn(xs[i], zs[j]), zs[j]), normal) for i, j in pts]
        lower = [m.vert((xs[i], y_bottom, zs[j]), normal) for i, j in pts]
        for k in range(len(pts) - 1):
            m.quad_facing(lower[k], lower[k + 1], upper[k + 1], upper[k], normal)
    down = (0.0, -1.0, 0.0)
    centre = m.vert((0.5 * (x0 + x1), y_bottom, 0.5 * (z0 + z1)), down)
    ring = [m.vert((xs[i], y_bottom, zs[j]), down) for i, j in rim]
    for k in range(len(ring)):
        m.tri_facing(centre, ring[k], ring[(k + 1) % len(ring)], down)
    return m


def hollow_box(center, outer_half, wall):
    """Thick-walled closed box: outer shell outward, inner (cavity) shell facing into the cavity,
    i.e. outward from the solid. A closed dielectric solid with a cavity of air."""
    m = box(center, outer_half)
    inner = box(center, tuple(h - wall for h in outer_half)).flip()
    return m.append(inner)


# --------------------------------------------------------------------------------------------
# glTF writer
# --------------------------------------------------------------------------------------------

EXT_TRANSMISSION = "KHR_materials_transmission"
EXT_IOR = "KHR_materials_ior"
EXT_STRENGTH = "KHR_materials_emissive_strength"


def lambert(name, albedo):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(albedo) + [1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": 1.0}}


def conductor(name, f0, roughness, microfacet=None):
    m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(f0) + [1.0],
                                                "metallicFactor": 1.0, "roughnessFactor": roughness}}
    if microfacet:
        m["extras"] = {"microfacet": microfacet}
    return m


def dielectric(name, ior, roughness=0.0):
    return {"name": name,
            "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0,
                                     "roughnessFactor": roughness},
            "extensions": {EXT_TRANSMISSION: {"transmissionFactor": 1.0}, EXT_IOR: {"ior": ior}}}


def emitter(name, radiance, albedo=(0.0, 0.0, 0.0)):
    """Area light with emitted radiance `radiance` (RGB): emissiveFactor (max component 1) x strength."""
    s = max(radiance)
    factor = [c / s for c in radiance]
    return {"name": name,
            "pbrMetallicRoughness": {"baseColorFactor": list(albedo) + [1.0], "metallicFactor": 0.0,
                                     "roughnessFactor": 1.0},
            "emissiveFactor": factor,
            "extensions": {EXT_STRENGTH: {"emissiveStrength": s}}}


class GltfScene:
    def __init__(self, name):
        self.name = name
        self.bin = bytearray()
        self.buffer_views = []
        self.accessors = []
        self.meshes = []
        self.materials = []
        self.material_ids = {}
        self.nodes = []
        self.cameras = []
        self.triangles = 0
        self.mesh_info = []  # (node name, material name, triangles) for the README

    def material(self, mat):
        if mat["name"] not in self.material_ids:
            self.material_ids[mat["name"]] = len(self.materials)
            self.materials.append(mat)
        return self.material_ids[mat["name"]]

    def _view(self, data, target):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.buffer_views.append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data),
                                  "target": target})
        self.bin += data
        return len(self.buffer_views) - 1

    def _vec3(self, values, with_bounds):
        data = b"".join(struct.pack("<3f", *v) for v in values)
        acc = {"bufferView": self._view(data, 34962), "componentType": 5126, "count": len(values),
               "type": "VEC3"}
        if with_bounds:
            stored = [tuple(f32(c) for c in v) for v in values]
            acc["min"] = [min(v[k] for v in stored) for k in range(3)]
            acc["max"] = [max(v[k] for v in stored) for k in range(3)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def add_mesh(self, name, mesh, mat, closed=None):
        """One node + one mesh with one primitive. closed: None, "outward" or "inward" (checked)."""
        n_vert = len(mesh.p)
        flat = [i for t in mesh.t for i in t]
        assert flat and max(flat) < n_vert and min(flat) >= 0, name
        if n_vert < 65535:
            idx = struct.pack("<%dH" % len(flat), *flat)
            ctype = 5123
        else:
            idx = struct.pack("<%dI" % len(flat), *flat)
            ctype = 5125
        attributes = {"POSITION": self._vec3(mesh.p, True)}
        if mesh.n is not None:
            attributes["NORMAL"] = self._vec3(mesh.n, False)
        self.accessors.append({"bufferView": self._view(idx, 34963), "componentType": ctype,
                               "count": len(flat), "type": "SCALAR"})
        prim = {"attributes": attributes, "indices": len(self.accessors) - 1, "material": self.material(mat),
                "mode": 4}
        m = {"name": name, "primitives": [prim]}
        if closed:
            m["extras"] = {"closed": closed}
        self.meshes.append(m)
        self.nodes.append({"name": name, "mesh": len(self.meshes) - 1})
        self.triangles += len(mesh.t)
        self.mesh_info.append((name, mat["name"], len(mesh.t)))

    def camera(self, name, eye, target, yfov, aspect=1.0):
        self.cameras.append({"name": name, "type": "perspective",
                             "perspective": {"yfov": yfov, "aspectRatio": aspect, "znear": 0.01}})
        self.nodes.append({"name": name, "camera": len(self.cameras) - 1,
                           "translation": [float(c) for c in eye],
                           "rotation": look_at_quaternion(eye, target)})
        self.camera_desc = (eye, target, yfov)

    def document(self, extras):
        used = set()
        for mat in self.materials:
            used.update(mat.get("extensions", {}).keys())
        doc = {
            "asset": {"version": "2.0", "generator": "relt scripts/make_scenes.py"},
            "extensionsUsed": sorted(used),
            "scene": 0,
            "scenes": [{"name": self.name, "nodes": list(range(len(self.nodes))), "extras": extras}],
            "nodes": self.nodes,
            "cameras": self.cameras,
            "meshes": self.meshes,
            "materials": self.materials,
            "accessors": self.accessors,
            "bufferViews": self.buffer_views,
            "buffers": [{"uri": self.name + ".bin", "byteLength": len(self.bin)}],
        }
        if not used:
            del doc["extensionsUsed"]
        return doc

    def write(self, out_dir, extras):
        doc = self.document(extras)
        text = json.dumps(doc, indent=1, allow_nan=False) + "\n"
        (out_dir / (self.name + ".gltf")).write_text(text, encoding="utf-8")
        (out_dir / (self.name + ".bin")).write_bytes(bytes(self.bin))


def settings(max_depth=8, bench=(512, 512), **more):
    e = {"width": 256, "height": 256, "max_depth": max_depth, "bench_width": bench[0], "bench_height": bench[1]}
    e.update(more)
    return e


# --------------------------------------------------------------------------------------------
# Shared pieces
# --------------------------------------------------------------------------------------------

WHITE = lambert("white_diffuse", (0.73, 0.73, 0.73))
RED = lambert("red_diffuse", (0.63, 0.065, 0.05))
GREEN = lambert("green_diffuse", (0.14, 0.45, 0.091))
GOLD_F0 = (1.0, 0.766, 0.336)
SILVER_F0 = (0.972, 0.960, 0.915)
LIGHT_GAP = 0.002  # how far ceiling lights hang below the ceiling


def cornell_room(g, half=1.0, height=2.0, left=RED, right=GREEN, z_back=None, z_front=None, closed=False):
    """Cornell-style room x in [-half, half], y in [0, height], z in [z_back, z_front] (default
    [-half, half]), open at +Z unless `closed`, all faces pointing into the room. The left wall
    (seen from a camera at +Z looking towards -Z) is at -X."""
    h = half
    zb = -h if z_back is None else z_back
    zf = h if z_front is None else z_front
    g.add_mesh("floor", rect_y(-h, h, zb, zf, 0.0, True), WHITE)
    g.add_mesh("ceiling", rect_y(-h, h, zb, zf, height, False), WHITE)
    g.add_mesh("back_wall", rect_z(zb, -h, h, 0.0, height, True), WHITE)
    g.add_mesh("left_wall", rect_x(-h, 0.0, height, zb, zf, True), left)
    g.add_mesh("right_wall", rect_x(h, 0.0, height, zb, zf, False), right)
    if closed:
        g.add_mesh("front_wall", rect_z(zf, -h, h, 0.0, height, False), WHITE)


def ceiling_light(g, name, mat, cx, cz, size_x, size_z, ceiling_y):
    y = ceiling_y - LIGHT_GAP
    g.add_mesh(name, rect_y(cx - size_x / 2, cx + size_x / 2, cz - size_z / 2, cz + size_z / 2, y, False), mat)


# --------------------------------------------------------------------------------------------
# The scenes
# --------------------------------------------------------------------------------------------

SCENES = {}


def scene(fn):
    SCENES[fn.__name__.replace("_", "-")] = fn
    return fn


@scene
def cornell_box():
    """The classic Cornell box (Cornell University data, as in Mitsuba/PBRT), scaled by 0.01."""
    g = GltfScene("cornell-box")
    S = 0.01

    def P(x, y, z):
        return (x * S, y * S, z * S)

    up, down = (0, 1, 0), (0, -1, 0)
    g.add_mesh("floor", quad([P(552.8, 0, 0), P(0, 0, 0), P(0, 0, 559.2), P(549.6, 0, 559.2)], up), WHITE)
    g.add_mesh("ceiling", quad([P(556, 548.8, 0), P(556, 548.8, 559.2), P(0, 548.8, 559.2), P(0, 548.8, 0)], down),
               WHITE)
    g.add_mesh("back_wall", quad([P(549.6, 0, 559.2), P(0, 0, 559.2), P(0, 548.8, 559.2), P(556, 548.8, 559.2)],
                                 (0, 0, -1)), WHITE)
    g.add_mesh("green_wall", quad([P(0, 0, 559.2), P(0, 0, 0), P(0, 548.8, 0), P(0, 548.8, 559.2)], (1, 0, 0)),
               GREEN)
    g.add_mesh("red_wall", quad([P(552.8, 0, 0), P(549.6, 0, 559.2), P(556, 548.8, 559.2), P(556, 548.8, 0)],
                                (-1, 0, 0)), RED)
    short = [(130.0, 65.0), (82.0, 225.0), (240.0, 272.0), (290.0, 114.0)]
    tall = [(423.0, 247.0), (265.0, 296.0), (314.0, 456.0), (472.0, 406.0)]
    g.add_mesh("short_block", prism([(x * S, z * S) for x, z in short], 0.0, 165.0 * S), WHITE)
    g.add_mesh("tall_block", prism([(x * S, z * S) for x, z in tall], 0.0, 330.0 * S), WHITE)
    light = emitter("ceiling_light", (17.0, 12.0, 4.0))
    y = 548.8 * S - 0.001  # 0.1 original units below the ceiling, as in Mitsuba's version
    g.add_mesh("ceiling_light", quad([(3.43, y, 2.27), (3.43, y, 3.32), (2.13, y, 3.32), (2.13, y, 2.27)], down),
               light)
    g.camera("camera", (2.78, 2.73, -8.0), (2.78, 2.73, 0.0), 2.0 * math.atan(0.0125 / 0.035))
    return g, settings(8, (512, 512))


FURNACE_LE, FURNACE_ALBEDO, FURNACE_DEPTH = 1.0, 0.5, 8


@scene
def furnace():
    """Closed emitting grey sphere seen from its centre: analytic answer."""
    g = GltfScene("furnace")
    mat = {"name": "grey_emitting_diffuse",
           "pbrMetallicRoughness": {"baseColorFactor": [FURNACE_ALBEDO] * 3 + [1.0], "metallicFactor": 0.0,
                                    "roughnessFactor": 1.0},
           "emissiveFactor": [1.0, 1.0, 1.0],
           "extensions": {EXT_STRENGTH: {"emissiveStrength": FURNACE_LE}}}
    sphere = icosphere((0.0, 0.0, 0.0), 1.0, 3, smooth=False).flip()  # front faces towards the centre
    g.add_mesh("furnace_sphere", sphere, mat, closed="inward")
    g.camera("camera", (0.0, 0.0, 0.0), (0.0, 0.0, -1.0), 1.2)
    a, le, d = FURNACE_ALBEDO, FURNACE_LE, FURNACE_DEPTH
    return g, settings(d, (512, 512), furnace_le=le, furnace_albedo=a,
                       furnace_expected=le * (1.0 - a ** d) / (1.0 - a),
                       furnace_expected_unbounded=le / (1.0 - a))


@scene
def glass_cube():
    """Kitaoka et al. 2009 Fig. 6: a yellow diffuse cube inside a smooth glass cube, small ceiling light."""
    g = GltfScene("glass-cube")
    cornell_room(g)
    lift = 0.001
    glass_half = 0.42
    gc = (0.05, lift + glass_half, -0.15)
    g.add_mesh("glass_cube", box(gc, (glass_half,) * 3, math.radians(25.0)), dielectric("glass", 1.5),
               closed="outward")
    yellow = lambert("yellow_diffuse", (0.75, 0.62, 0.06))
    g.add_mesh("yellow_cube", box(gc, (0.2,) * 3, math.radians(-20.0)), yellow, closed="outward")
    ceiling_light(g, "ceiling_light", emitter("small_light", (50.0, 50.0, 50.0)), 0.0, 0.05, 0.3, 0.3, 2.0)
    g.camera("camera", (0.0, 1.0, 3.5), (0.0, 0.95, 0.0), 2.0 * math.atan(0.0125 / 0.035))
    return g, settings(12, (512, 512))


def water_height(x, z):
    return (1.0 + 0.010 * math.sin(7.0 * x + 2.5 * z + 0.3) + 0.007 * math.sin(-3.0 * x + 9.0 * z + 1.1)
            + 0.004 * math.sin(13.0 * x - 11.0 * z + 2.0))


def water_grad(x, z):
    gx = 0.010 * 7.0 * math.cos(7.0 * x + 2.5 * z + 0.3) - 0.007 * 3.0 * math.cos(-3.0 * x + 9.0 * z + 1.1) \
        + 0.004 * 13.0 * math.cos(13.0 * x - 11.0 * z + 2.0)
    gz = 0.010 * 2.5 * math.cos(7.0 * x + 2.5 * z + 0.3) + 0.007 * 9.0 * math.cos(-3.0 * x + 9.0 * z + 1.1) \
        - 0.004 * 11.0 * math.cos(13.0 * x - 11.0 * z + 2.0)
    return gx, gz


@scene
def water_box():
    """Kitaoka et al. 2009 Fig. 7: Cornell box half filled with water, same small ceiling light."""
    g = GltfScene("water-box")
    cornell_room(g)
    # The water is in contact with the box: its sides, back and bottom lie 1 mm beyond the walls and the
    # floor (no coincident faces), so the walls and the floor cut through it. The front face, which the
    # camera looks through, stays 1 mm inside the open front. With a 1 mm air gap instead, the water's
    # bottom and sides reflected the camera's grazing rays totally, hiding the floor and the lower walls,
    # and only the bottom-back edge let them through (a row of bright dots).
    gap = 0.001
    water = water_body(-1.0 - gap, 1.0 + gap, -1.0 - gap, 1.0 - gap, -gap, water_height, water_grad, 48)
    g.add_mesh("water", water, dielectric("water", 1.33), closed="outward")
    ceiling_light(g, "ceiling_light", emitter("small_light", (50.0, 50.0, 50.0)), 0.0, 0.05, 0.3, 0.3, 2.0)
    g.camera("camera", (0.0, 1.5, 3.5), (0.0, 0.9, 0.0), 2.0 * math.atan(0.0125 / 0.035))
    return g, settings(16, (512, 512))


@scene
def ring():
    """Šik's thesis Fig. 5.2: faceted gold ring on a diffuse plane, mirror behind, small light."""
    g = GltfScene("ring")
    g.add_mesh("floor", rect_y(-4.0, 4.0, -4.0, 4.0, 0.0, True), lambert("floor_diffuse", (0.7, 0.7, 0.7)))
    g.add_mesh("mirror", rect_z(-1.0, -1.8, 1.8, 0.0, 1.5, True), conductor("mirror_silver", SILVER_F0, 0.0))
    g.add_mesh("ring", faceted_ring((0.0, 0.001, 0.0), 0.5, 0.46, 0.22, 64), conductor("gold", GOLD_F0, 0.0),
               closed="outward")
    # small square light, low on the left-front, facing the ring: its rays hit the inner wall of the ring at
    # a grazing angle and focus into the cardioid (nephroid) caustic on the floor inside the ring
    g.add_mesh("light", quad_towards((-2.4, 1.3, 1.0), (0.0, 0.1, 0.0), 0.075), emitter("small_light", (500.0,) * 3))
    g.camera("camera", (0.0, 1.9, 2.5), (0.0, 0.1, -0.2), 0.62)
    return g, settings(8, (512, 512))


@scene
def torus_in_glass():
    """Cline et al. 2005 Fig. 14: a diffuse torus inside a thick-walled glass case, small ceiling light:
    even the direct light on the torus arrives through glass (caustic paths)."""
    g = GltfScene("torus-in-glass")
    h = 1.5
    cornell_room(g, half=h, height=2.2, left=lambert("blue_diffuse", (0.12, 0.2, 0.5)),
                 right=lambert("orange_diffuse", (0.7, 0.35, 0.08)))
    lift = 0.001
    outer = (0.55, 0.38, 0.45)
    wall = 0.05
    cc = (0.0, lift + outer[1], -0.2)
    g.add_mesh("glass_case", hollow_box(cc, outer, wall), dielectric("glass", 1.5), closed="outward")
    cavity_floor = lift + wall
    tor = torus((0.0, cavity_floor + 0.09 + 0.001, -0.2), 0.28, 0.09, 64, 32)
    g.add_mesh("torus", tor, lambert("torus_diffuse", (0.8, 0.55, 0.2)), closed="outward")
    ceiling_light(g, "ceiling_light", emitter("small_light", (60.0, 60.0, 60.0)), 0.25, -0.1, 0.25, 0.25, 2.2)
    g.camera("camera", (0.0, 1.5, 3.0), (0.0, 0.4, -0.2), 0.6)
    return g, settings(12, (640, 480))


@scene
def glass_case():
    """torus-in-glass's room and empty case under a large light: pt and bdpt both converge fast, so
    their agreement through glass resting 1 mm above a floor is a short test."""
    g = GltfScene("glass-case")
    cornell_room(g, half=1.5, height=2.2)
    outer = (0.55, 0.38, 0.45)
    g.add_mesh("glass_case", hollow_box((0.0, 0.001 + outer[1], -0.2), outer, 0.05), dielectric("glass", 1.5),
               closed="outward")
    ceiling_light(g, "ceiling_light", emitter("large_light", (4.0, 4.0, 4.0)), 0.25, -0.1, 1.2, 1.2, 2.2)
    g.camera("camera", (0.0, 1.5, 3.0), (0.0, 0.4, -0.2), 0.6)
    return g, settings(12, (512, 512))


@scene
def door_ajar():
    """Two rooms joined by a doorway; the door is open by 8 degrees; the only light is in the far room."""
    g = GltfScene("door-ajar")
    W, H = 2.0, 2.5  # half width, height
    zf, za, zb, zback = 2.0, -2.0, -2.1, -4.1  # front wall, wall faces (room A side, room B side), back
    dx, dh = 0.45, 2.05  # doorway half width, height
    wall_a = lambert("wall_paint", (0.75, 0.74, 0.7))
    floor_m = lambert("wood_floor", (0.45, 0.3, 0.18))
    g.add_mesh("floor", rect_y(-W, W, zback, zf, 0.0, True), floor_m)
    g.add_mesh("ceiling", rect_y(-W, W, zback, zf, H, False), wall_a)
    g.add_mesh("left_wall", rect_x(-W, 0.0, H, zback, zf, True), wall_a)
    g.add_mesh("right_wall", rect_x(W, 0.0, H, zback, zf, False), wall_a)
    g.add_mesh("front_wall", rect_z(zf, -W, W, 0.0, H, False), wall_a)
    g.add_mesh("far_wall", rect_z(zback, -W, W, 0.0, H, True), wall_a)
    part = MeshData()  # the partition wall with its doorway, room A side, room B side and the jambs
    for z, facing in ((za, True), (zb, False)):
        part.append(rect_z(z, -W, -dx, 0.0, H, facing))
        part.append(rect_z(z, dx, W, 0.0, H, facing))
        part.append(rect_z(z, -dx, dx, dh, H, facing))
    part.append(rect_x(-dx, 0.0, dh, zb, za, True))
    part.append(rect_x(dx, 0.0, dh, zb, za, False))
    part.append(rect_y(-dx, dx, zb, za, dh, False))
    g.add_mesh("partition_wall", part, wall_a)
    # the door: hinged at x = -dx on the room A face, swung towards room A by 8 degrees
    angle = math.radians(8.0)
    clear, thick = 0.005, 0.04
    width = 2 * dx - 2 * clear
    hinge = (-dx + clear, 0.0, za)
    door = MeshData()
    corners = {}
    for i in range(8):
        lx = width if i & 1 else 0.0
        ly = (dh - clear) if i & 2 else clear
        lz = -thick if i & 4 else 0.0
        # local +x along the door, rotated so that the free edge moves towards +z (into room A)
        x = lx * math.cos(angle) - lz * math.sin(angle)
        z = lx * math.sin(angle) + lz * math.cos(angle)
        corners[i] = door.vert((hinge[0] + x, ly, hinge[2] + z))
    for a, b, c, d in [(0, 4, 6, 2), (1, 3, 7, 5), (2, 6, 7, 3), (0, 1, 5, 4), (0, 2, 3, 1), (4, 5, 7, 6)]:
        door.tri(a, b, c)
        door.tri(a, c, d)
    if door.signed_volume() < 0:
        door.flip()
    g.add_mesh("door", door, lambert("door_paint", (0.55, 0.12, 0.08)), closed="outward")
    g.add_mesh("cabinet", box((-1.55, 0.45, -0.6), (0.4, 0.45, 0.25), math.radians(90.0), open_bottom=True),
               lambert("cabinet_wood", (0.35, 0.22, 0.12)))
    g.add_mesh("table", box((0.9, 0.375, 0.3), (0.45, 0.375, 0.3), math.radians(15.0), open_bottom=True),
               lambert("table_white", (0.7, 0.7, 0.68)))
    # far room (room B): one ceiling light, and a light-coloured floor rug so the far room is bright
    g.add_mesh("far_room_light", rect_y(-0.6, 0.6, -2.9, -2.3, H - LIGHT_GAP, False),
               emitter("ceiling_panel", (300.0, 270.0, 225.0)))
    g.add_mesh("rug", rect_y(-1.5, 1.5, -3.9, -2.3, 0.002, True), lambert("rug", (0.8, 0.78, 0.7)))
    g.camera("camera", (-1.3, 1.55, 1.7), (0.25, 0.55, -1.8), 1.0)
    return g, settings(12, (640, 480))


@scene
def mirror_balls():
    """Šik's thesis Fig. 5.19: mirror and glass balls in a room with a small light."""
    g = GltfScene("mirror-balls")
    h = 1.5
    cornell_room(g, half=h, height=2.2, left=lambert("blue_diffuse", (0.12, 0.2, 0.5)),
                 right=lambert("orange_diffuse", (0.7, 0.35, 0.08)), z_front=3.5, closed=True)
    silver = conductor("silver_mirror", SILVER_F0, 0.0)
    gold = conductor("gold_mirror", GOLD_F0, 0.0)
    glass = dielectric("glass", 1.5)
    lift = 0.001
    balls = [("mirror_ball_large", silver, (-0.7, -0.5), 0.45, 4),
             ("glass_ball_large", glass, (0.55, 0.05), 0.38, 4),
             ("gold_ball", gold, (0.35, -0.9), 0.3, 4),
             ("glass_ball_small", glass, (-0.25, 0.6), 0.22, 3),
             ("mirror_ball_small", silver, (0.85, 0.7), 0.18, 3)]
    for name, mat, (x, z), r, level in balls:
        closed = "outward"
        g.add_mesh(name, icosphere((x, lift + r, z), r, level, smooth=True), mat, closed=closed)
    ceiling_light(g, "ceiling_light", emitter("small_light", (120.0, 110.0, 95.0)), 0.0, 0.0, 0.2, 0.2, 2.2)
    g.camera("camera", (0.0, 1.3, 3.3), (0.0, 0.4, -0.1), 0.85)
    return g, settings(10, (640, 480))


@scene
def glossy_caustics():
    """Šik's thesis ch. 5 (the glossy ring): glossy metals that throw and reflect caustics."""
    g = GltfScene("glossy-caustics")
    g.add_mesh("floor", rect_y(-4.0, 4.0, -4.0, 4.0, 0.0, True), lambert("floor_diffuse", (0.7, 0.7, 0.7)))
    g.add_mesh("back_wall", rect_z(-1.6, -4.0, 4.0, 0.0, 3.0, True), lambert("wall_diffuse", (0.6, 0.6, 0.58)))
    # a glossy gold ring (alpha 0.01) throwing its cardioid onto the floor, and a glossy silver torus
    # (alpha 0.0625) whose concave inner side focuses the light and whose outer side reflects the
    # ring's caustic
    g.add_mesh("ring", faceted_ring((-0.55, 0.001, 0.15), 0.45, 0.41, 0.2, 64),
               conductor("glossy_gold", GOLD_F0, 0.1), closed="outward")
    g.add_mesh("torus", torus((0.75, 0.121, -0.35), 0.42, 0.12, 64, 32),
               conductor("glossy_silver", SILVER_F0, 0.25), closed="outward")
    g.add_mesh("light", quad_towards((-2.3, 1.2, 1.1), (0.1, 0.1, -0.1), 0.075), emitter("small_light", (500.0,) * 3))
    g.camera("camera", (0.0, 1.9, 2.6), (0.1, 0.15, -0.3), 0.62)
    return g, settings(8, (512, 512))


@scene
def living_room():
    """A closed room lit only through one window, by a sky and a sun outside."""
    g = GltfScene("living-room")
    W, D0, D1, H = 2.5, -3.0, 2.0, 2.6  # half width, back and front z, height
    wz0, wz1, wy0, wy1 = -2.1, -0.7, 0.9, 2.1  # the window in the right wall (x = W)
    wall = lambert("wall_paint", (0.78, 0.76, 0.72))
    g.add_mesh("floor", rect_y(-W, W, D0, D1, 0.0, True), conductor("glossy_floor", (0.35, 0.25, 0.17), 0.3))
    g.add_mesh("ceiling", rect_y(-W, W, D0, D1, H, False), wall)
    g.add_mesh("back_wall", rect_z(D0, -W, W, 0.0, H, True), wall)
    g.add_mesh("front_wall", rect_z(D1, -W, W, 0.0, H, False), wall)
    g.add_mesh("left_wall", rect_x(-W, 0.0, H, D0, D1, True), lambert("blue_paint", (0.25, 0.35, 0.55)))
    right = MeshData()  # around the window
    right.append(rect_x(W, 0.0, wy0, D0, D1, False))
    right.append(rect_x(W, wy1, H, D0, D1, False))
    right.append(rect_x(W, wy0, wy1, D0, wz0, False))
    right.append(rect_x(W, wy0, wy1, wz1, D1, False))
    g.add_mesh("right_wall", right, wall)
    # outside: a sky facing the window, and a small bright sun high above it, so that a patch of sun
    # falls through the window onto the floor and the table
    g.add_mesh("sky", rect_x(W + 6.0, -2.0, 8.0, -10.0, 6.0, False), emitter("sky", (1.8, 2.2, 3.2)))
    window = (W, 0.5 * (wy0 + wy1), 0.5 * (wz0 + wz1))
    sun = add(window, mul(normalize(sub(window, (0.6, 0.75, -1.3))), 4.5))  # beyond the window from the table
    g.add_mesh("sun", quad_towards(sun, window, 0.12, up=(0.0, 0.0, 1.0)), emitter("sun", (4000.0, 3700.0, 3200.0)))
    # a table with a glass top, glass and metal objects on it, and a mirror ball on the floor
    g.add_mesh("table_base", box((0.6, 0.35, -1.3), (0.5, 0.35, 0.35), math.radians(10.0), open_bottom=True),
               lambert("table_wood", (0.45, 0.3, 0.18)))
    g.add_mesh("glass_top", box((0.6, 0.725, -1.3), (0.62, 0.025, 0.45), math.radians(10.0)),
               dielectric("glass", 1.5), closed="outward")
    g.add_mesh("glass_ball", icosphere((0.45, 0.751 + 0.14, -1.25), 0.14, 3, smooth=True), dielectric("glass", 1.5),
               closed="outward")
    g.add_mesh("metal_vase", icosphere((0.85, 0.751 + 0.1, -1.45), 0.1, 3, smooth=True),
               conductor("copper", (0.955, 0.638, 0.538), 0.15), closed="outward")
    g.add_mesh("mirror_ball", icosphere((-0.9, 0.001 + 0.3, -1.9), 0.3, 4, smooth=True),
               conductor("silver_mirror", SILVER_F0, 0.0), closed="outward")
    g.add_mesh("sofa", box((-1.7, 0.3, -0.2), (0.45, 0.3, 1.0)), lambert("sofa_fabric", (0.55, 0.2, 0.15)))
    g.camera("camera", (-1.6, 1.5, 1.7), (0.5, 0.6, -1.4), 0.95)
    return g, settings(12, (640, 480))


# --------------------------------------------------------------------------------------------
# README
# --------------------------------------------------------------------------------------------

DESCRIPTIONS = {
    "cornell-box": {
        "figure": "classic Cornell box",
        "source": "The Cornell box (Cornell University Program of Computer Graphics measured data), in the "
                  "version used by Mitsuba and PBRT: light radiance (17, 12, 4).",
        "what": "White, red and green Lambert walls, a short and a tall block (both rotated), a quad area light "
                "0.1 unit (original units) below the ceiling, facing down. The original coordinates (in mm) "
                "scaled by 0.01, so the room is 5.56 units wide. Camera in front of the open side "
                "(eye (2.78, 2.73, -8), looking +Z, vertical field of view 2 atan(12.5/35) = 39.3 degrees). "
                "As with the original camera, thin black slivers outside the box show at the left, right and "
                "bottom edges of the image (about 6 % of the pixels see nothing).",
        "why": "Diffuse interreflection only, no hard paths: the benchmark scene and the common ground on which "
               "every integrator (pt, bdpt, pssmlt, mmlt, erpt, relt) must agree within its error bars.",
        "materials": "white (0.73), red (0.63, 0.065, 0.05), green (0.14, 0.45, 0.091) Lambert; light: "
                     "emissiveFactor (1, 12/17, 4/17) x strength 17, black base colour.",
    },
    "furnace": {
        "figure": "furnace test (analytic)",
        "source": "The classic furnace test.",
        "what": "A closed sphere (icosphere, 1280 flat triangles, radius 1) with one material, Lambert "
                "albedo a = 0.5 and emitted radiance Le = 1, wound with its front faces towards the centre "
                "(emitters emit from their front face only). The camera sits at the centre.",
        "why": "An analytic answer for every pixel. With D = max_depth path segments, every pixel converges to "
               "Le (1 - a^D) / (1 - a) = 1.9921875 for D = 8, and to Le / (1 - a) = 2 for unbounded depth "
               "(a path of k segments carries Le a^(k-1), whatever the geometry, because the enclosure is closed "
               "and uniform). Tests check every integrator within 1 % of this value. "
               "Extras: furnace_le = 1.0, furnace_albedo = 0.5, furnace_expected = 1.9921875 (for max_depth 8), "
               "furnace_expected_unbounded = 2.0.",
        "materials": "grey_emitting_diffuse: baseColor 0.5, emissiveFactor (1, 1, 1) x strength 1.",
    },
    "glass-cube": {
        "figure": "Kitaoka et al. 2009, Fig. 6",
        "source": "Kitaoka, Kitamura, Kishino 2009 (seeds/000), Fig. 6: \"A yellow cube is in a glass cube, and a "
                  "small light source is on the ceiling.\"",
        "what": "A 2 x 2 x 2 Cornell-style room (white floor, ceiling and back wall, red left wall, green right "
                "wall, open front). On the floor, a smooth solid glass cube (side 0.84, ior 1.5, rotated 25 "
                "degrees) with a yellow diffuse cube (side 0.4, rotated -20 degrees) embedded in its centre. "
                "A small 0.3 x 0.3 ceiling light (radiance 50).",
        "why": "Caustics seen through glass: the yellow cube is lit only through the glass (its direct light is "
               "a caustic path L-S-D) and is seen only through the glass (E-S-D-S-L paths). Path tracing and "
               "BDPT cannot sample specular-diffuse-specular chains with a small light; this is the scene where "
               "Kitaoka's specific replica (class L0) matters.",
        "materials": "Lambert walls as in cornell-box; glass: transmission 1, ior 1.5, roughness 0; yellow "
                     "(0.75, 0.62, 0.06).",
    },
    "water-box": {
        "figure": "Kitaoka et al. 2009, Fig. 7",
        "source": "Kitaoka et al. 2009 (seeds/000), Fig. 7: water-filled Cornell box, same small ceiling light "
                  "as Fig. 6.",
        "what": "The glass-cube room filled to height 1 (half) with water: one closed dielectric (ior 1.33) "
                "whose top is a gently wavy smooth surface (three sine waves, amplitude about 2 cm, 48 x 48 grid "
                "with analytic normals) and whose sides and bottom are flat. The water touches the box: its "
                "sides, back and bottom lie 1 mm beyond the walls and the floor (|x| = 1.001, the back at "
                "z = -1.001, the bottom at y = -0.001), so the walls and the floor cut through it without coincident faces; "
                "its flat front face (z = 0.999), which the camera looks through, stays inside the open front "
                "(two 1 mm slivers of it beyond the side walls are dark and a fraction of a pixel wide). "
                "With a 1 mm air gap under and around the water instead, total internal reflection at its "
                "bottom and sides hid the floor and the lower walls from the camera. Small 0.3 x 0.3 ceiling "
                "light (radiance 50).",
        "why": "The lit floor and the lower walls are seen only through the water (its wavy top or its flat "
               "front face), and they are lit only through its top: every visible path below the water is a "
               "caustic (L-S-D-S-E). The water surface's radiance comes from the caustics on the floor; BPT "
               "renders it dark. Deep paths: max_depth 16.",
        "materials": "Lambert walls as in cornell-box; water: transmission 1, ior 1.33, roughness 0.",
    },
    "ring": {
        "figure": "Šik thesis, Fig. 5.2",
        "source": "Šik's thesis (seeds/004), Fig. 5.2 (the Ring scene; Table 5.4), used to measure tempering.",
        "what": "A gold ring (outer radius 0.5, inner 0.46, height 0.22) with 64 flat facets (no normals, so "
                "the facets are flat, as in the thesis) lying flat on a diffuse plane, a silver mirror "
                "behind it, and one small 0.15 x 0.15 square light low at the front left (elevation about 25 "
                "degrees) facing the ring. No walls: the background is black.",
        "why": "Reflected caustics: the inner wall focuses the light into a cardioid (nephroid) on the plane "
               "inside the ring, and the facets break it into many small, sharp caustics, also seen in the "
               "mirror (E-S-D-S-L paths). High, narrow peaks of the target function: the test scene for "
               "tempering and global exploration.",
        "materials": "floor Lambert 0.7; ring: conductor F0 (1.0, 0.766, 0.336), roughness 0 (perfect mirror); "
                     "mirror: conductor F0 (0.972, 0.960, 0.915), roughness 0; light radiance 500.",
    },
    "torus-in-glass": {
        "figure": "Cline et al. 2005, Fig. 14",
        "source": "Cline, Talbot, Egbert 2005 (seeds/003), Fig. 14 (\"difficult caustic lighting\").",
        "what": "A 3 x 2.2 x 3 room (white, blue left wall, orange right wall, open front). On the floor a "
                "thick-walled glass case (outer 1.1 x 0.76 x 0.9, walls 5 cm thick, ior 1.5: one closed "
                "dielectric made of an outer shell and an inner cavity shell) with a smooth orange diffuse torus "
                "lying in its air-filled cavity. A small 0.25 x 0.25 ceiling light (radiance 60), off centre.",
        "why": "As in the paper, even the direct light on the torus arrives through glass: every path that "
               "lights the torus is an implicit caustic path, seen through the glass again (two refractions "
               "on each side). Next-event estimation gets nothing on the torus.",
        "materials": "walls Lambert; glass: transmission 1, ior 1.5, roughness 0; torus (0.8, 0.55, 0.2).",
    },
    "glass-case": {
        "figure": "test scene (glass on a floor)",
        "source": "torus-in-glass without its torus, under a large light.",
        "what": "torus-in-glass's room (white walls) and its empty thick-walled glass case (outer 1.1 x 0.76 x "
                "0.9, walls 5 cm, ior 1.5), resting 1 mm above the floor, under a 1.2 x 1.2 ceiling light of "
                "radiance 4.",
        "why": "Light through glass onto the floor a millimetre below it and back out: pt and bdpt both render it "
               "in seconds, and must agree there (tests/stat/integrators_test.cpp). A subpath that took its "
               "directions between stored vertex positions, instead of along its traced rays, was 1.4 % dark "
               "here, because the ray origins' offset tilts them beside a 1 mm gap.",
        "materials": "walls Lambert (0.73); glass: transmission 1, ior 1.5, roughness 0; light radiance 4.",
    },
    "door-ajar": {
        "figure": "Veach-style door ajar",
        "source": "Veach's \"door ajar\" scene idea (complex visibility); listed in DESIGN.md section 5.",
        "what": "Two rooms (4 x 2.5 x 4 and 4 x 2.5 x 2) separated by a 10 cm partition wall with a 0.9 x 2.05 "
                "doorway. The door (hinged on the left, 4 cm thick) is open by 8 degrees towards the camera's room: "
                "its free edge stands 12 cm out of the wall, leaving a slit about 8 cm wide along the jamb. "
                "The only light is a 1.2 x 0.6 ceiling panel in the far room near the partition (radiance "
                "(300, 270, 225)); the camera's room receives light only through the slit. "
                "A cabinet and a table add occlusion.",
        "why": "Complex visibility: almost every light subpath and almost every camera subpath dies on the wrong "
               "side of the wall; the important paths all pass through a thin slit. This is the scene where "
               "Metropolis sampling shines and independent sampling (pt, bdpt) is very noisy.",
        "materials": "walls (0.75, 0.74, 0.7), floor (0.45, 0.3, 0.18), door (0.55, 0.12, 0.08), "
                     "cabinet (0.35, 0.22, 0.12), table (0.7, 0.7, 0.68), rug (0.8, 0.78, 0.7), all Lambert.",
    },
    "glossy-caustics": {
        "figure": "Šik thesis, ch. 5 (glossy ring)",
        "source": "Šik's thesis (seeds/004), chapter 5: the tempered family was made for glossy metals, "
                  "whose caustics a path tracer and BDPT find as rarely as a mirror's (the ring and dragon "
                  "scenes); this is the ring of `ring` made glossy, with a glossy torus beside it.",
        "what": "A diffuse floor and back wall, a faceted gold ring with roughness 0.1 (GGX alpha 0.01) and a "
                "smooth-shaded silver torus with roughness 0.25 (alpha 0.0625), lit by one small bright quad "
                "low at the left-front (radiance 500): the ring throws its cardioid onto the floor inside it, "
                "the torus's inner side focuses a caustic and its outer side reflects the ring's.",
        "why": "Glossy-diffuse-glossy light: caustics of near-specular metals, seen directly and in a "
               "glossy reflection, where connections fail for the same reason as at mirrors.",
        "materials": "Lambert floor (0.7) and wall (0.6, 0.6, 0.58); gold (F0 (1, 0.766, 0.336)) and silver "
                     "(F0 (0.972, 0.96, 0.915)) conductors, GGX; emitter (500, 500, 500).",
    },
    "living-room": {
        "figure": "window-lit interior (thesis ch. 6)",
        "source": "The window-lit interiors of the thesis's chapter 6 (seeds/004), where VCM and its "
                  "Metropolised version are compared: light comes in through one opening only.",
        "what": "A closed 5 x 2.6 x 5 room with one 1.4 x 1.2 window in its right wall. Outside, a large "
                "sky quad facing the window (radiance (1.8, 2.2, 3.2)) and, between them, a small sun quad "
                "(radiance about 4000) in line with the window and the table, so that its light falls "
                "through the window onto the table's glass. "
                "Inside: a glossy floor (roughness 0.3, alpha 0.09), a wooden table with a glass top, a "
                "glass ball and a copper ball (roughness 0.15) on it, a mirror ball on the floor, a sofa.",
        "why": "Most of the room is lit by light that bounced once inside (the window's light is "
               "complex visibility), with caustics from the glass seen directly and in the glossy floor: "
               "the case where merging and Markov chains are both needed.",
        "materials": "Lambert walls (0.78, 0.76, 0.72), left wall (0.25, 0.35, 0.55), table (0.45, 0.3, "
                     "0.18), sofa (0.55, 0.2, 0.15); glossy floor conductor F0 (0.35, 0.25, 0.17) roughness "
                     "0.3; glass ior 1.5; copper F0 (0.955, 0.638, 0.538) roughness 0.15; silver mirror.",
    },
    "mirror-balls": {
        "figure": "Šik thesis, Fig. 5.19",
        "source": "Šik's thesis (seeds/004), Fig. 5.19 (the Mirror-balls scene, 640 x 480 in Table 5.4).",
        "what": "A closed 3 x 2.2 x 5 room (white, blue left wall, orange right wall; the camera is inside, "
                "so the balls reflect walls all round) with five smooth "
                "balls (icospheres with exact sphere normals) standing on the floor: two silver mirror balls, "
                "one gold mirror ball, two glass balls (ior 1.5). A small 0.2 x 0.2 ceiling light "
                "(radiance (120, 110, 95)).",
        "why": "Many specular paths at once: caustics from the glass balls on the floor, reflected caustics "
               "from the mirror balls, the caustics seen in the mirror balls and through the glass balls "
               "(E-S-D-S-L); a small light makes them sharp. Global exploration between many separate peaks.",
        "materials": "walls Lambert; mirrors: conductor F0 silver (0.972, 0.960, 0.915) or gold "
                     "(1.0, 0.766, 0.336), roughness 0; glass: transmission 1, ior 1.5, roughness 0.",
    },
}


def readme(built):
    lines = []
    w = lines.append
    w("# relt scene suite")
    w("")
    w("Generated by `scripts/make_scenes.py` (Python standard library only, deterministic output).")
    w("Regenerate with")
    w("")
    w("    python3 scripts/make_scenes.py            # writes scenes/*.gltf, scenes/*.bin, this README, then checks them")
    w("    python3 scripts/make_scenes.py --check    # checks the committed files only")
    w("")
    w("Do not edit the files here by hand: change the generator and regenerate.")
    w("")
    w("| scene | triangles | lights | max_depth | test size | bench size | follows |")
    w("|---|---|---|---|---|---|---|")
    for name, (g, extras) in built.items():
        lights = [n for (n, m, t) in g.mesh_info if "emissiveFactor" in g.materials[g.material_ids[m]]]
        w("| `%s` | %d | %s | %d | %dx%d | %dx%d | %s |" % (
            name, g.triangles, ", ".join(lights), extras["max_depth"], extras["width"], extras["height"],
            extras["bench_width"], extras["bench_height"], DESCRIPTIONS[name]["figure"]))
    w("")
    w("## Conventions (how glTF maps to relt)")
    w("")
    w("- glTF 2.0, `asset.version` \"2.0\", one `.gltf` with an external `.bin` buffer (relative uri). One scene.")
    w("- Scene-level `extras`: `width`, `height` (test resolution, 256 x 256 everywhere), `max_depth` "
      "(maximum number of path segments), `bench_width`, `bench_height` (benchmark resolution). The command "
      "line overrides them.")
    w("- Units: metres-ish, Y up. All geometry is stored in world coordinates (mesh nodes have no transform).")
    w("- Camera: a node named `camera` with a perspective camera (`yfov` in radians, `aspectRatio` 1 = "
      "width/height of the test size, `znear` 0.01). As glTF specifies, it looks down its local -Z with +Y up; "
      "the node's translation is the eye and its rotation turns -Z towards the target.")
    w("- Triangles only (mode 4), indexed (UNSIGNED_SHORT, or UNSIGNED_INT above 65 534 vertices), POSITION "
      "with min/max; NORMAL only where smooth shading is wanted (spheres, torus, water surface). Without "
      "NORMAL the geometric normal is used, so faceted meshes (ring, blocks, furnace) render flat.")
    w("- Winding is counter-clockwise seen from the front: the front face is the side "
      "`cross(v1 - v0, v2 - v0)` points to. Walls face into their room; closed solids face outwards "
      "(mesh `extras.closed` = \"outward\"); the furnace sphere faces inwards (`extras.closed` = \"inward\").")
    w("- Materials (pbrMetallicRoughness):")
    w("  - Lambert: `metallicFactor` 0, `baseColorFactor` = albedo, `roughnessFactor` 1.")
    w("  - Conductor: `metallicFactor` 1, `baseColorFactor` = F0 (Schlick), `roughnessFactor` r, "
      "alpha = r^2, r = 0 is a perfect mirror. Optional material `extras.microfacet` = \"beckmann\" "
      "(default GGX). The conductors are perfect mirrors except the glossy metals of glossy-caustics and "
      "living-room.")
    w("  - Dielectric: `KHR_materials_transmission` (`transmissionFactor` 1) + `KHR_materials_ior` "
      "(1.5 glass, 1.33 water), `metallicFactor` 0, `roughnessFactor` 0 (smooth), white base colour. "
      "The side the geometric normal points to is the OUTSIDE (index 1), so every glass or water mesh "
      "is closed and wound outwards; the generator checks this (every edge shared by exactly two triangles "
      "with opposite orientations once vertices are welded by position, and positive signed volume). "
      "A diffuse object inside glass (glass-cube) is simply embedded in the solid; a cavity "
      "(torus-in-glass) is an inner shell facing into the cavity.")
    w("  - Emitters: emitted radiance = `emissiveFactor` (each component <= 1) x "
      "`KHR_materials_emissive_strength.emissiveStrength`. An emitter emits from its front face only "
      "(no `doubleSided` in this suite). Lights have a black base colour, except the furnace sphere. "
      "Ceiling lights hang 2 mm (cornell-box: 1 mm) below the ceiling and face down.")
    w("- `extensionsUsed` lists every extension used; `extensionsRequired` is never set. "
      "No punctual lights: all lights are emissive quads.")
    w("- Objects that stand on a floor are lifted by 1 mm where coplanar faces would otherwise touch it "
      "(dielectrics, the ring), except water-box's water, which reaches 1 mm into the floor and the walls; "
      "opaque blocks are open at the bottom, like the classic Cornell blocks.")
    w("")
    w("## The scenes")
    for name, (g, extras) in built.items():
        d = DESCRIPTIONS[name]
        eye, target, yfov = g.camera_desc
        w("")
        w("### %s" % name)
        w("")
        w("Follows: %s" % d["source"])
        w("")
        w("What it shows: %s" % d["what"])
        w("")
        w("Why it is in the suite: %s" % d["why"])
        w("")
        w("Materials: %s" % d["materials"])
        w("")
        w("Camera: eye (%s), target (%s), yfov %.4f rad (%.1f degrees)." % (
            ", ".join("%g" % c for c in eye), ", ".join("%g" % c for c in target), yfov, math.degrees(yfov)))
        w("")
        w("Extras: `%s`" % json.dumps(extras))
        w("")
        w("Meshes (%d triangles):" % g.triangles)
        w("")
        for node, mat, tris in g.mesh_info:
            w("- `%s` (%s): %d triangles" % (node, mat, tris))
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------------------------
# Checks
# --------------------------------------------------------------------------------------------


class CheckError(Exception):
    pass


def read_accessor(doc, blob, index):
    acc = doc["accessors"][index]
    view = doc["bufferViews"][acc["bufferView"]]
    ncomp = {"SCALAR": 1, "VEC3": 3}[acc["type"]]
    fmt, size = {5126: ("f", 4), 5123: ("H", 2), 5125: ("I", 4)}[acc["componentType"]]
    off = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    count = acc["count"]
    if off % size or "byteStride" in view:
        raise CheckError("accessor %d: unaligned or strided" % index)
    if off + count * ncomp * size > view.get("byteOffset", 0) + view["byteLength"]:
        raise CheckError("accessor %d overruns its buffer view" % index)
    vals = struct.unpack_from("<%d%s" % (count * ncomp, fmt), blob, off)
    if ncomp == 1:
        return acc, list(vals)
    return acc, [tuple(vals[i:i + 3]) for i in range(0, len(vals), 3)]


def check_closed(name, pos, tris, want):
    """Watertight (welded by exact position), consistently oriented, volume sign as wanted."""
    weld = {}
    ids = [weld.setdefault(p, len(weld)) for p in pos]
    edges = {}
    for a, b, c in tris:
        for u, v in ((ids[a], ids[b]), (ids[b], ids[c]), (ids[c], ids[a])):
            if u == v:
                raise CheckError("%s: degenerate edge" % name)
            edges[(u, v)] = edges.get((u, v), 0) + 1
    for (u, v), k in edges.items():
        if k != 1:
            raise CheckError("%s: directed edge used %d times (inconsistent orientation or non-manifold)" % (name, k))
        if edges.get((v, u), 0) != 1:
            raise CheckError("%s: open edge (not watertight)" % name)
    vol = 0.0
    for a, b, c in tris:
        vol += dot(pos[a], cross(pos[b], pos[c])) / 6.0
    if (vol <= 0.0) if want == "outward" else (vol >= 0.0):
        raise CheckError("%s: signed volume %g but the mesh should face %s" % (name, vol, want))
    return vol


def check_scene(path):
    """Validate one .gltf (+ .bin). Returns a one-line summary; raises CheckError."""
    text = path.read_text(encoding="utf-8")
    doc = json.loads(text, parse_constant=lambda c: (_ for _ in ()).throw(CheckError("non-finite number " + c)))
    if doc["asset"]["version"] != "2.0":
        raise CheckError("asset.version")
    if "extensionsRequired" in doc:
        raise CheckError("extensionsRequired must not be set")
    buf = doc["buffers"]
    if len(buf) != 1:
        raise CheckError("one buffer expected")
    blob = (path.parent / buf[0]["uri"]).read_bytes()
    if len(blob) != buf[0]["byteLength"]:
        raise CheckError("buffer byteLength %d != file size %d" % (buf[0]["byteLength"], len(blob)))
    for i, v in enumerate(doc["bufferViews"]):
        if v["byteOffset"] + v["byteLength"] > len(blob):
            raise CheckError("bufferView %d overruns the buffer" % i)
    sc = doc["scenes"][doc["scene"]]
    ex = sc["extras"]
    for k in ("width", "height", "max_depth", "bench_width", "bench_height"):
        if not isinstance(ex.get(k), int) or ex[k] <= 0:
            raise CheckError("scene extras %s" % k)
    used = set()
    for m in doc["materials"]:
        used.update(m.get("extensions", {}).keys())
        if not m.get("name"):
            raise CheckError("unnamed material")
        for c in m.get("emissiveFactor", []):
            if not 0.0 <= c <= 1.0:
                raise CheckError("%s: emissiveFactor component out of [0, 1]" % m["name"])
        if "emissiveFactor" in m and EXT_STRENGTH not in m.get("extensions", {}):
            raise CheckError("%s: emitter without emissive strength" % m["name"])
    if used != set(doc.get("extensionsUsed", [])):
        raise CheckError("extensionsUsed %s != used %s" % (doc.get("extensionsUsed"), sorted(used)))
    cams = 0
    tri_total = 0
    emissive_area = 0.0
    names = set()
    for ni in sc["nodes"]:
        node = doc["nodes"][ni]
        if not node.get("name") or node["name"] in names:
            raise CheckError("node %d: missing or duplicate name" % ni)
        names.add(node["name"])
        if "camera" in node:
            cams += 1
            cam = doc["cameras"][node["camera"]]["perspective"]
            if abs(cam["aspectRatio"] - ex["width"] / ex["height"]) > 1e-9 or not 0 < cam["yfov"] < math.pi:
                raise CheckError("camera parameters")
            q = node["rotation"]
            if abs(sum(c * c for c in q) - 1.0) > 1e-9:
                raise CheckError("camera rotation is not a unit quaternion")
            continue
        if any(k in node for k in ("matrix", "rotation", "scale", "translation", "children")):
            raise CheckError("%s: mesh nodes carry no transform here" % node["name"])
        mesh = doc["meshes"][node["mesh"]]
        if not mesh.get("name"):
            raise CheckError("unnamed mesh")
        for prim in mesh["primitives"]:
            label = "%s: %s" % (path.name, mesh["name"])
            if prim.get("mode", 4) != 4:
                raise CheckError(label + ": not triangles")
            acc, pos = read_accessor(doc, blob, prim["attributes"]["POSITION"])
            if acc["componentType"] != 5126 or acc["type"] != "VEC3":
                raise CheckError(label + ": POSITION type")
            for p in pos:
                if not all(math.isfinite(c) for c in p):
                    raise CheckError(label + ": non-finite position")
            mn = [min(p[k] for p in pos) for k in range(3)]
            mx = [max(p[k] for p in pos) for k in range(3)]
            if mn != acc["min"] or mx != acc["max"]:
                raise CheckError(label + ": POSITION min/max %s %s != %s %s" % (acc["min"], acc["max"], mn, mx))
            normals = None
            if "NORMAL" in prim["attributes"]:
                nacc, normals = read_accessor(doc, blob, prim["attributes"]["NORMAL"])
                if nacc["count"] != len(pos):
                    raise CheckError(label + ": NORMAL count")
                for n in normals:
                    if not all(math.isfinite(c) for c in n) or abs(length(n) - 1.0) > 1e-5:
                        raise CheckError(label + ": NORMAL not unit length")
            iacc, idx = read_accessor(doc, blob, prim["indices"])
            if iacc["count"] % 3 or not idx or max(idx) >= len(pos):
                raise CheckError(label + ": bad indices")
            tris = [tuple(idx[i:i + 3]) for i in range(0, len(idx), 3)]
            mat = doc["materials"][prim["material"]]
            area = 0.0
            for a, b, c in tris:
                g = cross(sub(pos[b], pos[a]), sub(pos[c], pos[a]))
                ga = 0.5 * length(g)
                if ga < 1e-9:
                    raise CheckError(label + ": degenerate triangle")
                area += ga
                if normals is not None:
                    # shading normals must agree with the winding (front side)
                    nm = add(add(normals[a], normals[b]), normals[c])
                    if dot(nm, g) <= 0.0:
                        raise CheckError(label + ": winding disagrees with the normals")
            if "emissiveFactor" in mat:
                emissive_area += area
            dielectric_mat = EXT_TRANSMISSION in mat.get("extensions", {})
            closed = mesh.get("extras", {}).get("closed")
            if dielectric_mat and closed != "outward":
                raise CheckError(label + ": dielectric mesh not declared closed outward")
            if closed:
                check_closed(label, pos, tris, closed)
            tri_total += len(tris)
    if cams != 1:
        raise CheckError("exactly one camera node expected")
    if emissive_area <= 0.0:
        raise CheckError("no emitter")
    return "%-16s %6d triangles  emitter area %.4f  max_depth %d" % (path.stem, tri_total, emissive_area,
                                                                    ex["max_depth"])


# --------------------------------------------------------------------------------------------


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=str(Path(__file__).resolve().parent.parent / "scenes"),
                    help="output folder (default: <repository>/scenes)")
    ap.add_argument("--check", action="store_true", help="only check the scenes already in --out")
    ap.add_argument("--only", nargs="*", help="generate only these scenes (the README is not rewritten)")
    args = ap.parse_args(argv)
    out = Path(args.out)
    names = list(SCENES)
    if args.only:
        unknown = [n for n in args.only if n not in SCENES]
        if unknown:
            ap.error("unknown scene(s): %s" % ", ".join(unknown))
        names = args.only
    if not args.check:
        out.mkdir(parents=True, exist_ok=True)
        built = {}
        for name in names:
            g, extras = SCENES[name]()
            assert g.name == name
            g.write(out, extras)
            built[name] = (g, extras)
        if not args.only:
            (out / "README.md").write_text(readme(built), encoding="utf-8")
    failed = False
    for name in names:
        path = out / (name + ".gltf")
        try:
            summary = check_scene(path)
            digest = hashlib.sha256(path.read_bytes() + (out / (name + ".bin")).read_bytes()).hexdigest()[:12]
            print("ok    %s  sha256 %s" % (summary, digest))
        except (CheckError, OSError, KeyError, ValueError, IndexError, struct.error) as e:
            failed = True
            print("FAIL  %s: %s" % (name, e), file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
