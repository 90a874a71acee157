// Internal to core/io: every file writer of core/io writes under a temporary name in the target's
// folder and renames it into place, so that a failed write leaves nothing, and a reader never
// sees half a file.
//
//   write_file_atomically(file, write)
//     calls write(temporary) with ".<name>.<pid>.partial<extension>" beside `file` (the extension
//     kept, as OpenImageIO picks a format by it), then renames it to `file`. When `write` throws
//     or the rename fails the temporary is removed; the rename's failure becomes an InputError
//     "cannot write <file>: <reason>".
#pragma once

#include <filesystem>
#include <functional>

namespace gt::detail {

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace gt::detail
