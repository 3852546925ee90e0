#pragma once
// A look at an EXR file's headers before OpenEXR reads it. OpenEXR allocates what a header
// declares (an attribute of any size, an offset table for any image size) before it reads a
// byte of it, so a file of a hundred bytes can make it allocate gigabytes.
#include <filesystem>

namespace glintlab {

/// Throws InputError naming the file, the value and what is allowed when a header attribute
/// claims more bytes than the file holds, a data window exceeds kMaxImageSide / kMaxImagePixels
/// (core/image_io.hpp), or the pixel data claims more chunks than the file could list (each
/// chunk has an 8-byte entry in the offset table). Anything else is left to OpenEXR.
void check_exr_header(const std::filesystem::path& path);

}  // namespace glintlab
