#!/usr/bin/env python3
"""Time VTK's isosurface filters on a volume: the peers of cave.marching_tetrahedra's timings.

Usage: vtk_isosurface.py VOLUME.npy THRESHOLD REPS OUT.json

VOLUME.npy holds float32 samples of shape (nz, ny, nx) (core/io/volume_io.hpp's layout: x
fastest, which is VTK's point order). Each filter (vtkFlyingEdges3D, vtkMarchingCubes) extracts
the THRESHOLD isosurface without normals, gradients or scalars, once to warm up and then REPS
times; VTK's SMP tools run sequentially (one thread, as our CPU reference). OUT.json gets
{"vtk_version": ..., "filters": [{"name", "ms": [...], "triangles"}]}. Exits 3 with a one-line
reason when VTK or numpy cannot be imported, 2 on bad arguments.
"""
import json
import sys
import time


def run(volume_path, threshold, reps, out_path):
    import numpy
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkSMPTools, vtkVersion
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D, vtkMarchingCubes

    vtkSMPTools.SetBackend("Sequential")
    samples = numpy.load(volume_path)
    if samples.ndim != 3:
        raise ValueError(f"{volume_path}: expected a 3-D array, got shape {samples.shape}")
    nz, ny, nx = samples.shape
    image = vtkImageData()
    image.SetDimensions(nx, ny, nz)
    scalars = numpy_to_vtk(numpy.ascontiguousarray(samples).ravel(), deep=1)
    scalars.SetName("density")
    image.GetPointData().SetScalars(scalars)

    filters = []
    for make in (vtkFlyingEdges3D, vtkMarchingCubes):
        extractor = make()
        extractor.SetInputData(image)
        extractor.SetValue(0, threshold)
        extractor.ComputeNormalsOff()
        extractor.ComputeGradientsOff()
        extractor.ComputeScalarsOff()
        extractor.Update()  # warm-up
        times = []
        for _ in range(reps):
            extractor.Modified()
            start = time.perf_counter()
            extractor.Update()
            times.append((time.perf_counter() - start) * 1e3)
        filters.append({"name": make.__name__, "ms": times,
                        "triangles": extractor.GetOutput().GetNumberOfPolys()})
    with open(out_path, "w", encoding="utf-8") as out:
        json.dump({"vtk_version": vtkVersion.GetVTKVersion(), "filters": filters}, out)


def main(argv):
    if len(argv) != 5:
        print("usage: vtk_isosurface.py VOLUME.npy THRESHOLD REPS OUT.json", file=sys.stderr)
        return 2
    try:
        import numpy  # noqa: F401
        import vtkmodules  # noqa: F401
    except ImportError as error:
        print(f"VTK's Python modules are not installed (Debian python3-vtk9): {error}")
        return 3
    try:
        threshold = float(argv[2])
        reps = int(argv[3])
    except ValueError:
        print(f"bad THRESHOLD or REPS: {argv[2]!r} {argv[3]!r}")
        return 2
    if reps < 1:
        print("REPS must be at least 1")
        return 2
    run(argv[1], threshold, reps, argv[4])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
