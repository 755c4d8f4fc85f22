#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# An independent LAS reader for the tests (struct, no dtm code): prints one JSON object with the
# header's version, point format and count on the first line, then one line per point record:
# x y z (scale and offset applied, Python's shortest round-trip repr), classification, withheld
# (0/1). Usage: las_oracle.py FILE
import struct
import sys

data = open(sys.argv[1], "rb").read()
assert data[:4] == b"LASF"
major, minor = data[24], data[25]
header_size, point_offset = struct.unpack_from("<HI", data, 94)
fmt = data[104] & 0x3F
length = struct.unpack_from("<H", data, 105)[0]
count = struct.unpack_from("<I", data, 107)[0]
if minor >= 4:
    count = struct.unpack_from("<Q", data, 247)[0] or count
scale = struct.unpack_from("<3d", data, 131)
offset = struct.unpack_from("<3d", data, 155)
lines = []
for i in range(count):
    at = point_offset + i * length
    x, y, z = struct.unpack_from("<3i", data, at)
    flags = data[at + 15]
    if fmt >= 6:
        cls, withheld = data[at + 16], bool(flags & 0x04)
    else:
        cls, withheld = flags & 0x1F, bool(flags & 0x80)
    lines.append(f"{x * scale[0] + offset[0]!r} {y * scale[1] + offset[1]!r} "
                 f"{z * scale[2] + offset[2]!r} {cls} {int(withheld)}")
print(f"{major}.{minor} {fmt} {count}")
print("\n".join(lines))
