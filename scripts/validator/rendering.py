"""Which glTF-Validator errors affect what relt renders.

An error affects rendering when it lies in data relt reads to build the scene: positions, normals
and indices (and the accessors, buffer views and buffers behind them), primitive modes and
materials, the material factors relt maps (base colour, metallic, roughness, emission, the three
material extensions), node hierarchy and transforms, perspective cameras' yfov, punctual lights,
the scene choice, the asset version and the container. Anything else is ignored by relt, so an
error there cannot change the image: textures, images, samplers, animations, skins, morph targets,
attributes other than POSITION and NORMAL, camera clipping planes, orthographic cameras, accessor
bounds, alignment and GPU usage hints. docs/ARCHITECTURE.md, "The loader against the glTF
validator", gives the reasons code by code.
"""
import json
import struct

# Codes that never change relt's image, wherever they point, with the reason.
COSMETIC_CODES = {
    "ACCESSOR_MIN_MISMATCH": "relt never reads accessor min/max; bounds come from the data",
    "ACCESSOR_MAX_MISMATCH": "relt never reads accessor min/max",
    "ACCESSOR_ELEMENT_OUT_OF_MIN_BOUND": "relt never reads accessor min/max",
    "ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND": "relt never reads accessor min/max",
    "MESH_PRIMITIVE_POSITION_ACCESSOR_WITHOUT_BOUNDS": "relt never reads accessor min/max",
    "ACCESSOR_OFFSET_ALIGNMENT": "alignment is for GPU upload; relt copies bytes at any offset",
    "ACCESSOR_TOTAL_OFFSET_ALIGNMENT": "alignment is for GPU upload; relt copies bytes at any offset",
    "MESH_PRIMITIVE_ACCESSOR_UNALIGNED": "alignment is for GPU upload; relt copies bytes at any offset",
    "ACCESSOR_MATRIX_ALIGNMENT": "alignment is for GPU upload; relt reads no matrix accessors",
    "GLB_CHUNK_LENGTH_UNALIGNED": "padding only; the chunk's bytes are the same",
    "MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE": "without byteStride the elements are tightly packed: one reading",
    "BUFFER_VIEW_TOO_BIG_BYTE_STRIDE": "every accessor range is checked against the view's byteLength",
    "BUFFER_VIEW_TARGET_OVERRIDE": "a GPU buffer-binding hint; relt has no GPU buffers",
    "ACCESSOR_USAGE_OVERRIDE": "a GPU buffer-binding hint; relt reads the accessor the same for each use",
    "ACCESSOR_NORMALIZED_INVALID": "relt reads float positions and normals, where normalized means nothing",
    "UNDECLARED_EXTENSION": "relt reads its four extensions wherever they appear; the list changes nothing",
    "UNUSED_EXTENSION_REQUIRED": "a required extension that nothing uses requires nothing",
    "NON_REQUIRED_EXTENSION": "relt does not support such extensions and refuses the data they would change",
    "UNEXPECTED_EXTENSION_OBJECT": "relt reads extensions only where they belong, so a misplaced one is ignored",
    "CAMERA_XMAG_YMAG_ZERO": "orthographic cameras are skipped with a warning",
    "EMPTY_ENTITY": "an empty array or object declares nothing, which is how relt reads it",
}

# Properties relt never reads, wherever they are (the last part of the pointer).
IGNORED_LEAVES = {"min", "max", "normalized", "target", "extras"}

# Top-level properties relt never reads.
IGNORED_TOP = {"animations", "skins", "textures", "images", "samplers", "extensionsUsed", "extensionsRequired",
               "extras", "asset/copyright", "asset/generator"}

MATERIAL_READ = {"name", "doubleSided", "emissiveFactor", "pbrMetallicRoughness/baseColorFactor",
                 "pbrMetallicRoughness/metallicFactor", "pbrMetallicRoughness/roughnessFactor",
                 "extensions/KHR_materials_emissive_strength", "extensions/KHR_materials_ior",
                 "extensions/KHR_materials_transmission", "extras/microfacet"}


def gltf_json(path):
    """The JSON document of a .gltf or .glb file, or None when it cannot be parsed."""
    try:
        data = open(path, "rb").read()
        if data[:4] == b"glTF":
            length = struct.unpack_from("<I", data, 12)[0]
            data = data[20:20 + length]
        doc = json.loads(data.decode("utf-8"))
        return doc if isinstance(doc, dict) else None
    except (OSError, ValueError, struct.error, RecursionError):
        return None


def _list(doc, key):
    v = doc.get(key)
    return v if isinstance(v, list) else []


def _index(v):
    return v if isinstance(v, int) and not isinstance(v, bool) and v >= 0 else None


