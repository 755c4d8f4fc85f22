#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# bench/las_read.sh's helper (Debian's python3-numpy):
#   las_points.py write FILE N   N random points as LAS 1.4 point format 6 (classes 2, 5, 9)
#   las_points.py read FILE      reads every record with numpy, applies scale and offset
import struct
import sys

import numpy as np

RECORD = np.dtype([("x", "<i4"), ("y", "<i4"), ("z", "<i4"), ("intensity", "<u2"),
                   ("returns", "u1"), ("flags", "u1"), ("cls", "u1"), ("user", "u1"),
                   ("angle", "<i2"), ("source", "<u2"), ("gps", "<f8")])
HEADER = 375


def write(path, n):
    rng = np.random.default_rng(7)
    header = bytearray(HEADER)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 4
    struct.pack_into("<HIIBHI", header, 94, HEADER, HEADER, 0, 6, RECORD.itemsize, 0)
    struct.pack_into("<6d", header, 131, 0.001, 0.001, 0.001, -750000.0, -1050000.0, 0.0)
    struct.pack_into("<Q", header, 247, n)
    with open(path, "wb") as f:
        f.write(header)
        chunk = 1 << 22
        for start in range(0, n, chunk):
            m = min(chunk, n - start)
            r = np.zeros(m, RECORD)
            r["x"] = rng.integers(0, 2_000_000, m)
            r["y"] = rng.integers(0, 2_000_000, m)
            r["z"] = rng.integers(200_000, 350_000, m)
            r["returns"] = 0x11
            r["cls"] = rng.choice(np.array([2, 5, 9], np.uint8), m)
            f.write(r.tobytes())


def read(path):
    data = np.memmap(path, np.uint8, "r")
    offset = struct.unpack_from("<I", data, 96)[0]
    scale = struct.unpack_from("<3d", data, 131)
    origin = struct.unpack_from("<3d", data, 155)
    r = np.frombuffer(data, RECORD, offset=offset)
    xyz = np.empty((len(r), 3))
    xyz[:, 0] = r["x"] * scale[0] + origin[0]
    xyz[:, 1] = r["y"] * scale[1] + origin[1]
    xyz[:, 2] = r["z"] * scale[2] + origin[2]
    print(len(xyz), xyz[:, 2].min())


if __name__ == "__main__":
    if sys.argv[1] == "write":
        write(sys.argv[2], int(sys.argv[3]))
    else:
        read(sys.argv[2])
