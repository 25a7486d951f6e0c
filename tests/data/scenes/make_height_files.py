#!/usr/bin/env python3
"""Writes the small height files the scene tests use (no NumPy needed).

good/heights_16x8.npy: float64, 8 rows (y) x 16 columns (x), h = 0.01 + 0.001 i + 0.002 j
good/heights_16x8.png: 16-bit grey, value 1000 i + 100 j; the image's top row is the largest y
bad/heights_5x5.npy:   float64, 5 x 5 zeros (the wrong shape for bad/npy_wrong_shape.yaml)
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write_npy(path, rows):
    ny, nx = len(rows), len(rows[0])
    header = "{'descr': '<f8', 'fortran_order': False, 'shape': (%d, %d), }" % (ny, nx)
    total = 10 + len(header) + 1
    header += " " * ((64 - total % 64) % 64) + "\n"
    with open(path, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode("latin1"))
        for row in rows:
            f.write(struct.pack("<%dd" % nx, *row))


def write_png16(path, rows_top_first):
    ny, nx = len(rows_top_first), len(rows_top_first[0])
    raw = b"".join(b"\x00" + struct.pack(">%dH" % nx, *row) for row in rows_top_first)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", nx, ny, 16, 0, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw)))
        f.write(chunk(b"IEND", b""))


nx, ny = 16, 8
write_npy(os.path.join(HERE, "good", "heights_16x8.npy"),
          [[0.01 + 0.001 * i + 0.002 * j for i in range(nx)] for j in range(ny)])
write_png16(os.path.join(HERE, "good", "heights_16x8.png"),
            [[1000 * i + 100 * j for i in range(nx)] for j in reversed(range(ny))])
write_npy(os.path.join(HERE, "bad", "heights_5x5.npy"), [[0.0] * 5 for _ in range(5)])
