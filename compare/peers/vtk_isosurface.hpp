// VTK's isosurface filters (vtkFlyingEdges3D, vtkMarchingCubes) as peers of the cave mesher,
// driven through Debian's python3-vtk9 by compare/peers/vtk_isosurface.py rather than linked:
// libvtk9-dev would pull a JDK, MPI and Qt into the build for two filters, while the Python
// package is a runtime dependency only and its filters run in VTK's C++ all the same (the script
// times Update() alone, sequential SMP back end: one thread).
//
// run_vtk_isosurface(density, threshold, reps) -> for each filter: its name, `reps` times in ms
//   after one warm-up, and the triangles it made. The volume goes to the script as a float32 .npy
//   in a temporary folder, removed afterwards. Throws std::runtime_error saying why when no
//   Python with VTK was found at configure time or the script fails.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/volume.hpp"

namespace gt {

struct IsosurfacePeerRun {
  std::string name;  // "VTK 9.1.0 vtkFlyingEdges3D (float32, 1 thread)"
  std::vector<double> ms;
  std::size_t triangles = 0;
};

std::vector<IsosurfacePeerRun> run_vtk_isosurface(const Volume<double>& density, double threshold, int reps);

}  // namespace gt
