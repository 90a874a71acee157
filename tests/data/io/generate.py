#!/usr/bin/env python3
# Writes the small malformed or synthetic inputs that tests/heightmap_io_test.cpp reads (run it in
# this folder). .npy arrays are written by hand (format version 1) so that numpy is not needed.
import json
import struct
import zipfile


def npy(descr, shape, payload, fortran=False):
    header = "{'descr': '%s', 'fortran_order': %s, 'shape': %s, }" % (descr, fortran, shape)
    header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + payload


def f8(value):
    return npy("<f8", "()", struct.pack("<d", value))


def npz(name, members):
    with zipfile.ZipFile(name, "w", zipfile.ZIP_DEFLATED) as archive:
        for key, data in members.items():
            archive.writestr(key + ".npy", data)


elevation = npy("<i2", "(2, 3)", struct.pack("<6h", 1, 2, 3, 4, 5, 6))
# jacksboro layout without 'dx'
npz("jacksboro_missing_dx.npz", {"elevation": elevation, "dy": f8(1 / 1200), "ymin": f8(36.7), "ymax": f8(36.4)})
# 'elevation' stored as uint8 (unsupported dtype)
npz("elevation_uint8.npz", {"elevation": npy("|u1", "(2, 3)", bytes(6))})
# 'elevation' in Fortran order (unsupported)
npz("elevation_fortran.npz", {"elevation": npy("<i2", "(2, 3)", bytes(12), fortran=True)})
# topobathy layout, 3 x 2 cells, one NaN
npz("topobathy_nan.npz", {
    "topo": npy("<f4", "(2, 3)", struct.pack("<6f", -10, 0, 5, float("nan"), 20, 30)),
    "longitude": npy("<f4", "(3,)", struct.pack("<3f", 234.0, 234.5, 235.0)),
    "latitude": npy("<f4", "(2,)", struct.pack("<2f", 48.0, 48.5)),
})
# volcano layout with 5 values for 3 x 2 cells
with open("volcano_wrong_count.json", "w") as out:
    json.dump({"width": 3, "height": 2, "values": [1, 2, 3, 4, 5]}, out)


def truncated_tiff(name, width=4, height=4):
    """Little-endian int16 TIFF, directory first, whose single strip is cut off after 10 bytes."""
    entries = [  # tag, type (3 SHORT, 4 LONG), value
        (256, 3, width), (257, 3, height), (258, 3, 16), (259, 3, 1), (262, 3, 1),
        (273, 4, 0), (277, 3, 1), (278, 3, height), (279, 4, width * height * 2), (339, 3, 2),
    ]
    strip_offset = 8 + 2 + 12 * len(entries) + 4
    directory = struct.pack("<H", len(entries))
    for tag, kind, value in entries:
        value = strip_offset if tag == 273 else value
        directory += struct.pack("<HHI", tag, kind, 1) + (struct.pack("<HH", value, 0) if kind == 3 else struct.pack("<I", value))
    with open(name, "wb") as out:
        out.write(b"II*\x00" + struct.pack("<I", 8) + directory + struct.pack("<I", 0) + bytes(10))


truncated_tiff("truncated_strip.tif")
