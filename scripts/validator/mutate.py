#!/usr/bin/python3
"""Deterministic mutations of the fuzz corpus, for comparing relt's loader with the glTF validator.

mutate.py OUT_DIR [COUNT] [SEED] writes COUNT (default 10000) files into OUT_DIR, the same files
for the same seed (default 20240601) and corpus. The corpus is what scripts/fuzz.sh seeds with:
every .gltf and .glb under tests/data/gltf, scenes and tests/data/fuzz. Each output is one source
file with one to three mutations:
- JSON (.gltf, and the JSON chunk of a .glb): a value replaced (numbers nudged, set to edge values
  or made fractional, another type, another enum string), a key or an array entry deleted or
  duplicated, a key moved into another object;
- binary data: bytes of a data: URI buffer or of a GLB's BIN chunk overwritten (NaN, huge or
  out-of-range values), so that accessor data goes wrong too;
- raw bytes (files that are not JSON, and some GLB headers): bytes flipped, truncated or appended.
Each source folder gets its own folder in OUT_DIR with links to its other files (.bin, images), so
that relative URIs resolve. Prints the paths written, one a line.
"""
import base64
import copy
import json
import os
import random
import struct
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
CORPUS = ["tests/data/gltf", "scenes", "tests/data/fuzz"]
EDGE_NUMBERS = [0, -1, 1, 2, 3, 4, 5, 0.5, -0.5, 1.5, 255, 256, 65535, 65536, 2**31, 2**32, 2**53, 2**53 + 1,
                1e30, -1e30, 1e308, 5120, 5121, 5123, 5125, 5126, 34962, 34963]
ENUM_STRINGS = ["SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4", "perspective", "orthographic", "point",
                "spot", "directional", "POSITION", "NORMAL", "TEXCOORD_0", "2.0", "1.0", "2.1", "3.0", "", "x.y",
                "KHR_materials_ior", "KHR_lights_punctual", "KHR_draco_mesh_compression", "Cube.bin",
                "data:application/octet-stream;base64,AAAA", "data:application/gltf-buffer;base64,", "missing.bin"]
BAD_FLOATS = [struct.pack("<f", v) for v in (float("nan"), float("inf"), -float("inf"), 1e38, -1e38, 0.0)]
BAD_U32 = [struct.pack("<I", v) for v in (0, 1, 0xFFFFFFFF, 0x7FFFFFFF, 0x10000, 3, 12, 0x46546C67, 0x4E4F534A)]


def corpus_files():
    out = []
    for top in CORPUS:
        for folder, _, names in sorted(os.walk(os.path.join(ROOT, top))):
            for name in sorted(names):
                if name.endswith((".gltf", ".glb")):
                    out.append(os.path.join(folder, name))
    return sorted(out)


