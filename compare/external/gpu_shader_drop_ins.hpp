// A user's GLSL drop-ins (`groundtruth run --gpu-shaders DIR`): files laid over the built-in shader
// tree by their path relative to it (gpu/shader_program.hpp, set_shader_overlay), so that a variant
// of one pass is one file, graded in the GPU twin's place with everything else built-in. The
// interface a drop-in keeps (bindings, block members, passes) is docs/gpu-shader-drop-ins.md's; a
// block whose layout differs from the host's C++ mirror is an `error` naming the member, found by
// program interface queries when the program links (GlProgram::check_block).
//
// Inputs:  the folder, the built-in shader root.
// Outputs: the drop-ins' paths relative to the root, sorted.
// Throws:  InputError when the folder is not one, holds no file, or holds a file whose path names
//          no built-in shader (a typo would otherwise leave the built-in one running, unsaid).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gt {

std::vector<std::string> gpu_shader_drop_ins(const std::filesystem::path& folder, const std::filesystem::path& root);

}  // namespace gt
