"""Makes the example candidates of this folder with the built command line, as a user's own mesher
and renderer would hand theirs in (`groundtruth run CASE --candidate FILE`):

  solid8_float.obj      cave.marching_tetrahedra.mutant_probe.solid8 meshed by the reference, its
                        positions rounded to float and written with 9 significant digits: what a
                        float mesher writes; passes
  solid8_flipped.obj    the same with its first triangle's corners swapped: fails mesh.oriented
  quad_gl.png           render.phong.mutant_probe.quad drawn by the GL pipeline (llvmpipe); passes
  quad_bright_patch.png the same with a 12 x 12 patch 40 levels brighter in the middle: fails the
                        image share and the quad's closed form

Run from the root of the checkout: /usr/bin/python3 examples/candidates/make_examples.py
[build/release/groundtruth]. The README's tutorial grades them (python/tests/test_readme_tutorial.py)."""

import pathlib
import subprocess
import sys
import tempfile

import matplotlib.image
import numpy

HERE = pathlib.Path(__file__).resolve().parent
CLI = sys.argv[1] if len(sys.argv) > 1 else "build/release/groundtruth"


def run(*args):
    subprocess.run([CLI, *args, "--quiet"], check=True)


def read_obj(path):
    vertices, faces = [], []
    for line in pathlib.Path(path).read_text().splitlines():
        words = line.split()
        if words and words[0] == "v":
            vertices.append([float(w) for w in words[1:4]])
        elif words and words[0] == "f":
            faces.append([int(w.split("/")[0]) for w in words[1:4]])
    return numpy.array(vertices), faces


def write_obj(path, vertices, faces, comment):
    lines = [f"# {comment}"]
    lines += ["v " + " ".join(f"{c:.9g}" for c in v) for v in vertices]
    lines += ["f " + " ".join(str(i) for i in f) for f in faces]
    pathlib.Path(path).write_text("\n".join(lines) + "\n")


def meshes(scratch):
    out = scratch / "mesh"
    run("run", "--algorithm", "cave.marching_tetrahedra", "--set", "size_x=8", "--set", "size_y=8", "--set", "size_z=8",
        "--set", "solid=true", "--set", "mesh_format=obj", "--backend", "cpu", "--out", str(out))
    vertices, faces = read_obj(next(out.glob("*/mesh.cpu.obj")))
    vertices = vertices.astype(numpy.float32).astype(numpy.float64)
    write_obj(HERE / "solid8_float.obj", vertices, faces, "the reference's mesh of solid8, positions rounded to float")
    faces[0] = [faces[0][0], faces[0][2], faces[0][1]]
    write_obj(HERE / "solid8_flipped.obj", vertices, faces, "solid8_float.obj with its first triangle flipped")


def images(scratch):
    out = scratch / "image"
    run("run", "render.phong.mutant_probe.quad", "--out", str(out))
    gl = matplotlib.image.imread(out / "render.phong.mutant_probe.quad" / "gpu.png")[:, :, :3]
    matplotlib.image.imsave(HERE / "quad_gl.png", gl)
    levels = numpy.round(gl * 255.0)
    levels[26:38, 26:38] = numpy.minimum(levels[26:38, 26:38] + 40, 255)
    matplotlib.image.imsave(HERE / "quad_bright_patch.png", (levels / 255.0).astype(numpy.float32))


with tempfile.TemporaryDirectory() as folder:
    meshes(pathlib.Path(folder))
    images(pathlib.Path(folder))
