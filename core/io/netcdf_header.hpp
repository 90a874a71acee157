// Internal to core/io: the header of a classic netCDF file (CDF-1, the 64-bit-offset CDF-2 and
// CDF-5) walked with every count checked against the bytes that are there, before libnetcdf opens
// the file. libnetcdf allocates what a header declares: a 96-byte file declaring 2^31 variables
// crashed inside nc_open, and 2^31 dimensions or a 2 GB attribute exhausted memory. It also reads a
// truncated file without complaint and fills the missing data with the fill value.
//
//   void check_netcdf_header(path)
//     Inputs: a file. Files that are not classic netCDF (HDF5-based netCDF-4, anything else) are
//     left to libnetcdf.
//     Throws InputError naming the file when a count (dimensions, attributes, variables, the
//     characters of a name, the values of an attribute, a variable's dimensions) needs more bytes
//     than the file holds after it, when the header is larger than 16 MiB, when a dimension id is
//     out of range, or when a fixed-size variable's data ends beyond the end of the file
//     (truncated). Follows the format description of the netCDF Users Guide ("The NetCDF Binary
//     Format"): big-endian, 4-byte counts (8 in CDF-5), names and values padded to 4 bytes.
#pragma once

#include <filesystem>

namespace gt::detail {

void check_netcdf_header(const std::filesystem::path& file);

}  // namespace gt::detail
