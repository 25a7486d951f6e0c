#!/usr/bin/env python3
"""Writes the malformed-input corpus (tests/malformed/files/) and one small
scene per file (tests/malformed/*.yaml) that uses it as its initial height
file or as a mesh object, so that `repose check`, `repose run` and, for .npy
files, `repose render` read it end to end. No NumPy needed: every byte is
written here on purpose.

Each scene's first line is `# expect: FRAGMENT`, a piece of the one-line error
the parser must give (tests/experiments/malformed_inputs_test.cpp checks it,
together with the exit code 2, the scene's FILE:LINE:COL, the data file's
name and an untouched output folder).

Run it again after changing a case: python3 tests/malformed/make_malformed.py
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
FILES = os.path.join(HERE, "files")


# ---- .npy ---------------------------------------------------------------

def npy_header(descr, shape, fortran=False, version=(1, 0), raw_dict=None):
    text = raw_dict if raw_dict is not None else "{'descr': '%s', 'fortran_order': %s, 'shape': %s, }" % (
        descr, "True" if fortran else "False", shape)
    total = 10 + len(text) + 1
    text += " " * ((64 - total % 64) % 64) + "\n"
    return b"\x93NUMPY" + bytes(version) + struct.pack("<H", len(text)) + text.encode("latin1")


def f8(values):
    return struct.pack("<%dd" % len(values), *values)


NPY = {
    # name: (bytes, expected fragment)
    "npy_empty.npy": (b"", "truncated: the magic and version needs 8 bytes"),
    "npy_text.npy": (b"this is not a NumPy array\n", "not a .npy file (bad magic)"),
    "npy_bad_magic.npy": (b"\x93NUMPX" + npy_header("<f8", "(2, 2)")[6:] + f8([0.0] * 4), "not a .npy file (bad magic)"),
    "npy_bad_version.npy": (npy_header("<f8", "(2, 2)", version=(9, 0)) + f8([0.0] * 4), "unsupported .npy format version 9.0"),
    "npy_truncated_header.npy": (npy_header("<f8", "(2, 2)")[:30], "truncated header"),
    "npy_truncated_data.npy": (npy_header("<f8", "(4, 4)") + f8([0.0] * 5), "truncated: shape (4, 4) needs 128 bytes"),
    "npy_header_not_dict.npy": (npy_header("", "", raw_dict="[1, 2, 3]") + f8([0.0] * 3), "bad .npy header: expected '{'"),
    "npy_missing_descr.npy": (npy_header("", "", raw_dict="{'fortran_order': False, 'shape': (2, 2), }") +
                              f8([0.0] * 4), "no 'descr' key"),
    "npy_int64.npy": (npy_header("<i8", "(2, 2)") + struct.pack("<4q", 1, 2, 3, 4), "unsupported dtype '<i8'"),
    "npy_complex.npy": (npy_header("<c16", "(2, 2)") + f8([0.0] * 8), "unsupported dtype '<c16'"),
    "npy_big_endian.npy": (npy_header(">f8", "(2, 2)") + struct.pack(">4d", 0, 0, 0, 0), "big-endian dtype '>f8' is not supported"),
    "npy_object.npy": (npy_header("|O", "(2, 2)") + b"\x00" * 32, "unsupported dtype '|O'"),
    "npy_3d.npy": (npy_header("<f8", "(2, 2, 2)") + f8([0.0] * 8), "expected a 1-D or 2-D array, got 3-D"),
    "npy_0d.npy": (npy_header("<f8", "()") + f8([0.0]), "expected a 1-D or 2-D array, got 0-D"),
    "npy_huge_shape.npy": (npy_header("<f8", "(1000000000, 1000000000)") + f8([0.0] * 4), "is too large"),
    "npy_overflow_shape.npy": (npy_header("<f8", "(4611686018427387904, 8)") + f8([0.0] * 4), "is too large"),
    "npy_negative_shape.npy": (npy_header("<f8", "(-2, 2)") + f8([0.0] * 4), "expected a non-negative integer in 'shape'"),
    "npy_nan.npy": (npy_header("<f8", "(4, 4)") + f8([0.01] * 7 + [float("nan")] + [0.01] * 8), "finite"),
    "npy_infinite.npy": (npy_header("<f8", "(4, 4)") + f8([0.01] * 15 + [float("inf")]), "finite"),
}


# ---- .png ---------------------------------------------------------------

def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(width, height, bit_depth, colour_type, raw_rows, ihdr_override=None):
    ihdr = ihdr_override or struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", zlib.compress(raw_rows)) +
            png_chunk(b"IEND", b""))


def grey16_rows(nx, ny):
    return b"".join(b"\x00" + struct.pack(">%dH" % nx, *([1000] * nx)) for _ in range(ny))


GOOD_PNG = png(4, 4, 16, 0, grey16_rows(4, 4))
PNG_BAD_CRC = bytearray(GOOD_PNG)
PNG_BAD_CRC[8 + 8 + 13] ^= 0xFF  # the IHDR chunk's CRC

PNG = {
    "png_empty.png": (b"", "not a PNG file (bad signature)"),
    "png_text.png": (b"not an image at all\n", "not a PNG file (bad signature)"),
    "png_wrong_magic.png": (b"\x89PNX\r\n\x1a\n" + GOOD_PNG[8:], "not a PNG file (bad signature)"),
    "png_truncated.png": (GOOD_PNG[:45], "truncated PNG"),
    "png_bad_crc.png": (bytes(PNG_BAD_CRC), "CRC error"),
    "png_rgb.png": (png(4, 4, 8, 2, b"".join(b"\x00" + b"\x10\x20\x30" * 4 for _ in range(4))), "PNG colour type is RGB"),
    "png_palette.png": (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", struct.pack(">IIBBBBB", 4, 4, 8, 3, 0, 0, 0)) +
                        png_chunk(b"PLTE", b"\x00\x00\x00\xff\xff\xff") +
                        png_chunk(b"IDAT", zlib.compress(b"\x00\x00\x01\x00\x01" * 4)) + png_chunk(b"IEND", b""),
                        "PNG colour type is palette"),
    "png_zero_width.png": (png(0, 4, 16, 0, b"\x00" * 4), "Invalid IHDR data"),
    # 100000 x 100000 16-bit pixels would need 20 GB: must be refused, not allocated
    "png_huge.png": (png(100000, 100000, 16, 0, b"\x00" * 16), "100000 x 100000"),
    # within the pixel limit, but 16384^2 for a 4 x 4 grid: refused from the header (the
    # loader gives the expected size) or by the memory budget (2.5 GB to decode), never
    # decoded; a few rows of data are enough for the header to be believed
    "png_header_larger_than_grid.png": (png(16384, 16384, 16, 0, b"\x00" * 4 * (1 + 2 * 16384)), "16384 x 16384"),
}


# ---- meshes -------------------------------------------------------------

CUBE_V = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
CUBE_F = "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"


def stl_binary(triangles, count=None):
    body = b"".join(struct.pack("<12fH", 0, 0, 0, *[c for v in t for c in v], 0) for t in triangles)
    return b"repose malformed".ljust(80, b" ") + struct.pack("<I", len(triangles) if count is None else count) + body


TETRA = [((0, 0, 0), (0, 1, 0), (1, 0, 0)), ((0, 0, 0), (1, 0, 0), (0, 0, 1)),
         ((0, 0, 0), (0, 0, 1), (0, 1, 0)), ((1, 0, 0), (0, 1, 0), (0, 0, 1))]

MESH = {
    "obj_binary_garbage.obj": (bytes(range(256)) * 4, "binary data: not an OBJ file"),
    "obj_nan_vertex.obj": ((CUBE_V.replace("v 1 1 1", "v 1 nan 1") + CUBE_F).encode(), "obj:7: non-finite coordinate"),
    "obj_inf_vertex.obj": ((CUBE_V.replace("v 0 0 1", "v 0 0 inf") + CUBE_F).encode(), "obj:5: non-finite coordinate"),
    "obj_bad_number.obj": ((CUBE_V.replace("v 1 0 0", "v 1 zero 0") + CUBE_F).encode(), "obj:2: 'zero' is not a number"),
    "obj_index_out_of_range.obj": ((CUBE_V + CUBE_F.replace("f 5 6 7 8", "f 5 6 7 9")).encode(), "obj:10: face index 9 out of range"),
    "obj_index_zero.obj": ((CUBE_V + CUBE_F.replace("f 1 4 3 2", "f 0 4 3 2")).encode(), "obj:9: face index 0 out of range"),
    "obj_face_two_vertices.obj": ((CUBE_V + "f 1 2\n" + CUBE_F).encode(), "obj:9: a face needs at least 3 vertices"),
    "obj_unknown_statement.obj": ((CUBE_V + "frobnicate 1 2 3\n" + CUBE_F).encode(), "obj:9: unknown OBJ statement"),
    "stl_empty.stl": (b"", "not an STL file (0 bytes"),
    "stl_truncated_binary.stl": (stl_binary(TETRA, count=12), "truncated or corrupt binary STL: header says 12 triangles"),
    "stl_huge_count.stl": (stl_binary(TETRA, count=0xFFFFFFFF), "truncated or corrupt binary STL: header says 4294967295 triangles"),
    "stl_nan_binary.stl": (stl_binary(TETRA[:3] + [((1, 0, 0), (0, float("nan"), 0), (0, 0, 1))]), "triangle 4: non-finite coordinate"),
    "stl_ascii_truncated.stl": (b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n", "truncated ASCII STL (no 'endsolid')"),
    "stl_ascii_bad_number.stl": (b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 x\n"
                                 b"vertex 0 1 0\nendloop\nendfacet\nendsolid t\n", "stl:5: 'x' is not a number"),
}

SCENE_HEAD = "time: {step_s: 0.1, duration_s: 0.2}\n"


def height_scene(name, expect):
    return ("# expect: %s\n" % expect + SCENE_HEAD + "ground:\n  extent_m: [0.04, 0.04]\n  resolution: [4, 4]\n"
            "  initial_height: {kind: file, path: files/%s%s}\n" %
            (name, ", height_scale_m: 0.1" if name.endswith(".png") else ""))


def mesh_scene(name, expect):
    return ("# expect: %s\n" % expect + SCENE_HEAD + "ground:\n  extent_m: [0.4, 0.4]\n  cell_size_m: 0.01\n"
            "  initial_height: {kind: flat, height_m: 0.05}\nobjects:\n  - name: thing\n    shape: mesh\n"
            "    mesh: files/%s\n    scale: 0.1\n    motion:\n      - {time_s: 0, position_m: [0, 0, 0.1]}\n" % name)


def write(path, data):
    with open(path, "wb") as f:
        f.write(data)


def main():
    os.makedirs(FILES, exist_ok=True)
    for table, scene in ((NPY, height_scene), (PNG, height_scene), (MESH, mesh_scene)):
        for name, (data, expect) in table.items():
            write(os.path.join(FILES, name), data)
            write(os.path.join(HERE, os.path.splitext(name)[0] + ".yaml"), scene(name, expect).encode())
    # paths that name directories (git keeps a directory by a file inside it)
    for name, scene, expect in (("directory.npy", height_scene, "is a directory"),
                                ("directory.obj", mesh_scene, "which is a directory")):
        os.makedirs(os.path.join(FILES, name), exist_ok=True)
        write(os.path.join(FILES, name, "README"), b"A directory named like a data file, for the malformed corpus.\n")
        write(os.path.join(HERE, os.path.splitext(name)[1][1:] + "_is_directory.yaml"), scene(name, expect).encode())


if __name__ == "__main__":
    main()
