// Every file groundtruth writes (fields, meshes, pictures, report pages, markers) is written under
// a temporary name in the target's folder and renamed into place, so that a failed write (a full
// disk, a file-size limit) leaves nothing behind and a reader never sees half a file.
//
//   write_file_atomically(file, write)
//     calls write(temporary) with ".<name>.<pid>.partial<extension>" beside `file` (the extension
//     kept, as OpenImageIO picks a format by it), then renames it to `file`. When `write` throws
//     or the rename fails the temporary is removed; the rename's failure becomes an InputError
//     "cannot write <file>: <reason>".
//
//   write_file_atomically(file, contents)
//     the same for bytes held in memory; a failed write or close (ENOSPC, EFBIG, EIO) is an
//     InputError "cannot write <file>: <the system's reason>" (the command exits 2), never a file
//     cut short.
//
//   write_image_atomically(file, spec, pixel_type, pixels)
//     encodes an image (the format by `file`'s extension, OpenImageIO) in memory, then writes its
//     bytes as above. OpenImageIO's PNG writer does not report a failed write to the disk (a full
//     disk left a truncated PNG and a success), so no image is encoded straight into a file.
//     `pixels` holds spec.width x spec.height x spec.nchannels values of `pixel_type`, converted to
//     spec.format.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

#include <OpenImageIO/imageio.h>

namespace gt {

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(const std::filesystem::path& temporary)>& write);

void write_file_atomically(const std::filesystem::path& file, std::string_view contents);

void write_image_atomically(const std::filesystem::path& file, const OIIO::ImageSpec& spec, OIIO::TypeDesc pixel_type,
                            const void* pixels);

}  // namespace gt
