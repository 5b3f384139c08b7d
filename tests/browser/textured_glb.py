"""A small textured GLB for the browser's checks: a globe whose base colour texture is a checkerboard."""

from __future__ import annotations

import json
import math
import struct
import zlib

# The checkerboard's two colours: far from the mu colour map's (which has no magenta) and from
# the clay and the highlight, so that either is told in a screenshot whatever the shading.
MAGENTA = (230, 0, 230)
GREEN = (0, 190, 0)


def checker_png(width: int = 64, height: int = 32, square: int = 8) -> bytes:
    """An RGB PNG of square x square cells, MAGENTA and GREEN alternating."""
    rows = b"".join(
        b"\0" + b"".join(bytes(MAGENTA if (x // square + y // square) % 2 else GREEN) for x in range(width))
        for y in range(height))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def globe_glb(rows: int = 16, cols: int = 32) -> bytes:
    """A sphere of rows x cols quads (a slightly flattened one, so its pose is well defined), its
    texture wrapped around it once: a seam where u goes from 1 back to 0, as a globe's."""
    positions, uvs, indices = [], [], []
    for i in range(rows + 1):
        theta = math.pi * i / rows
        for j in range(cols + 1):  # the seam's column twice, with u = 0 and u = 1
            phi = 2 * math.pi * j / cols
            positions += [1.0 * math.sin(theta) * math.cos(phi), 0.8 * math.cos(theta),
                          0.6 * math.sin(theta) * math.sin(phi)]
            uvs += [j / cols, i / rows]  # glTF: v = 0 at the image's top row
    for i in range(rows):
        for j in range(cols):
            a, b = i * (cols + 1) + j, (i + 1) * (cols + 1) + j
            if i > 0:
                indices += [a, a + 1, b]
            if i < rows - 1:
                indices += [a + 1, b + 1, b]
    image = checker_png()
    parts = [struct.pack(f"<{len(positions)}f", *positions), struct.pack(f"<{len(uvs)}f", *uvs),
             struct.pack(f"<{len(indices)}H", *indices), image]
    views, offset = [], 0
    for part in parts:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(part)})
        offset += len(part) + (-len(part)) % 4
    binary = b"".join(p + b"\0" * ((-len(p)) % 4) for p in parts)
    count = len(positions) // 3
    gltf = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(binary)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": [-1, -0.8, -0.6], "max": [1, 0.8, 0.6]},
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "images": [{"bufferView": 3, "mimeType": "image/png"}],
        "textures": [{"source": 0}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                                    "material": 0}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }
    text = json.dumps(gltf).encode()
    text += b" " * ((-len(text)) % 4)
    length = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<4sII", b"glTF", 2, length) + struct.pack("<I4s", len(text), b"JSON") + text
            + struct.pack("<I4s", len(binary), b"BIN\0") + binary)
