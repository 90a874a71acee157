// Reading a scalar volume from a file: what the cave mesher meshes when the field is not the
// seed's noise (issue 5, "any scalar volume read from a file"); and writing one, as read_volume
// reads it back (the cave's density as a field, issue 19).
//
//   Volume<double> read_volume(const std::filesystem::path& path)
//   void write_volume(const Volume<double>& volume, const std::filesystem::path& path)
//
// Inputs
//   path  a NumPy .npy file (format version 1, 2 or 3) holding one 3-D array of dtype '<f4',
//         '<f8', '<i2' or '<i4' in C order with shape (nz, ny, nx): the array indexed [z, y, x],
//         as numpy.save writes it, so that x varies fastest.
// Outputs
//   The volume: nx, ny, nz from the shape, value(x, y, z) = array[z, y, x] at index
//   (z·ny + y)·nx + x (core/volume.hpp), every sample converted to double exactly. origin (0, 0, 0)
//   and spacing 1: a .npy file holds no placement, the caller sets it.
// Conventions and refusals
//   Throws gt::InputError, its message naming the file and the reason, for: a missing or
//   unreadable file; content that is not .npy (no magic); an unsupported format version or dtype;
//   Fortran order; an array that is not 3-D; an axis of fewer than 2 samples ("empty volume": a
//   volume needs 2 samples per axis to hold a cube); more than 2^28 samples (2 GiB of doubles, too
//   large for memory); a file whose size is not the header's promise (truncated, or trailing
//   bytes); a NaN or infinite sample (the message gives the first one's (x, y, z)). Sizes are
//   checked against the shape and the file's size before anything is allocated.
//
// write_volume writes a .npy file of float32 '<f4' with shape (nz, ny, nx) (the placement is not
// stored), under a temporary name renamed into place; InputError when the file cannot be written
// or the volume holds fewer values than nx·ny·nz.
#pragma once

#include <filesystem>

#include "core/volume.hpp"

namespace gt {

Volume<double> read_volume(const std::filesystem::path& path);

void write_volume(const Volume<double>& volume, const std::filesystem::path& path);

}  // namespace gt
