#!/usr/bin/env python3
"""Hand-written seed inputs for the libFuzzer targets, and conversions of generated meshes.

Usage: make_seeds.py GENERATED_DIR CORPUS_DIR

GENERATED_DIR holds the output of `argtool gen` (off/, ply/, stl/, obj/) and `argtool build`
(arg/); every seed is written to CORPUS_DIR/<target>/<name>. Only the standard library is used,
and every byte is either written here or made by the project's own generator, so the corpus
carries no third-party data.
"""

import base64
import json
import os
import struct
import sys
import zlib

GEN, OUT = sys.argv[1], sys.argv[2]


def put(target, name, data):
    if isinstance(data, str):
        data = data.encode("latin-1")
    assert len(data) <= 64 * 1024, (target, name, len(data))
    folder = os.path.join(OUT, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def generated(fmt, name):
    with open(os.path.join(GEN, fmt, name + "." + fmt), "rb") as f:
        return f.read()


def parse_off(data):
    """The project's own OFF output: 'OFF', counts, vertices, '3 i j k [r g b]' faces."""
    words = data.decode().split("\n")
    nv, nf, _ = map(int, words[1].split())
    verts = [tuple(map(float, line.split())) for line in words[2:2 + nv]]
    faces, colours = [], []
    for line in words[2 + nv:2 + nv + nf]:
        n = list(map(int, line.split()))
        faces.append(tuple(n[1:4]))
        colours.append(tuple(n[4:7]) if len(n) >= 7 else None)
    return verts, faces, colours


# ----------------------------------------------------------------------------------------------
# Images


def png_chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


def png(width, height, colour_type=2, bit_depth=8, pixel=None, palette=None, interlace=0,
        declared=None):
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[colour_type]
    bytes_per_sample = 2 if bit_depth == 16 else 1

    def sample(x, y):
        values = pixel(x, y) if pixel else [(x * 40 + y * 20 + c * 70) % 256
                                            for c in range(channels)]
        return b"".join(struct.pack(">H", v * 257) if bytes_per_sample == 2 else bytes([v % 256])
                        for v in values[:channels])
    # Adam7 passes (x0, y0, dx, dy) when interlaced; one pass over every pixel otherwise.
    passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2),
              (0, 1, 1, 2)] if interlace else [(0, 0, 1, 1)]
    rows = b""
    for x0, y0, dx, dy in passes:
        if x0 >= width:
            continue
        for y in range(y0, height, dy):
            rows += b"\0" + b"".join(sample(x, y) for x in range(x0, width, dx))
    w, h = declared or (width, height)
    out = b"\x89PNG\r\n\x1a\n"
    out += png_chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, bit_depth, colour_type, 0, 0,
                                          interlace))
    if palette:
        out += png_chunk(b"PLTE", bytes(palette))
    out += png_chunk(b"IDAT", zlib.compress(rows))
    out += png_chunk(b"IEND", b"")
    return out


def tga(width, height, rle=False, grey=False, top_first=False):
    kind = (11 if rle else 3) if grey else (10 if rle else 2)
    descriptor = 0x20 if top_first else 0
    out = struct.pack("<BBBHHBHHHHBB", 0, 0, kind, 0, 0, 0, 0, 0, width, height,
                      8 if grey else 24, descriptor)
    pixels = [bytes([(x * 50) % 256]) if grey else bytes([x * 60 % 256, y * 60 % 256, 128])
              for y in range(height) for x in range(width)]
    if not rle:
        return out + b"".join(pixels)
    body = b""
    for i in range(0, len(pixels), 2):  # alternate a run packet and a raw packet
        if i // 2 % 2 == 0:
            body += bytes([0x80 | 1]) + pixels[i]
        else:
            body += bytes([1]) + pixels[i] + pixels[i + 1]
    return out + body


