#!/usr/bin/env python3
# Writes the seed corpus of the libFuzzer targets (run it in this folder; the output is committed).
# Every seed is a small valid file of its format, so that the fuzzers start from inputs that reach
# deep into each reader; images come from oiiotool (openimageio-tools), the rest is written here.
import json
import os
import struct
import subprocess
import zipfile


def put(target, name, data):
    os.makedirs(os.path.join("corpus", target), exist_ok=True)
    with open(os.path.join("corpus", target, name), "wb") as out:
        out.write(data if isinstance(data, bytes) else data.encode())


def image(target, name, data_type):
    os.makedirs(os.path.join("corpus", target), exist_ok=True)
    subprocess.run(["oiiotool", "--pattern", "fill:top=0:bottom=1", "6x5", "1", "-d", data_type,
                    "-o", os.path.join("corpus", target, name)], check=True)


def npy(descr, shape, payload):
    header = "{'descr': '%s', 'fortran_order': False, 'shape': %s, }" % (descr, shape)
    header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + payload


def npz(members):
    path = "corpus/heightmap_npz/tmp.npz"
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with zipfile.ZipFile(path, "w", zipfile.ZIP_STORED) as archive:
        for name, data in members.items():
            archive.writestr(name + ".npy", data)
    with open(path, "rb") as f:
        data = f.read()
    os.remove(path)
    return data


def f8(value):
    return npy("<f8", "()", struct.pack("<d", value))


# Heightmaps.
image("heightmap_png", "ramp16.png", "uint16")
image("heightmap_png", "ramp8.png", "uint8")
image("heightmap_tif", "ramp_float.tif", "float")
image("heightmap_tif", "ramp_int16.tif", "int16")
image("heightmap_exr", "ramp_half.exr", "half")
image("heightmap_exr", "ramp_float.exr", "float")
put("heightmap_json", "volcano.json", json.dumps({"width": 3, "height": 2, "values": [1, 2, 3, 4, None, 6]}))
put("heightmap_npz", "jacksboro.npz", npz({
    "elevation": npy("<i2", "(2, 3)", struct.pack("<6h", 1, 2, 3, 4, 5, 6)),
    "dx": f8(1 / 1200), "dy": f8(1 / 1200)}))
put("heightmap_npz", "topobathy.npz", npz({
    "topo": npy("<f4", "(2, 3)", struct.pack("<6f", 1, 2, 3, 4, 5, float("nan"))),
    "longitude": npy("<f8", "(3,)", struct.pack("<3d", 10, 10.01, 10.02)),
    "latitude": npy("<f8", "(2,)", struct.pack("<2d", 45, 45.01))}))

# Meshes: a tetrahedron in each format.
corners = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
put("mesh_off", "tetra.off", "OFF\n4 4 0\n" + "".join("%g %g %g\n" % c for c in corners)
    + "".join("3 %d %d %d\n" % f for f in faces))
