#pragma once
// Reading and writing image files. Writes are atomic: the data goes to a
// temporary file beside the target, renamed into place only when complete, so
// a failure never leaves a partial file.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/image/image.h"

namespace penumbra::image {

enum class FileFormat { Exr, Png };

// A path's extension in lower case, with its dot (".exr"; "" without one).
std::string lowerExtension(const std::string& path);

// From the extension (.exr, .png; case-insensitive); penumbra::Error otherwise.
FileFormat formatFromPath(const std::string& path);

// Fails early (penumbra::Error) if `path` cannot be written: unknown
// extension, missing directory, no permission. Leaves nothing behind.
void checkWritable(const std::string& path);

// Linear float RGB(A) as OpenEXR (32-bit float channels, ZIP compressed).
void saveExr(const std::string& path, const Image& image);
Image loadExr(const std::string& path);
// What loadExr and loadExrChannels decode at most, checked on the header
// before anything is allocated: tinyexr allocates what the data window
// declares whatever the file holds, so a 300-byte file could ask for
// gigabytes. At most 16384 x 16384 pixels (the largest render), 128
// channels (a piece of a split render, batch/partial_render.h, has up to
// 100), and 2^30 values in all (4 GiB as float: the largest render's RGBA,
// or a 1080p piece's 100 channels).
inline constexpr uint64_t kMaxExrPixels = uint64_t(16384) * 16384;
inline constexpr int kMaxExrChannels = 128;
inline constexpr uint64_t kMaxExrValues = uint64_t(1) << 30;
// The width and height an EXR file's header declares (its data window),
// read without decoding, for callers with a tighter bound (environment
// maps). penumbra::Error if unreadable.
std::pair<uint64_t, uint64_t> exrSize(const std::string& path);

// A named group of channels of a layered EXR: channel k of `image` is
// written as "<name>.<channels[k]>" (e.g. "albedo.R"), one to four of them.
struct ExrLayer {
  std::string name;
  std::vector<std::string> channels;  // e.g. {"R", "G", "B"}, {"X", "Y", "Z"}, {"Z"}
  Image image;  // same size as the beauty image; the first channels.size() used
};
// The beauty image as R, G, B, A (what plain EXR readers show) plus the
// layers' channels, all 32-bit float, ZIP compressed, channels sorted by name
// as OpenEXR requires. Atomic like saveExr.
// `attributes`: string attributes written into the header (name, text),
// which loadExrChannels returns; other readers ignore them.
using ExrAttributes = std::vector<std::pair<std::string, std::string>>;
void saveExrLayers(const std::string& path, const Image& beauty,
                   const std::vector<ExrLayer>& layers, const ExrAttributes& attributes = {});
// Every channel of an EXR file by its full name, as float rows (top row
// first), with the image size.
struct ExrChannels {
  uint32_t width = 0, height = 0;
  std::vector<std::pair<std::string, std::vector<float>>> channels;
  ExrAttributes attributes;  // the header's string attributes beyond the standard ones
  const std::vector<float>* find(const std::string& name) const;
  const std::string* attribute(const std::string& name) const;
};
ExrChannels loadExrChannels(const std::string& path);
// The size and string attributes of an EXR file from its header alone (no
// channels), for readers that look before they load.
ExrChannels loadExrHeader(const std::string& path);
// 8-bit sRGB-encoded RGBA as PNG.
void savePng(const std::string& path, const Image8& image);

}  // namespace penumbra::image
