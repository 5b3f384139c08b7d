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
    return plain_checker_png(MAGENTA, GREEN, width, height, square)


def plain_checker_png(light: tuple, dark: tuple, width: int = 16, height: int = 16, square: int = 4) -> bytes:
    """An RGB PNG of square x square cells, LIGHT and DARK alternating (DARK first)."""
    rows = b"".join(
        b"\0" + b"".join(bytes(light if (x // square + y // square) % 2 else dark) for x in range(width))
        for y in range(height))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def globe(rows: int, cols: int) -> tuple:
    """A sphere of rows x cols quads (a slightly flattened one, so its pose is well defined), its
    texture wrapped around it once: a seam where u goes from 1 back to 0, as a globe's. Positions,
    texture coordinates, and the triangles' corners of each row of quads."""
    positions, uvs, row_indices = [], [], []
    for i in range(rows + 1):
        theta = math.pi * i / rows
        for j in range(cols + 1):  # the seam's column twice, with u = 0 and u = 1
            phi = 2 * math.pi * j / cols
            positions += [1.0 * math.sin(theta) * math.cos(phi), 0.8 * math.cos(theta),
                          0.6 * math.sin(theta) * math.sin(phi)]
            uvs += [j / cols, i / rows]  # glTF: v = 0 at the image's top row
    for i in range(rows):
        indices = []
        for j in range(cols):
            a, b = i * (cols + 1) + j, (i + 1) * (cols + 1) + j
            if i > 0:
                indices += [a, a + 1, b]
            if i < rows - 1:
                indices += [a + 1, b + 1, b]
        row_indices.append(indices)
    return positions, uvs, row_indices


def pack_glb(positions: list, uvs: list, primitives: list, images: list, materials: list) -> bytes:
    """A GLB of one mesh: POSITION and TEXCOORD_0 shared by the primitives, each (indices,
    material index); each image a base colour texture (texture i is image i)."""
    parts = [struct.pack(f"<{len(positions)}f", *positions), struct.pack(f"<{len(uvs)}f", *uvs)]
    parts += [struct.pack(f"<{len(indices)}H", *indices) for indices, _ in primitives] + images
    views, offset = [], 0
    for part in parts:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(part)})
        offset += len(part) + (-len(part)) % 4
    binary = b"".join(p + b"\0" * ((-len(p)) % 4) for p in parts)
    count = len(positions) // 3
    first_image = 2 + len(primitives)
    gltf = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(binary)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": [min(positions[k::3]) for k in range(3)], "max": [max(positions[k::3]) for k in range(3)]},
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC2"},
        ] + [{"bufferView": 2 + p, "componentType": 5123, "count": len(indices), "type": "SCALAR"}
             for p, (indices, _) in enumerate(primitives)],
        "images": [{"bufferView": first_image + i, "mimeType": "image/png"} for i in range(len(images))],
        "textures": [{"source": i} for i in range(len(images))],
        "materials": materials,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2 + p,
                                    "material": material} for p, (_, material) in enumerate(primitives)]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }
    text = json.dumps(gltf).encode()
    text += b" " * ((-len(text)) % 4)
    length = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<4sII", b"glTF", 2, length) + struct.pack("<I4s", len(text), b"JSON") + text
            + struct.pack("<I4s", len(binary), b"BIN\0") + binary)


def globe_glb(rows: int = 16, cols: int = 32) -> bytes:
    """The globe with the checkerboard as its one base colour texture."""
    positions, uvs, row_indices = globe(rows, cols)
    indices = [k for row in row_indices for k in row]
    return pack_glb(positions, uvs, [(indices, 0)], [checker_png()],
                    [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])


# The two-texture globe's southern texture: white and black cells, which its material's factor
# turns blue (BLUE_FACTOR) and black; without the factor they stay white and black.
WHITE, BLACK = (255, 255, 255), (0, 0, 0)
BLUE_FACTOR = [0.1, 0.2, 1.0, 1.0]


def south_png() -> bytes:
    return plain_checker_png(WHITE, BLACK, 64, 64, 2)


def two_textures_glb(rows: int = 16, cols: int = 32) -> bytes:
    """The globe in two primitives of two materials: the north with the checkerboard, the south
    with south_png under baseColorFactor BLUE_FACTOR, so that magenta, green, and bright blue next
    to black show only when each primitive maps its own texture and the factor multiplies it."""
    positions, uvs, row_indices = globe(rows, cols)
    north = [k for row in row_indices[:rows // 2] for k in row]
    south = [k for row in row_indices[rows // 2:] for k in row]
    return pack_glb(positions, uvs, [(north, 0), (south, 1)],
                    [checker_png(), south_png()],
                    [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
                     {"pbrMetallicRoughness": {"baseColorTexture": {"index": 1},
                                               "baseColorFactor": BLUE_FACTOR}}])


def globe_obj(rows: int = 16, cols: int = 32) -> tuple:
    """The globe as an OBJ naming model.mtl, whose material maps textures/checker.png (a
    folder, as exporters write it): (the OBJ's text, the MTL's text)."""
    positions, uvs, row_indices = globe(rows, cols)
    lines = ["mtllib model.mtl", "o globe"]
    lines += [f"v {positions[i]:.6f} {positions[i + 1]:.6f} {positions[i + 2]:.6f}" for i in range(0, len(positions), 3)]
    # OBJ: v = 0 at the image's bottom row.
    lines += [f"vt {uvs[i]:.6f} {1 - uvs[i + 1]:.6f}" for i in range(0, len(uvs), 2)]
    lines.append("usemtl globe")
    corners = [k + 1 for row in row_indices for k in row]
    lines += ["f " + " ".join(f"{k}/{k}" for k in corners[i:i + 3]) for i in range(0, len(corners), 3)]
    mtl = "newmtl globe\nKd 1 1 1\nmap_Kd textures/checker.png\n"
    return "\n".join(lines) + "\n", mtl
