#pragma once
// Line-by-line check of a Wavefront OBJ file before tinyobjloader reads it: tinyobjloader keeps no
// line numbers, resolves indices without range checks and parses `nan` as a number, so the errors
// a user can act on (which line, which value, what is allowed) have to come from here.
#include <filesystem>

namespace glintlab {

/// Throws InputError "FILE:LINE: ..." for a `v`/`vn`/`vt` value that is not a finite float, and
/// for an `f` index that is 0 or refers past the position, normal or uv lists (positive indices
/// against the whole file, negative ones against the lines before the face, as OBJ defines them),
/// and for an `mtllib` naming something that is not a regular file (a device or FIFO never ends).
void check_obj_statements(const std::filesystem::path& path);

}  // namespace glintlab