def bmp(width, height, bits=24, colours=0, compression=0, masks=b""):
    """An uncompressed BMP; with bits <= 8 a palette of `colours` entries (0: all 2^bits) and
    pixels cycling through it; with compression 3 (bit fields) the three `masks` after the
    header."""
    if bits <= 8:
        entries = colours or 1 << bits
        palette = b"".join(bytes([i * 40 % 256, i * 80 % 256, i * 120 % 256, 0])
                           for i in range(entries))
        bits_row = "".join(format(x % entries, "0%db" % bits) for x in range(width))
        bits_row += "0" * (-len(bits_row) % 8)
        row = int(bits_row, 2).to_bytes(len(bits_row) // 8, "big")
    else:
        palette = b""
        row = b"".join(bytes([x * 60 % 256, 100, 200, 255][:bits // 8]) for x in range(width))
    row += b"\0" * ((4 - len(row) % 4) % 4)
    pixels = row * height
    offset = 54 + len(masks) + len(palette)
    header = struct.pack("<2sIHHI", b"BM", offset + len(pixels), 0, 0, offset)
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, bits, compression, len(pixels), 2835,
                       2835, colours, 0)
    return header + info + masks + palette + pixels


def jpeg(width, height, components=1):
    """A baseline JPEG whose every block is flat grey: one-code Huffman tables (category 0 for
    DC, end-of-block for AC), so each block is two zero bits."""
    def segment(marker, body):
        return b"\xff" + bytes([marker]) + struct.pack(">H", len(body) + 2) + body
    out = b"\xff\xd8"
    out += segment(0xDB, b"\x00" + b"\x01" * 64)
    comps = b"".join(bytes([i + 1, 0x11, 0]) for i in range(components))
    out += segment(0xC0, struct.pack(">BHHB", 8, height, width, components) + comps)
    one_code = bytes([1] + [0] * 15) + b"\x00"
    out += segment(0xC4, b"\x00" + one_code + b"\x10" + one_code)
    scan = b"".join(bytes([i + 1, 0x00]) for i in range(components))
    out += segment(0xDA, bytes([components]) + scan + b"\x00\x3f\x00")
    blocks = ((width + 7) // 8) * ((height + 7) // 8) * components
    bits = "00" * blocks
    bits += "1" * (-len(bits) % 8)
    out += bytes(int(bits[i:i + 8], 2) for i in range(0, len(bits), 8))
    return out + b"\xff\xd9"


def image_seeds():
    t = "fuzz_decode_image"
    put(t, "png_rgb_4x3.png", png(4, 3))
    put(t, "png_grey_5x2.png", png(5, 2, colour_type=0))
    put(t, "png_rgba_3x3.png", png(3, 3, colour_type=6))
    put(t, "png_grey_alpha_2x2.png", png(2, 2, colour_type=4))
    put(t, "png_palette_4x4.png", png(4, 4, colour_type=3, pixel=lambda x, y: [(x + y) % 3],
                                      palette=[255, 0, 0, 0, 255, 0, 0, 0, 255]))
    put(t, "png_rgb16_2x2.png", png(2, 2, bit_depth=16))
    put(t, "png_interlaced_9x9.png", png(9, 9, interlace=1))
    put(t, "png_declares_100000x100000.png", png(1, 1, declared=(100000, 100000)))
    put(t, "png_declares_0x0.png", png(1, 1, declared=(0, 0)))
    put(t, "png_truncated.png", png(4, 4)[:50])
    put(t, "png_signature_only.png", b"\x89PNG\r\n\x1a\n")
    put(t, "png_ihdr_only.png", png(4, 4)[:33])
    put(t, "png_chunk_length_huge.png", png(2, 2)[:33] + struct.pack(">I", 0x7fffffff) + b"IDAT")
    put(t, "jpeg_grey_16x16.jpg", jpeg(16, 16))
    put(t, "jpeg_colour_8x8.jpg", jpeg(8, 8, components=3))
    put(t, "jpeg_truncated.jpg", jpeg(16, 16)[:120])
    put(t, "jpeg_declares_65000x65000.jpg", jpeg(65000, 65000)[:200])
    # Progressive (SOF2): libjpeg allocates every coefficient while the image is opened, so the
    # size must be refused before (found by fuzzing as an out-of-memory).
    put(t, "jpeg_progressive_declares_65000x65000.jpg",
        jpeg(65000, 65000)[:200].replace(b"\xff\xc0", b"\xff\xc2", 1))
    put(t, "jpeg_soi_only.jpg", b"\xff\xd8\xff")
    put(t, "tga_rgb_3x2.tga", tga(3, 2))
    put(t, "tga_rgb_top_first_2x2.tga", tga(2, 2, top_first=True))
    put(t, "tga_rle_4x2.tga", tga(4, 2, rle=True))
    put(t, "tga_grey_4x1.tga", tga(4, 1, grey=True))
    # TGA 2.0: an extension area (495 bytes, fields left zero) named by the footer.
    plain = tga(2, 2)
    extension = struct.pack("<H", 495) + bytes(493)
    footer = struct.pack("<II", len(plain), 0) + b"TRUEVISION-XFILE.\0"
    put(t, "tga_with_extension_area_2x2.tga", plain + extension + footer)
    put(t, "tga_truncated.tga", tga(4, 4)[:30])
    put(t, "tga_declares_65535x65535.tga", tga(1, 1)[:12] + struct.pack("<HH", 65535, 65535) +
        b"\x18\x00" + b"\x01\x02\x03")
    put(t, "bmp_3x2.bmp", bmp(3, 2))
    put(t, "bmp_truncated.bmp", bmp(3, 2)[:40])
    put(t, "bmp_palette8_3_colours_5x3.bmp", bmp(5, 3, bits=8, colours=3))
    put(t, "bmp_palette4_7x2.bmp", bmp(7, 2, bits=4))
    put(t, "bmp_palette1_9x2.bmp", bmp(9, 2, bits=1))
    put(t, "bmp_top_first_2x2.bmp", bmp(2, -2))
    put(t, "bmp_bitfields32_3x2.bmp", bmp(3, 2, bits=32, compression=3,
                                          masks=struct.pack("<III", 0xff0000, 0xff00, 0xff)))
    put(t, "bmp_bitfields16_4x2.bmp", bmp(4, 2, bits=16, compression=3,
                                          masks=struct.pack("<III", 0xf800, 0x7e0, 0x1f)))
    put(t, "empty", b"")


# ----------------------------------------------------------------------------------------------
# OFF


def off_seeds():
    t = "fuzz_read_off"
    quad = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"
    put(t, "empty.off", "")
    put(t, "keyword_only.off", "OFF\n")
    put(t, "header_only.off", "OFF\n3 1 0\n")
    put(t, "counts_on_keyword_line.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    put(t, "huge_counts.off", "OFF\n2000000000 2000000000 0\n0 0 0\n")
    put(t, "counts_past_int.off", "OFF\n99999999999999999999 1 0\n0 0 0\n")
    put(t, "negative_counts.off", "OFF\n-3 -1 0\n0 0 0\n")
    put(t, "nan_coordinate.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    put(t, "inf_coordinate.off", "OFF\n3 1 0\n0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n")
    put(t, "quad.off", quad)
    put(t, "quad_crlf.off", quad.replace("\n", "\r\n"))
    put(t, "concave_heptagon.off",
        "OFF\n7 1 0\n0 0 0\n4 0 0\n4 4 0\n3 1 0\n2 4 0\n1 1 0\n0 4 0\n7 0 1 2 3 4 5 6\n")
    put(t, "self_intersecting_pentagon.off",
        "OFF\n5 1 0\n0 0 0\n2 2 0\n2 0 0\n0 2 0\n1 3 0\n5 0 1 2 3 4\n")
    put(t, "huge_corner_count.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000 0 1 2\n")
    put(t, "index_out_of_range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")
    put(t, "negative_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n")
    put(t, "two_corner_face.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n3 0 1 2\n")
    put(t, "repeated_corners.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0 1 2 0\n")
    put(t, "comments.off", "# a comment\nOFF # keyword\n# counts next\n3 1 0\n0 0 0 # v0\n"
        "1 0 0\n0 1 0\n\n3 0 1 2 # face\n")
    put(t, "coff_vertex_colours.off",
        "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n")
    put(t, "coff_float_colours.off",
        "COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n")
    put(t, "face_colours_int.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 128 0\n")
    put(t, "face_colours_float.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1.0 0.5 0.0 1\n")
    put(t, "noff_normals.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n")
    put(t, "stoff_texcoords.off", "STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n")
    put(t, "stcnoff_all.off", "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0 0 1\n1 0 0 0 0 1 0 1 0 1 0\n"
        "0 1 0 0 0 1 0 0 1 0 1\n3 0 1 2\n")
    put(t, "4off.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n")
    put(t, "noff_dimension.off", "nOFF\n4\n3 1 0\n0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 2\n")
    put(t, "nan_word.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0x\n3 0 1 2\n")
    binary = b"OFF BINARY\n" + struct.pack(">iii", 3, 1, 0)
    binary += struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack(">iiiii", 3, 0, 1, 2, 0)
    put(t, "binary.off", binary)
    put(t, "binary_truncated.off", binary[:30])
    put(t, "binary_huge_counts.off", b"OFF BINARY\n" + struct.pack(">iii", 0x7fffffff, -5, 0))
    put(t, "extra_data_after.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\njunk\n")


# ----------------------------------------------------------------------------------------------
# OBJ


def obj_seeds():
    t = "fuzz_read_obj"
    tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    put(t, "empty.obj", "")
    put(t, "vertices_only.obj", tri)
    put(t, "triangle.obj", tri + "f 1 2 3\n")
    put(t, "quad_and_polygon.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 2 0\nv -1 1 0\n"
        "f 1 2 3 4\nf 4 3 5 6 1\n")
    put(t, "texcoords_normals.obj", tri + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
        "f 1/1/1 2/2/1 3/3/1\n")
    put(t, "texcoords_out_of_range.obj", tri + "vt 0 0\nf 1/1 2/2 3/3\n")
    put(t, "huge_texcoords.obj", tri + "vt 1e30 -1e30\nvt 3.5 -7.25\nvt 0 1\nf 1/1 2/2 3/3\n")
    put(t, "vertex_normal_only.obj", tri + "vn 0 0 1\nf 1//1 2//1 3//1\n")
    put(t, "negative_indices.obj", tri + "f -3 -2 -1\n")
    put(t, "index_zero.obj", tri + "f 0 1 2\n")
    put(t, "index_out_of_range.obj", tri + "f 1 2 4\n")
    put(t, "index_past_int.obj", tri + "f 1 2 99999999999999999999\n")
    put(t, "nan_vertex.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    put(t, "beyond_float.obj", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    put(t, "vertex_colours.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n")
    put(t, "materials.obj", "mtllib missing.mtl\no thing\ng group\ns 1\nusemtl red\n" + tri +
        "f 1 2 3\nusemtl\n")
    put(t, "lines_points.obj", tri + "l 1 2\np 3\nf 1 2 3\n")
    put(t, "two_corner_face.obj", tri + "f 1 2\nf 1 2 3\n")
    put(t, "repeated_corner.obj", tri + "f 1 1 2 3\n")
    put(t, "continuation.obj", "v 0 0 \\\n0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n3\n")
    put(t, "crlf_comments.obj", "# comment\r\nv 0 0 0\r\nv 1 0 0 # c\r\nv 0 1 0\r\n\r\n"
        "f 1 2 3\r\n")
    put(t, "vw_weight.obj", "v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n")
    put(t, "vertex_too_short.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    put(t, "many_slashes.obj", tri + "f 1/// 2//// 3/1/1/1\n")


# ----------------------------------------------------------------------------------------------
# PLY


def ply_header(fmt, elements, comments=()):
    out = "ply\nformat %s 1.0\n" % fmt
    for c in comments:
        out += "comment %s\n" % c
    for name, count, props in elements:
        out += "element %s %s\n" % (name, count)
        for p in props:
            out += "property %s\n" % p
    return out + "end_header\n"


def ply_seeds(verts, faces, colours):
    t = "fuzz_read_ply"
    vp = ["float x", "float y", "float z"]
    fp = ["list uchar int vertex_indices"]
    put(t, "empty.ply", "")
    put(t, "magic_only.ply", "ply\n")
    put(t, "header_only.ply", ply_header("ascii", [("vertex", 3, vp), ("face", 1, fp)]))
    put(t, "no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n")
    tri_ascii = ply_header("ascii", [("vertex", 3, vp), ("face", 1, fp)]) + \
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
    put(t, "triangle_ascii.ply", tri_ascii)
    put(t, "triangle_ascii_crlf.ply", tri_ascii.replace("\n", "\r\n"))
    put(t, "huge_counts.ply", ply_header("binary_little_endian",
                                         [("vertex", 4000000000, vp), ("face", 4000000000, fp)]))
    put(t, "counts_past_64_bits.ply", ply_header("ascii", [("vertex", "99999999999999999999999",
                                                            vp)]))
    put(t, "negative_counts.ply", ply_header("ascii", [("vertex", -3, vp), ("face", -1, fp)]))
    put(t, "nan_ascii.ply", ply_header("ascii", [("vertex", 3, vp), ("face", 1, fp)]) +
        "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    put(t, "quad_ascii.ply", ply_header("ascii", [("vertex", 4, vp), ("face", 1, fp)]) +
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    put(t, "list_count_255.ply", ply_header("binary_little_endian",
                                            [("vertex", 3, vp), ("face", 1, fp)]).encode() +
        struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\xff" + struct.pack("<3i", 0, 1, 2))
    put(t, "float_list_count.ply", ply_header("ascii", [("vertex", 3, vp),
                                                        ("face", 1, ["list float int v"])]) +
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    put(t, "face_before_vertex.ply", ply_header("ascii", [("face", 1, fp), ("vertex", 3, vp)]) +
        "3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n")
    put(t, "extra_elements.ply", ply_header(
        "ascii", [("vertex", 3, vp + ["double confidence"]), ("face", 1, fp),
                  ("edge", 1, ["int vertex1", "int vertex2"])], comments=["made by hand"]) +
        "0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n0 1\n")
    put(t, "all_types.ply", ply_header(
        "binary_little_endian",
        [("vertex", 3, ["double x", "double y", "double z", "int8 a", "uint16 b", "int32 c"]),
         ("face", 1, ["list uint8 uint32 vertex_indices", "short s"])]).encode() +
        b"".join(struct.pack("<3dbHi", *v, -1, 65535, -7) for v in
                 [(0, 0, 0), (1, 0, 0), (0, 1, 0)]) + b"\x03" + struct.pack("<3Ih", 0, 1, 2, 9))
    put(t, "index_out_of_range.ply", ply_header("ascii", [("vertex", 3, vp), ("face", 1, fp)]) +
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    put(t, "vertex_indices_alias.ply", ply_header("ascii", [("vertex", 3, vp),
                                                            ("face", 1, ["list uchar int "
                                                                         "vertex_index"])]) +
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    put(t, "texcoords.ply", ply_header("ascii", [("vertex", 3, vp + ["float s", "float t"]),
                                                 ("face", 1, fp)]) +
        "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n")
    put(t, "texture_uv_huge.ply", ply_header("ascii", [("vertex", 3, vp + ["float u",
                                                                           "float v"]),
                                                       ("face", 1, fp)]) +
        "0 0 0 1e30 0\n1 0 0 -1e30 0\n0 1 0 0 3e38\n3 0 1 2\n")
    put(t, "face_texcoord_list.ply", ply_header("ascii", [("vertex", 3, vp),
                                                          ("face", 1, fp + ["list uchar float "
                                                                            "texcoord"])]) +
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 6 0 0 1 0 0 1\n")
    put(t, "vertex_colours_uchar.ply", ply_header(
        "ascii", [("vertex", 3, vp + ["uchar red", "uchar green", "uchar blue",
                                      "uchar alpha"]), ("face", 1, fp)]) +
        "0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n")
    put(t, "vertex_colours_float.ply", ply_header(
        "ascii", [("vertex", 3, vp + ["float red", "float green", "float blue"]),
                  ("face", 1, fp)]) + "0 0 0 1 0 0\n1 0 0 0 1 0\n0 1 0 0 0 5\n3 0 1 2\n")
    put(t, "bad_format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n")
    put(t, "unknown_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n"
        "end_header\n0\n")

    # Conversions of a generated model: ASCII and big-endian binary.
    def body(endian, with_colour):
        out = b""
        for v in verts:
            out += struct.pack(endian + "3f", *v)
        for f, c in zip(faces, colours):
            out += struct.pack(endian + "B3i", 3, *f)
            if with_colour:
                out += bytes(c)
        return out
    cp = ["uchar red", "uchar green", "uchar blue"]
    put(t, "gen_human_big_endian.ply",
        ply_header("binary_big_endian", [("vertex", len(verts), vp),
                                         ("face", len(faces), fp + cp)]).encode() +
        body(">", True))
    text = ply_header("ascii", [("vertex", len(verts), vp), ("face", len(faces), fp)])
    text += "".join("%g %g %g\n" % v for v in verts)
    text += "".join("3 %d %d %d\n" % f for f in faces)
    put(t, "gen_human_ascii.ply", text)


# ----------------------------------------------------------------------------------------------
# STL


def stl_binary(tris, header=b"binary stl made by hand", count=None):
    out = header.ljust(80, b" ")[:80] + struct.pack("<I", len(tris) if count is None else count)
    for a, b, c in tris:
        out += struct.pack("<12fH", 0, 0, 1, *a, *b, *c, 0)
    return out


def stl_ascii(tris, name="thing"):
    out = "solid %s\n" % name
    for a, b, c in tris:
        out += " facet normal 0 0 1\n  outer loop\n"
        for p in (a, b, c):
            out += "   vertex %r %r %r\n" % p
        out += "  endloop\n endfacet\n"
    return out + "endsolid %s\n" % name


def stl_seeds(verts, faces):
    t = "fuzz_read_stl"
    tri = [((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))]
    tet_v = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
    tet = [tuple(tet_v[i] for i in f) for f in [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]]
    put(t, "empty.stl", "")
    put(t, "solid_only.stl", "solid")
    put(t, "ascii_triangle.stl", stl_ascii(tri))
    put(t, "ascii_tetrahedron_crlf.stl", stl_ascii(tet).replace("\n", "\r\n"))
    put(t, "ascii_nan.stl", stl_ascii(tri).replace("1.0 0.0 0.0", "nan 0 0"))
    put(t, "ascii_missing_endloop.stl", stl_ascii(tri).replace("  endloop\n", ""))
    put(t, "ascii_four_vertices.stl", stl_ascii(tri).replace("  endloop", "   vertex 1 1 1\n"
                                                                          "  endloop"))
    put(t, "ascii_no_endsolid.stl", stl_ascii(tri).split("endsolid")[0])
    put(t, "ascii_two_solids.stl", stl_ascii(tri, "a") + stl_ascii(tet, "b"))
    put(t, "binary_triangle.stl", stl_binary(tri))
    put(t, "binary_tetrahedron_named_solid.stl", stl_binary(tet, header=b"solid tetrahedron"))
    put(t, "binary_zero_triangles.stl", stl_binary([]))
    put(t, "binary_header_only.stl", stl_binary([])[:80])
    put(t, "binary_count_too_big.stl", stl_binary(tri, count=0xffffffff))
    put(t, "binary_count_too_small.stl", stl_binary(tet, count=2))
    put(t, "binary_truncated.stl", stl_binary(tet)[:150])
    put(t, "binary_nan.stl", stl_binary([((float("nan"), 0.0, 0.0), (1.0, 0.0, 0.0),
                                          (0.0, 1.0, 0.0))]))
    put(t, "binary_inf.stl", stl_binary([((float("inf"), 0.0, 0.0), (1.0, 0.0, 0.0),
                                          (0.0, 1.0, 0.0))]))
    # Conversion of a generated model to ASCII.
    put(t, "gen_human_ascii.stl", stl_ascii([tuple(verts[i] for i in f) for f in faces], "human"))


# ----------------------------------------------------------------------------------------------
# GLB


def glb(document, binary=b"", version=2, declared=None):
    text = json.dumps(document, separators=(",", ":")).encode() if not isinstance(
        document, bytes) else document
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text
    if binary:
        body += struct.pack("<I4s", len(binary), b"BIN\0") + binary
    length = 12 + len(body) if declared is None else declared
    return b"glTF" + struct.pack("<II", version, length) + body


def gltf_mesh(verts, faces, colours=None, uv=None, image=None, mode=None, index_type=5125,
              nodes=None, extra=None):
    """A GLB document with one primitive; returns (document, binary)."""
    binary = b""
    views, accessors = [], []

    def add(data, target=None):
        nonlocal binary
        binary += b"\0" * (-len(binary) % 4)
        view = {"buffer": 0, "byteOffset": len(binary), "byteLength": len(data)}
        if target:
            view["target"] = target
        binary += data
        views.append(view)
        return len(views) - 1

    pos = b"".join(struct.pack("<3f", *v) for v in verts)
    lo = [min(v[i] for v in verts) for i in range(3)]
    hi = [max(v[i] for v in verts) for i in range(3)]
    accessors.append({"bufferView": add(pos, 34962), "componentType": 5126, "count": len(verts),
                      "type": "VEC3", "min": lo, "max": hi})
    attributes = {"POSITION": 0}
    fmt = {5121: "B", 5123: "H", 5125: "I"}[index_type]
    idx = b"".join(struct.pack("<3" + fmt, *f) for f in faces)
    accessors.append({"bufferView": add(idx, 34963), "componentType": index_type,
                      "count": 3 * len(faces), "type": "SCALAR"})
    primitive = {"attributes": attributes, "indices": 1}
    if mode is not None:
        primitive["mode"] = mode
    doc = {"asset": {"version": "2.0", "generator": "arg make_seeds.py"}}
    if colours:
        data = b"".join(struct.pack("<4B", *c, 255) for c in colours)
        accessors.append({"bufferView": add(data), "componentType": 5121, "normalized": True,
                          "count": len(verts), "type": "VEC4"})
        attributes["COLOR_0"] = len(accessors) - 1
    material = {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.4, 0.2, 1.0]}}
    if uv:
        data = b"".join(struct.pack("<2f", *t) for t in uv)
        accessors.append({"bufferView": add(data), "componentType": 5126, "count": len(verts),
                          "type": "VEC2"})
        attributes["TEXCOORD_0"] = len(accessors) - 1
    if image:
        doc["images"] = [{"bufferView": add(image), "mimeType": "image/png"}]
        doc["samplers"] = [{"wrapS": 33648, "wrapT": 33071}]
        doc["textures"] = [{"source": 0, "sampler": 0}]
        material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    doc["materials"] = [material]
    primitive["material"] = 0
    doc["buffers"] = [{"byteLength": len(binary) + (-len(binary) % 4)}]
    doc["bufferViews"] = views
    doc["accessors"] = accessors
    doc["meshes"] = [{"primitives": [primitive]}]
    doc["nodes"] = nodes if nodes is not None else [{"mesh": 0}]
    doc["scenes"] = [{"nodes": [0]}]
    doc["scene"] = 0
    if extra:
        extra(doc)
    return doc, binary


def glb_seeds(verts, faces, colours):
    t = "fuzz_read_glb"
    tet_v = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
    tet_f = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
    put(t, "empty.glb", "")
    put(t, "magic_only.glb", "glTF")
    put(t, "header_only.glb", b"glTF" + struct.pack("<II", 2, 12))
    put(t, "tetrahedron.glb", glb(*gltf_mesh(tet_v, tet_f)))
    put(t, "tetrahedron_uint8_indices.glb", glb(*gltf_mesh(tet_v, tet_f, index_type=5121)))
    put(t, "tetrahedron_uint16_indices.glb", glb(*gltf_mesh(tet_v, tet_f, index_type=5123)))
    put(t, "tetrahedron_vertex_colours.glb",
        glb(*gltf_mesh(tet_v, tet_f, colours=[(255, 0, 0), (0, 255, 0), (0, 0, 255),
                                              (9, 9, 9)])))
    uv = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (2.5, -3.0)]
    put(t, "tetrahedron_textured.glb", glb(*gltf_mesh(tet_v, tet_f, uv=uv, image=png(4, 4))))
    put(t, "tetrahedron_bad_texture.glb",
        glb(*gltf_mesh(tet_v, tet_f, uv=uv, image=png(4, 4)[:40])))
    put(t, "tetrahedron_texture_100000x100000.glb",
        glb(*gltf_mesh(tet_v, tet_f, uv=uv, image=png(1, 1, declared=(100000, 100000)))))
    strip_f = [(0, 1, 2), (3, 0, 1)]
    put(t, "triangle_strip.glb", glb(*gltf_mesh(tet_v, strip_f, mode=5)))
    put(t, "triangle_fan.glb", glb(*gltf_mesh(tet_v, strip_f, mode=6)))
    put(t, "points_mode.glb", glb(*gltf_mesh(tet_v, tet_f, mode=0)))
    nodes = [{"children": [1], "matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1]},
             {"children": [2], "translation": [1, 0, 0], "rotation": [0, 0, 0.7071068, 0.7071068],
              "scale": [1, 2, 3]},
             {"mesh": 0}]
    put(t, "node_tree.glb", glb(*gltf_mesh(tet_v, tet_f, nodes=nodes)))
    cyclic = [{"children": [1], "mesh": 0}, {"children": [0]}]
    put(t, "cyclic_node_tree.glb", glb(*gltf_mesh(tet_v, tet_f, nodes=cyclic)))
    put(t, "node_is_own_child.glb", glb(*gltf_mesh(tet_v, tet_f, nodes=[{"children": [0],
                                                                        "mesh": 0}])))
    chain = [{"children": [i + 1]} for i in range(100)] + [{"mesh": 0}]
    put(t, "deep_node_chain.glb", glb(*gltf_mesh(tet_v, tet_f, nodes=chain)))
    put(t, "huge_scale.glb", glb(*gltf_mesh(tet_v, tet_f, nodes=[{"mesh": 0,
                                                                 "scale": [1e308, 1e308, 1e308]}])))
    overflow = [{"children": [1], "scale": [1e308, 1, 1]}, {"mesh": 0, "scale": [1e308, 1, 1]}]
    put(t, "overflowing_transform.glb", glb(*gltf_mesh(tet_v, tet_f, nodes=overflow)))

    def deep_extras(doc):
        doc["extras"] = json.loads("[" * 500 + "]" * 500)
    put(t, "deep_json_extras.glb", glb(*gltf_mesh(tet_v, tet_f, extra=deep_extras)))
    doc, binary = gltf_mesh(tet_v, tet_f)
    text = json.dumps(doc).encode()
    put(t, "deep_json_unparsed.glb", glb(text[:-1] + b',"x":' + b"[" * 5000 + b"]" * 5000 + b"}",
                                         binary))

    def no_scene(doc):
        del doc["scenes"], doc["scene"]
    put(t, "no_scene.glb", glb(*gltf_mesh(tet_v, tet_f, extra=no_scene)))

    def bad_scene(doc):
        doc["scene"] = 7
    put(t, "missing_default_scene.glb", glb(*gltf_mesh(tet_v, tet_f, extra=bad_scene)))

    def bad_view(doc):
        doc["accessors"][0]["bufferView"] = 42
    put(t, "accessor_view_missing.glb", glb(*gltf_mesh(tet_v, tet_f, extra=bad_view)))

    def huge_count(doc):
        doc["accessors"][1]["count"] = 4000000000
    put(t, "accessor_huge_count.glb", glb(*gltf_mesh(tet_v, tet_f, extra=huge_count)))

    def strided(doc):
        doc["bufferViews"][0]["byteStride"] = 16
    put(t, "view_stride_past_end.glb", glb(*gltf_mesh(tet_v, tet_f, extra=strided)))

    def view_past_end(doc):
        doc["bufferViews"][1]["byteLength"] = 1 << 30
    put(t, "view_past_buffer.glb", glb(*gltf_mesh(tet_v, tet_f, extra=view_past_end)))

    def sparse(doc):
        doc["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": 1,
                                                                 "componentType": 5125},
                                         "values": {"bufferView": 0}}
    put(t, "sparse_accessor.glb", glb(*gltf_mesh(tet_v, tet_f, extra=sparse)))

    def data_uri(doc):
        doc["buffers"].append({"byteLength": 3, "uri": "data:application/octet-stream;base64,"
                                                       "AAEC"})
    put(t, "second_buffer_data_uri.glb", glb(*gltf_mesh(tet_v, tet_f, extra=data_uri)))

    def file_uri(doc):
        doc["buffers"].append({"byteLength": 3, "uri": "/etc/passwd"})
    put(t, "second_buffer_file_uri.glb", glb(*gltf_mesh(tet_v, tet_f, extra=file_uri)))

    def out_of_range_index(doc):
        pass
    put(t, "index_out_of_range.glb", glb(*gltf_mesh(tet_v, [(0, 1, 9)])))
    doc, binary = gltf_mesh(tet_v, tet_f)
    put(t, "wrong_version.glb", glb(doc, binary, version=1))
    put(t, "declared_length_too_big.glb", glb(doc, binary, declared=1 << 30))
    put(t, "truncated.glb", glb(doc, binary)[:-20])
    put(t, "json_chunk_only.glb", glb(doc))
    # Conversion of a generated model, with its face colours as vertex colours of corners.
    vcol = [(128, 128, 128)] * len(verts)
    for f, c in zip(faces, colours):
        if c:
            for i in f:
                vcol[i] = c
    put(t, "gen_human.glb", glb(*gltf_mesh(verts, faces, colours=vcol)))


# ----------------------------------------------------------------------------------------------
# Text inputs


def weights_seeds():
    t = "fuzz_weights"
    for name, text in [
        ("preset_arg", "arg"), ("preset_mrg", "mrg"), ("preset_shape", "shape"),
        ("preset_colour", "colour"), ("preset_color", "color"),
        ("preset_then_pair", "shape lambda_4=0.1"),
        ("all_keys", "alpha_l=0.3 beta_l=0.15 gamma_l=0.15 delta_l=0.2 eps_l=0.2 alpha_s=0.65 "
                     "beta_s=0.35 lambda_1=0.3 lambda_2=1 lambda_3=3 lambda_4=1 norm=l1 tung=on"),
        ("commas", "alpha_l=1,beta_l=2,,norm=l2,tung=off"),
        ("tiny_subnormal", "alpha_s=1e-45 beta_s=1.4e-45"), ("max", "lambda_4=1e6"),
        ("over_max", "lambda_4=1000000.1"), ("negative_zero", "alpha_l=-0"),
        ("hex_float", "alpha_s=0x1.8p-3"), ("inf", "alpha_s=inf"), ("nan", "beta_s=nan"),
        ("overflow", "alpha_s=1e999999"), ("all_sim_zero",
                                          "alpha_s=0 beta_s=0 lambda_1=0 lambda_2=0 "
                                          "lambda_3=0 lambda_4=0"),
        ("unknown_key", "zeta=1"), ("missing_value", "alpha_s="), ("missing_key", "=1"),
        ("preset_not_first", "alpha_s=1 mrg"), ("bad_norm", "norm=l3"),
        ("whitespace", " \t\r\n"), ("empty", ""), ("nine_digits", "alpha_l=0.300000012"),
        ("leading_plus", "alpha_l=+.5e-1"), ("long", "alpha_s=1 " * 420),
        ("readable_names", "shape loss_area=0.3 loss_length=0.15 loss_radius=0.15 loss_theta=0.2 "
                           "loss_phi=0.2 area=0.65 length=0.35 volume=0.3 cords=1 curvature=3 "
                           "colour=1"),
        ("name_and_symbol", "curvature=2 lambda_3=3"), ("twice", "color=1,colour=1"),
    ]:
        put(t, name, text)


def build_options_seeds():
    t = "fuzz_build_options"
    for name, text in [
        ("defaults", "levels=5 mu=geodesic base_points=96 threads=1"),
        ("height", "mu=height levels=3"), ("centroid", "mu=centroid,base_points=8"),
        ("empty", ""), ("levels_zero", "levels=0"), ("levels_huge", "levels=99999999999999999999"),
        ("levels_plus", "levels=+3"), ("levels_hex", "levels=0x3"), ("bad_mu", "mu=random"),
        ("threads_max", "threads=256"), ("repeated", "levels=2 levels=7"),
        ("missing_value", "levels="), ("no_equals", "levels"), ("nul", "levels=3\0"),
        ("long", "threads=1 " * 420),
    ]:
        put(t, name, text)


def build_seeds():
    t = "fuzz_build"
    put(t, "tetrahedron.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
        "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")
    put(t, "single_triangle.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    put(t, "two_disjoint_triangles.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nv 6 5 5\n"
        "v 5 6 5\nf 1 2 3\nf 4 5 6\n")
    put(t, "all_points_equal.off", "OFF\n3 1 0\n1 1 1\n1 1 1\n1 1 1\n3 0 1 2\n")
    put(t, "collinear.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n")
    put(t, "flat_quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    put(t, "huge_coordinates.off", "OFF\n4 4 0\n0 0 0\n1e300 0 0\n0 1e300 0\n0 0 1e300\n"
        "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")
    put(t, "tiny_coordinates.off", "OFF\n4 4 0\n0 0 0\n1e-300 0 0\n0 1e-300 0\n0 0 1e-300\n"
        "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")
    put(t, "nonmanifold_fan.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n"
        "3 0 1 2\n3 0 1 3\n3 0 1 4\n")
    put(t, "duplicate_faces.off", "OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n3 2 1 0\n")


def arg_seeds():
    folder = os.path.join(GEN, "arg")
    values = {}
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), "rb") as f:
            values[name] = f.read()
    for name, data in values.items():
        put("fuzz_arg_binary", name, data)
        put("fuzz_arg_text", name + ".txt", b"arg1:" + base64.b64encode(data))
    some = next(iter(values.values()))
    put("fuzz_arg_binary", "empty", b"")
    put("fuzz_arg_binary", "magic_only", b"ARGR")
    put("fuzz_arg_binary", "header_truncated", some[:100])
    put("fuzz_arg_binary", "wrong_version", some[:4] + b"\x09\x00" + some[6:])
    put("fuzz_arg_text", "tag_only.txt", "arg1:")
    put("fuzz_arg_text", "future_tag.txt", "arg2:" + base64.b64encode(some).decode())
    put("fuzz_arg_text", "no_tag.txt", base64.b64encode(some).decode())
    put("fuzz_arg_text", "bad_padding.txt", "arg1:QUJD=")
    put("fuzz_arg_text", "non_canonical_padding.txt", "arg1:QR==")
    put("fuzz_arg_text", "whitespace.txt", "arg1: " + base64.b64encode(some).decode())

    # fuzz_arg_structure: byte 0 picks the base graph (bit 6: without colour; bit 7: refresh the
    # declared size), then patches [offset u16 LE][length u8][bytes].
    t = "fuzz_arg_structure"

    def patch(offset, data):
        return struct.pack("<HB", offset, len(data)) + data
    header = 4 + 2 + 2 + 4 + 4 + 8 + 4 + 4 + 4 + 4 + 28 + 4 * 9 + 4 * 48
    node = 2 + 2 + 4 * 5 + 4 * 8 + 4 * (8 + 16 + 24)
    for base in range(4):
        put(t, "base_%d" % base, bytes([base]))
        put(t, "base_%d" % (base + 4), bytes([0x40 | base]))
    put(t, "node0_level_1", b"\x00" + patch(header, b"\x01\x00"))
    put(t, "node1_parent_minus_1", b"\x01" + patch(header + node + 4, b"\xff\xff\xff\xff"))
    put(t, "node1_adjacency_huge", b"\x01" + patch(header + node + 20, b"\x00\x00\x00\x40"))
    put(t, "node2_adj_begin_far", b"\x01" + patch(header + 2 * node + 16,
                                                 b"\xff\xff\x00\x00\x05\x00\x00\x00"))
    put(t, "level_table", b"\x00" + patch(72, b"\x02\x00\x00\x00"))
    put(t, "node_count_plus_one_resized", b"\x80" + patch(28, b"\x02\x00\x00\x00") +
        struct.pack("<h", node // 4))
    put(t, "levels_7", b"\x00" + patch(24, b"\x07"))
    put(t, "area_nan", b"\x00" + patch(header + 24, b"\x00\x00\xc0\x7f"))
    put(t, "shrunk", b"\x80" + struct.pack("<h", -(node // 4)))


def main():
    verts, faces, colours = parse_off(generated("off", "human_00"))
    image_seeds()
    off_seeds()
    obj_seeds()
    ply_seeds(verts, faces, colours)
    stl_seeds(verts, faces)
    glb_seeds(verts, faces, colours)
    weights_seeds()
    build_options_seeds()
    build_seeds()
    arg_seeds()


main()