def used_data(doc):
    """Accessors, buffer views and buffers relt reads: POSITION, NORMAL and indices of every mesh."""
    accessors = set()
    for mesh in _list(doc, "meshes"):
        for prim in _list(mesh, "primitives") if isinstance(mesh, dict) else []:
            if not isinstance(prim, dict):
                continue
            attributes = prim.get("attributes") if isinstance(prim.get("attributes"), dict) else {}
            for v in (attributes.get("POSITION"), attributes.get("NORMAL"), prim.get("indices")):
                if _index(v) is not None:
                    accessors.add(v)
    views = set()
    all_accessors = _list(doc, "accessors")
    for a in accessors:
        acc = all_accessors[a] if a < len(all_accessors) and isinstance(all_accessors[a], dict) else {}
        views.add(_index(acc.get("bufferView")))
        sparse = acc.get("sparse") if isinstance(acc.get("sparse"), dict) else {}
        for part in ("indices", "values"):
            if isinstance(sparse.get(part), dict):
                views.add(_index(sparse[part].get("bufferView")))
    all_views = _list(doc, "bufferViews")
    buffers = {_index(all_views[v].get("buffer")) for v in views
               if v is not None and v < len(all_views) and isinstance(all_views[v], dict)}
    return accessors, views - {None}, buffers - {None}


def _value_at(doc, parts):
    for p in parts:
        if isinstance(doc, list) and p.isdigit() and int(p) < len(doc):
            doc = doc[int(p)]
        elif isinstance(doc, dict) and p in doc:
            doc = doc[p]
        else:
            return None
    return doc


def _under(rest, prefixes):
    return any(rest == p or rest.startswith(p + "/") for p in prefixes)


def _primitive_part(rest):
    """Whether /meshes/m/primitives/p/REST is something relt reads."""
    if rest.startswith("attributes/"):
        return rest.split("/")[1] in ("POSITION", "NORMAL")
    return not _under(rest, ["targets", "extensions", "extras"])


def _node_part(rest):
    """Whether /nodes/n/REST is something relt reads (of the extensions only KHR_lights_punctual)."""
    if _under(rest, ["weights", "skin", "extras"]):
        return False
    return not rest.startswith("extensions/") or rest.startswith("extensions/KHR_lights_punctual")


def affects_rendering(code, pointer, doc, used):
    """(affects, why) for one error of a file relt loaded."""
    if code in COSMETIC_CODES:
        return False, COSMETIC_CODES[code]
    parts = [p.replace("~1", "/").replace("~0", "~") for p in pointer.split("/")[1:]] if pointer else []
    if not parts or doc is None:
        return True, "the file or its container"
    top, path = parts[0], "/".join(parts)
    accessors, views, buffers = used
    if _under(path, IGNORED_TOP) or top not in (
            "asset", "scene", "scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers", "materials",
            "cameras", "extensions"):
        return False, "relt does not read " + top
    index = int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else None
    rest = "/".join(parts[2:])
    if any(p.endswith("Texture") for p in parts) or (top not in ("nodes", "cameras", "materials") and
                                                     parts[-1] == "name"):
        return False, "textures and names of things relt does not list are not read"
    if any(p in IGNORED_LEAVES for p in parts[2:]):
        return False, "relt does not read " + next(p for p in parts[2:] if p in IGNORED_LEAVES)
    if code == "VALUE_NOT_IN_RANGE" and parts[-1] == "byteStride" and _value_at(doc, parts) == 0:
        return False, "byteStride 0 reads as tightly packed, as without byteStride"
    if code == "UNSATISFIED_DEPENDENCY" and parts[-1] == "byteOffset" and _value_at(doc, parts) == 0:
        return False, "a byteOffset of 0 without a bufferView is the default: the accessor is zeros"
    if code == "UNDEFINED_PROPERTY" and path == "extensions/KHR_lights_punctual":
        return False, "KHR_lights_punctual without lights declares no light, as with an empty list"
    if top in ("accessors", "bufferViews", "buffers") and index is not None:
        used_set = {"accessors": accessors, "bufferViews": views, "buffers": buffers}[top]
        return (index in used_set, "used by POSITION, NORMAL or indices" if index in used_set
                else "not used by POSITION, NORMAL or indices")
    if top == "meshes" and len(parts) >= 4 and parts[2] == "primitives":
        read = _primitive_part("/".join(parts[4:]))
        return read, "a primitive's geometry or material" if read else "morph targets or attributes relt ignores"
    if top == "meshes":
        read = not _under(rest, ["weights", "extras", "extensions"])
        return read, "mesh primitives" if read else "mesh weights or extensions"
    if top == "materials":
        read = rest == "" or _under(rest, MATERIAL_READ)
        return read, "a material factor relt maps" if read else "texture or material property relt ignores"
    if top == "cameras":
        read = rest in ("", "type", "perspective", "perspective/yfov")
        return read, "perspective camera" if read else "clip planes, aspect ratio or orthographic camera"
    if top == "nodes":
        read = _node_part(rest)
        return read, "node hierarchy, transform, mesh, camera or light" if read else "node weights or skin"
    if top == "extensions":
        read = _under(path, ["extensions/KHR_lights_punctual"]) and not path.endswith("/range")
        return read, "punctual lights" if read else "an extension or light range relt ignores"
    return True, top