put("mesh_off", "quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
put("mesh_obj", "tetra.obj", "".join("v %g %g %g\n" % c for c in corners)
    + "".join("f %d %d %d\n" % tuple(i + 1 for i in f) for f in faces) + "f -1 -2 -3\n")
ply_header = ("ply\nformat %s 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 4\nproperty list uchar int vertex_indices\nend_header\n")
put("mesh_ply", "tetra_ascii.ply", ply_header % "ascii" + "".join("%g %g %g\n" % c for c in corners)
    + "".join("3 %d %d %d\n" % f for f in faces))
put("mesh_ply", "tetra_binary.ply", (ply_header % "binary_little_endian").encode()
    + b"".join(struct.pack("<3f", *c) for c in corners) + b"".join(struct.pack("<B3i", 3, *f) for f in faces))
put("mesh_stl", "tetra_ascii.stl", "solid tetra\n" + "".join(
    "facet normal 0 0 0\nouter loop\n" + "".join("vertex %g %g %g\n" % corners[i] for i in f) + "endloop\nendfacet\n"
    for f in faces) + "endsolid tetra\n")
put("mesh_stl", "tetra_binary.stl", b"\0" * 80 + struct.pack("<I", len(faces)) + b"".join(
    struct.pack("<12fH", 0, 0, 0, *[v for i in f for v in corners[i]], 0) for f in faces))

# Volumes: a 3x3x2 .npy of each dtype.
for descr, code in (("<f4", "f"), ("<f8", "d"), ("<i2", "h"), ("<i4", "i")):
    put("volume_npy", "block_%s.npy" % descr[1:], npy(descr, "(2, 3, 3)", struct.pack("<18" + code, *range(-9, 9))))

# Heightmaps as .npy: a 3x4 grid of each dtype, the float ones with a NaN (no-data) cell.
for descr, code in (("<f4", "f"), ("<f8", "d"), ("<i2", "h"), ("<i4", "i")):
    values = [float("nan")] + list(range(11)) if code in "fd" else list(range(-6, 6))
    put("heightmap_npy", "grid_%s.npy" % descr[1:], npy(descr, "(3, 4)", struct.pack("<12" + code, *values)))

# Case files: one entry of each input kind.
put("cases", "cases.json", json.dumps([
    {"name": "fuzz.thermal.cone", "algorithm": "erosion.thermal", "params": {"iterations": 2},
     "input": {"generator": "cone", "width": 8, "height": 8, "noise": 0.1}, "crop": [1, 1, 4, 4]},
    {"name": "fuzz.thermal.volcano", "algorithm": "erosion.thermal", "input": {"file": "real/volcano.json"},
     "expect": {"cells": [[0, 0, 1.0]], "tolerance": 1e-12}},
    {"name": "fuzz.pipe.slope", "algorithm": "erosion.pipe", "input": {"generator": "slope", "width": 4, "height": 4}},
    {"name": "fuzz.cave", "algorithm": "cave.marching_tetrahedra", "params": {"size_x": 4, "size_y": 4, "size_z": 4}}]))

# Expectations: the format's every field.
put("expectations", "expectations.txt",
    "# comment\ncave.marching_cubes.* mesh.closed.cpu fail device=llvmpipe* holes in the seed's tables\n"
    "erosion.thermal.* parity.* pass known good\n")

# Global grids: a classic netCDF (CDF-1) file of a 3x4 ROSE(lat, lon) grid in float with its
# coordinate variables and a _FillValue, written byte by byte after the netCDF classic format
# specification (no netCDF tool needed).
def nc_name(name):
    data = name.encode()
    return struct.pack(">I", len(data)) + data + b"\0" * (-len(data) % 4)


def nc_global_grid():
    lat, lon = [-45.0, 0.0, 45.0], [0.0, 90.0, 180.0, 270.0]
    rose = [float(v) for v in range(-300, 900, 100)]
    rose[5] = -9999.0  # the fill value: no-data
    absent = b"\0" * 8
    fill_att = (struct.pack(">II", 0x0C, 1) + nc_name("_FillValue") + struct.pack(">II", 5, 1)
                + struct.pack(">f", -9999.0))
    variables = [("lat", [0], absent, 6, struct.pack(">3d", *lat)),
                 ("lon", [1], absent, 6, struct.pack(">4d", *lon)),
                 ("ROSE", [0, 1], fill_att, 5, struct.pack(">12f", *rose))]
    header = b"CDF\x01" + struct.pack(">I", 0)
    header += struct.pack(">II", 0x0A, 2) + nc_name("lat") + struct.pack(">I", 3) + nc_name("lon") + struct.pack(">I", 4)
    header += absent  # no global attributes
    entry_sizes = [len(nc_name(n)) + 4 + 4 * len(d) + len(a) + 4 + 4 + 4 for n, d, a, _, _ in variables]
    offset = len(header) + 8 + sum(entry_sizes)
    header += struct.pack(">II", 0x0B, len(variables))
    data = b""
    for name, dims, atts, nc_type, payload in variables:
        header += nc_name(name) + struct.pack(">I", len(dims)) + b"".join(struct.pack(">I", d) for d in dims)
        header += atts + struct.pack(">III", nc_type, len(payload), offset + len(data))
        data += payload
    return header + data


put("global_grid", "etopo_like.nc", nc_global_grid())

# Reports: a small report.json of each shape the readers meet (a passing case, a failing one with
# expectations, a shard).
report_case = {"name": "erosion.thermal.spec.example_3x3", "algorithm": "erosion.thermal", "status": "pass",
               "checks": [{"name": "spec.cells.cpu", "status": "pass", "value": 0.0, "bound": 0.0, "detail": "x"}],
               "timing": {"cpu_ms": 1.5, "gpu_ms": 0.5}}
put("report", "report.json", json.dumps({"schema": 1, "environment": {"command_line": "groundtruth run"},
                                          "cases": [report_case]}))
put("report", "shard.json", json.dumps({"schema": 1, "shard": {"index": 1, "count": 2, "selection": [report_case["name"]]},
                                         "cases": [dict(report_case, status="fail", expected="a known fail")]}))
