#pragma once
// Reading and writing image files. Writes are atomic: the data goes to a
// temporary file beside the target, renamed into place only when complete, so
// a failure never leaves a partial file.
#include <string>

#include "image/image.h"

namespace penumbra::image {

enum class FileFormat { Exr, Png };

// From the extension (.exr, .png; case-insensitive); penumbra::Error otherwise.
FileFormat formatFromPath(const std::string& path);

// Fails early (penumbra::Error) if `path` cannot be written: unknown
// extension, missing directory, no permission. Leaves nothing behind.
void checkWritable(const std::string& path);

// Linear float RGB(A) as OpenEXR (32-bit float channels, ZIP compressed).
void saveExr(const std::string& path, const Image& image);
Image loadExr(const std::string& path);
// 8-bit sRGB-encoded RGBA as PNG.
void savePng(const std::string& path, const Image8& image);

}  // namespace penumbra::image
