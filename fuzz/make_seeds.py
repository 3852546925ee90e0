#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora (fuzz/corpus/<target>/): small valid files, made here by
hand so no third-party asset is needed. Run from anywhere: python3 fuzz/make_seeds.py."""
import base64
import json
import pathlib
import shutil
import struct
import zlib

FUZZ = pathlib.Path(__file__).resolve().parent
CORPUS = FUZZ / "corpus"


def put(target, name, data):
    path = CORPUS / target / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data.encode() if isinstance(data, str) else data)


# --- OBJ ---------------------------------------------------------------------------------------
put("obj", "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n")
put("obj", "quad-negative.obj",
    "# a quad (triangulated) with relative indices\no quad\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
    "vn 0 1 0\nf -4//-1 -3//-1 -2//-1 -1//-1\n")
put("obj", "objects.obj",
    "mtllib missing.mtl\no a\ng first\ns 1\nusemtl none\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\n"
    "vt 0 0\nvt 1 1\nf 1/1 2/2 3/1\no b\nf 1 3 4 5\n")
put("obj", "pentagon.obj", "v 1 0 0\nv 0.31 0.95 0\nv -0.81 0.59 0\nv -0.81 -0.59 0\nv 0.31 -0.95 0\nf 1 2 3 4 5\n")

# --- glTF / GLB --------------------------------------------------------------------------------
def triangle_buffer(index_format="<3H"):
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    normals = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
    uvs = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    indices = struct.pack(index_format, 0, 1, 2)
    return positions + normals + uvs + indices


def triangle_gltf(index_type=5123, index_format="<3H", uri=True):
    data = triangle_buffer(index_format)
    buffer = {"byteLength": len(data)}
    if uri:
        buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "translation": [0, 0.5, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "mode": 4}]}],
        "buffers": [buffer],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 36},
            {"buffer": 0, "byteOffset": 72, "byteLength": 24},
            {"buffer": 0, "byteOffset": 96, "byteLength": len(data) - 96},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
            {"bufferView": 3, "componentType": index_type, "count": 3, "type": "SCALAR"},
        ],
    }
    return gltf, data


def glb(gltf, binary):
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


gltf, _ = triangle_gltf()
put("gltf", "triangle.gltf", json.dumps(gltf, indent=1))
gltf["nodes"] = [{"children": [1], "rotation": [0, 0.7071068, 0, 0.7071068], "scale": [2, 2, 2]},
                 {"mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 1]}]
gltf["scenes"] = [{"nodes": [0]}]
put("gltf", "hierarchy.gltf", json.dumps(gltf, indent=1))
# Without indices and normals (the loader makes both), and without a scene (every node is drawn).
gltf, _ = triangle_gltf()
del gltf["scene"], gltf["scenes"]
gltf["meshes"][0]["primitives"][0] = {"attributes": {"POSITION": 0}}
put("gltf", "no-indices.gltf", json.dumps(gltf, indent=1))
gltf, data = triangle_gltf(uri=False)
put("gltf", "triangle.glb", glb(gltf, data))
gltf, data = triangle_gltf(index_type=5125, index_format="<3I", uri=False)
gltf["bufferViews"][3]["byteLength"] = 12
put("gltf", "uint32-indices.glb", glb(gltf, data))

# --- PNG (and one BMP: stb_image takes any format it knows) -------------------------------------
def png_chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def png(width, height, bit_depth, colour_type, rows, extra=b""):
    raw = b"".join(b"\0" + row for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0))
            + extra + png_chunk(b"IDAT", zlib.compress(raw)) + png_chunk(b"IEND", b""))


flat = bytes([128, 128, 255])
put("png", "flat-rgb8.png", png(4, 4, 8, 2, [flat * 4] * 4))
put("png", "tilted-rgba8.png", png(2, 2, 8, 6, [bytes([200, 128, 230, 255]) * 2] * 2))
put("png", "flat-rgb16.png", png(2, 2, 16, 2, [struct.pack(">3H", 32768, 32768, 65535) * 2] * 2))
put("png", "grey8.png", png(1, 1, 8, 0, [b"\x80"]))
put("png", "palette.png", png(2, 2, 8, 3, [b"\0\1", b"\1\0"], png_chunk(b"PLTE", flat + bytes([255, 128, 200]))))
bmp_pixels = (flat[::-1] * 2 + b"\0\0") * 2  # BGR rows padded to 4 bytes
put("png", "flat.bmp", b"BM" + struct.pack("<IHHI", 54 + len(bmp_pixels), 0, 0, 54)
    + struct.pack("<IiiHHIIiiII", 40, 2, 2, 1, 24, 0, len(bmp_pixels), 2835, 2835, 0, 0) + bmp_pixels)

# --- EXR (scanline, uncompressed or ZIPS; float or half; layers) --------------------------------
def exr_attribute(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def zip_rows(raw):
    """OpenEXR's ZIP preprocessing (bytes split into two halves, then deltas) and zlib."""
    reordered = bytearray(raw[0::2] + raw[1::2])
    for i in range(len(reordered) - 1, 0, -1):
        reordered[i] = (reordered[i] - reordered[i - 1] + 128) & 0xFF
    packed = zlib.compress(bytes(reordered))
    return packed if len(packed) < len(raw) else raw