def json_paths(value, path=()):
    """Every (path, value) in the document, the root included."""
    yield path, value
    if isinstance(value, dict):
        for k in value:
            yield from json_paths(value[k], path + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from json_paths(v, path + (i,))


def get_at(doc, path):
    for p in path:
        doc = doc[p]
    return doc


def new_value(rng, old):
    if isinstance(old, bool) or rng.random() < 0.15:
        return rng.choice([None, True, False, "x", [], {}, 0, [0, 0, 0], {"a": 1}])
    if isinstance(old, (int, float)):
        choice = rng.random()
        if choice < 0.4:
            return old + rng.choice([-1, 1, -2, 2, 4, -4])
        if choice < 0.55:
            return old * rng.choice([2, 10, -1, 0.5])
        if choice < 0.65:
            return old + 0.5
        return rng.choice(EDGE_NUMBERS)
    if isinstance(old, str):
        if old.startswith("data:") and rng.random() < 0.5:
            cut = rng.randrange(len(old) + 1)
            return old[:cut] + rng.choice(["", "=", "!", "%", "A"]) + old[cut + 1:]
        return rng.choice(ENUM_STRINGS + [old[: len(old) // 2], old + old])
    if isinstance(old, list):
        return rng.choice([[], old[:1], old + old[:1], [None], list(reversed(old))])
    return rng.choice([{}, "x", [old]])


def mutate_json(rng, doc):
    """One structural or value mutation of `doc` in place; returns the new root."""
    paths = list(json_paths(doc))
    path, value = rng.choice(paths)
    op = rng.random()
    if not path:
        if isinstance(doc, dict) and doc and op < 0.5:
            del doc[rng.choice(list(doc))]  # drop a top-level array or object
            return doc
        return new_value(rng, doc) if op < 0.6 else doc
    parent = get_at(doc, path[:-1])
    key = path[-1]
    if op < 0.55:
        parent[key] = new_value(rng, value)
    elif op < 0.75:
        del parent[key]
    elif op < 0.85 and isinstance(parent, list):
        parent.insert(key, copy.deepcopy(value))
    else:
        # Move the key/value into another object: misplaced or unexpected properties.
        objects = [p for p, v in paths if isinstance(v, dict)]
        if not objects:
            parent[key] = new_value(rng, value)
            return doc
        target = get_at(doc, rng.choice(objects))
        target[key if isinstance(key, str) else "k%d" % key] = copy.deepcopy(value)
    return doc


def mutate_bytes(rng, data, fraction=1.0):
    data = bytearray(data)
    op = rng.random()
    if not data or op < 0.1:
        return bytes(data + bytes(rng.randrange(256) for _ in range(rng.randint(1, 16))))
    if op < 0.2:
        return bytes(data[: rng.randrange(len(data))])
    for _ in range(rng.randint(1, 4)):
        at = rng.randrange(max(1, int(len(data) * fraction)))
        kind = rng.random()
        patch = (bytes([rng.randrange(256)]) if kind < 0.4 else
                 rng.choice(BAD_FLOATS) if kind < 0.7 else rng.choice(BAD_U32))
        data[at:at + len(patch)] = patch
    return bytes(data)


def mutate_data_uri(rng, doc):
    """Overwrite bytes inside a base64 data: URI buffer; False when the document has none."""
    uris = [b for b in doc.get("buffers", []) if isinstance(b, dict) and str(b.get("uri", "")).startswith("data:")
            and "," in b["uri"]] if isinstance(doc, dict) and isinstance(doc.get("buffers"), list) else []
    if not uris:
        return False
    buffer = rng.choice(uris)
    head, _, body = buffer["uri"].partition(",")
    try:
        data = base64.b64decode(body, validate=True)
    except ValueError:
        return False
    buffer["uri"] = head + "," + base64.b64encode(mutate_bytes(rng, data)).decode()
    return True


def split_glb(data):
    """(json_doc, bin_bytes) of a well-formed two-chunk GLB, else None."""
    if len(data) < 20 or data[:4] != b"glTF":
        return None
    length, kind = struct.unpack_from("<II", data, 12)
    if kind != 0x4E4F534A or 20 + length > len(data):
        return None
    try:
        doc = json.loads(data[20:20 + length].decode("utf-8"))
    except ValueError:
        return None
    rest = data[20 + length:]
    bin_chunk = rest[8:8 + struct.unpack_from("<I", rest, 0)[0]] if len(rest) >= 8 else None
    return doc, bin_chunk


def join_glb(doc, bin_chunk):
    text = json.dumps(doc, allow_nan=False).encode()
    text += b" " * (-len(text) % 4)
    out = struct.pack("<II", len(text), 0x4E4F534A) + text
    if bin_chunk is not None:
        padded = bin_chunk + b"\0" * (-len(bin_chunk) % 4)
        out += struct.pack("<II", len(padded), 0x004E4942) + padded
    return struct.pack("<4sII", b"glTF", 2, 12 + len(out)) + out


def mutate_doc(rng, doc, bin_chunk=None):
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        if bin_chunk is not None and rng.random() < 0.25:
            bin_chunk = mutate_bytes(rng, bin_chunk)
        elif rng.random() < 0.2 and mutate_data_uri(rng, doc):
            pass
        else:
            doc = mutate_json(rng, doc)
    return doc, bin_chunk


def mutate_file(rng, source):
    """The mutated bytes of `source`."""
    data = open(source, "rb").read()
    for _ in range(8):  # retry when a mutation cannot be written as JSON (an overflow to inf)
        try:
            if source.endswith(".glb") or data[:4] == b"glTF":
                parts = split_glb(data)
                if parts is None or rng.random() < 0.3:
                    return mutate_bytes(rng, data, fraction=0.3 if rng.random() < 0.5 else 1.0)
                doc, bin_chunk = mutate_doc(rng, *parts)
                return join_glb(doc, bin_chunk)
            try:
                doc = json.loads(data.decode("utf-8"))
            except ValueError:
                return mutate_bytes(rng, data)
            if rng.random() < 0.05:
                return mutate_bytes(rng, data)
            doc, _ = mutate_doc(rng, doc)
            return json.dumps(doc, allow_nan=False, indent=1).encode()
        except (ValueError, OverflowError, RecursionError):
            continue
    return mutate_bytes(rng, data)


def link_folder(out_dir, source_dir, folders):
    """The output folder for one source folder, with links to its non-glTF files."""
    if source_dir not in folders:
        folder = os.path.join(out_dir, "%03d" % len(folders))
        os.makedirs(folder, exist_ok=True)
        for name in sorted(os.listdir(source_dir)):
            src = os.path.join(source_dir, name)
            if os.path.isfile(src) and not name.endswith((".gltf", ".glb")):
                dst = os.path.join(folder, name)
                if not os.path.lexists(dst):
                    os.symlink(src, dst)
        folders[source_dir] = folder
    return folders[source_dir]


def write_mutations(out_dir, count, seed):
    """Writes the mutations and returns their paths."""
    rng = random.Random(seed)
    sources = corpus_files()
    folders, paths = {}, []
    for i in range(count):
        source = rng.choice(sources)
        folder = link_folder(out_dir, os.path.dirname(source), folders)
        path = os.path.join(folder, "m%05d%s" % (i, os.path.splitext(source)[1]))
        with open(path, "wb") as f:
            f.write(mutate_file(rng, source))
        paths.append(path)
    return paths


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: mutate.py OUT_DIR [COUNT] [SEED]")
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 10000
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 20240601
    for path in write_mutations(sys.argv[1], count, seed):
        print(path)


sys.setrecursionlimit(10000)  # deeply nested fuzz inputs
if __name__ == "__main__":
    main()
