// The drop-in shader folder, checked against the built-in tree; see gpu_shader_drop_ins.hpp.
#include "compare/external/gpu_shader_drop_ins.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"

namespace gt {

std::vector<std::string> gpu_shader_drop_ins(const std::filesystem::path& folder, const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw InputError(fmt::format("--gpu-shaders {}: not a folder (lay your shader files out as gpu/shaders/ is: "
                                 "erosion/thermal_transfer.comp, ...)",
                                 folder.string()));
  }
  constexpr std::size_t most_files = 10000;
  std::vector<std::string> drop_ins, unknown;
  for (auto entry = fs::recursive_directory_iterator(folder, error); !error && entry != fs::recursive_directory_iterator();
       entry.increment(error)) {
    if (!entry->is_regular_file(error)) continue;
    const std::string relative = fs::relative(entry->path(), folder).generic_string();
    (fs::is_regular_file(root / relative, error) ? drop_ins : unknown).push_back(relative);
    if (drop_ins.size() + unknown.size() > most_files) {
      throw InputError(fmt::format("--gpu-shaders {}: more than {} files", folder.string(), most_files));
    }
  }
  if (error) throw InputError(fmt::format("--gpu-shaders {}: cannot be read: {}", folder.string(), error.message()));
  if (!unknown.empty()) {
    std::sort(unknown.begin(), unknown.end());
    throw InputError(fmt::format("--gpu-shaders {}: {} name no built-in shader (paths are relative to {}, e.g. "
                                 "erosion/thermal_transfer.comp)",
                                 folder.string(), fmt::join(unknown, ", "), root.string()));
  }
  if (drop_ins.empty()) throw InputError(fmt::format("--gpu-shaders {}: no shader file in it", folder.string()));
  std::sort(drop_ins.begin(), drop_ins.end());
  return drop_ins;
}

}  // namespace gt