def exr(width, height, channels, pixel_type=2, compression=0):
    """channels: names; each pixel of channel c in row y is 0.5 + 0.1 c + 0.01 y."""
    channels = sorted(channels)
    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", pixel_type, 0, 1, 1) for c in channels) + b"\0"
    window = struct.pack("<4i", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2) + exr_attribute("channels", "chlist", chlist)
              + exr_attribute("compression", "compression", bytes([compression]))
              + exr_attribute("dataWindow", "box2i", window) + exr_attribute("displayWindow", "box2i", window)
              + exr_attribute("lineOrder", "lineOrder", b"\0")
              + exr_attribute("pixelAspectRatio", "float", struct.pack("<f", 1))
              + exr_attribute("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0))
              + exr_attribute("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
    fmt = "<%d%s" % (width, "f" if pixel_type == 2 else "e")
    blocks = []
    for y in range(height):
        raw = b"".join(struct.pack(fmt, *[0.5 + 0.1 * c + 0.01 * y] * width) for c in range(len(channels)))
        data = zip_rows(raw) if compression == 2 else raw
        blocks.append(struct.pack("<ii", y, len(data)) + data)
    offset = len(header) + 8 * height
    table = b""
    for block in blocks:
        table += struct.pack("<Q", offset)
        offset += len(block)
    return header + table + b"".join(blocks)


put("exr", "rgb-float.exr", exr(3, 2, ["R", "G", "B"]))
put("exr", "rgb-half.exr", exr(2, 2, ["R", "G", "B"], pixel_type=1))
put("exr", "rgb-zips.exr", exr(4, 3, ["R", "G", "B"], compression=2))
put("exr", "layers.exr", exr(2, 1, ["R", "G", "B", "specular.R", "specular.G", "specular.B"]))

# --- Scenes: the built-in ones, and one that reaches the mesh and image loaders ------------------
(CORPUS / "scene").mkdir(parents=True, exist_ok=True)
for toml in sorted((FUZZ.parent / "scenes").glob("*.toml")):
    shutil.copy(toml, CORPUS / "scene" / toml.name)
put("scene", "files-and-generators.toml", """\
[film]
width = 32
height = 16
[camera]
position = [0, 1, 3]
target = [0, 0, 0]
[[material]]
name = "bumpy"
alpha = 0.1
normal_map = { generator = "bumps", resolution = 16, waves = 8, max_frequency = 4 }
[[material]]
name = "flaky"
normal_map = { generator = "flakes", resolution = 16, cells = 4 }
[[material]]
name = "mapped"
normal_map = { file = "normals.png" }
[[shape]]
type = "mesh"
file = "mesh.obj"
material = "mapped"
[[shape]]
type = "sphere"
segments = 8
material = "bumpy"
[[shape]]
type = "tube"
points = [[0, 0, 0], [1, 0, 0], [1, 1, 0]]
radius = 0.1
material = "flaky"
[[light]]
type = "point"
position = [1, 2, 3]
intensity = 10
""")

# --- Viewer scripts: the README's screenshot script, and one line of every command -----------------
(CORPUS / "view_script").mkdir(parents=True, exist_ok=True)
shutil.copy(FUZZ.parent / "tools" / "viewer-readme.script", CORPUS / "view_script" / "viewer-readme.script")
put("view_script", "every-command.txt", """\
# one of each
method lean
compare reference
mode split
split 0.25
flip
param sigma2=0.5
compare-param sigma2=0.1
reset-params
error-overlay on 0.5
frame 3
next
previous
play
pause
orbit 10 -5
dolly 1.5
fly 0.1 0 -0.2
look 5 2
path
exposure -1.5
bloom 0.2
continuous off
magnify 12 20 8
magnify off
screenshot shot.png
window-screenshot window.png
wait 2
quit
""")

# The pyramid target's seed (fuzz/corpus/pyramid/bumps-16-rank2.bin) is the payload of a real cache
# entry, made by glintlab itself rather than here (docs/fuzzing.md says how).
