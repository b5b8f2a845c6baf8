#include "image/image_io.h"

#include <fmt/format.h>
#include <stb_image_write.h>
#include <tinyexr.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "util/error.h"

namespace penumbra::image {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string temporaryPathFor(const std::string& path) {
  return fmt::format("{}.tmp-{}", path, getpid());
}

// Runs `write(tmp)`, then renames tmp over `path`; removes tmp on any failure.
template <class Write>
void writeAtomically(const std::string& path, Write write) {
  const std::string tmp = temporaryPathFor(path);
  bool ok = false;
  std::string reason;
  try {
    ok = write(tmp, reason);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (!ok) {
    std::remove(tmp.c_str());
    throw Error(fmt::format("output '{}': {}", path, reason.empty() ? "write failed" : reason));
  }
  // std::filesystem::rename replaces an existing file on Windows too
  // (MoveFileEx with MOVEFILE_REPLACE_EXISTING); std::rename does not there.
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
  if (error) {
    std::remove(tmp.c_str());
    throw Error(fmt::format("output '{}': cannot move the finished file into place", path));
  }
}

}  // namespace

FileFormat formatFromPath(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".exr") return FileFormat::Exr;
  if (ext == ".png") return FileFormat::Png;
  throw Error(fmt::format("output '{}': unknown image type '{}' (use .exr or .png)", path, ext));
}

void checkWritable(const std::string& path) {
  formatFromPath(path);
  const std::string tmp = temporaryPathFor(path);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    auto dir = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
      throw Error(fmt::format("output '{}': directory '{}' does not exist", path, dir.string()));
    throw Error(fmt::format("output '{}': cannot create a file there", path));
  }
  std::fclose(f);
  std::remove(tmp.c_str());
}

void saveExr(const std::string& path, const Image& image) {
  writeAtomically(path, [&](const std::string& tmp, std::string& reason) {
    const char* err = nullptr;
    // tinyexr: 4 components, FP32 storage (save_as_fp16 = 0).
    int r = SaveEXR(image.rgba.data(), int(image.width), int(image.height), 4, 0, tmp.c_str(), &err);
    if (r != TINYEXR_SUCCESS) {
      reason = err ? err : "tinyexr could not write the file";
      if (err) FreeEXRErrorMessage(err);
      return false;
    }
    return true;
  });
}

Image loadExr(const std::string& path) {
  float* data = nullptr;
  int w = 0, h = 0;
  const char* err = nullptr;
  if (LoadEXR(&data, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
    std::string reason = err ? err : "unreadable";
    if (err) FreeEXRErrorMessage(err);
    throw Error(fmt::format("image '{}': {}", path, reason));
  }
  Image image{uint32_t(w), uint32_t(h)};
  std::copy(data, data + size_t(w) * h * 4, image.rgba.begin());
  std::free(data);
  return image;
}

void savePng(const std::string& path, const Image8& image) {
  writeAtomically(path, [&](const std::string& tmp, std::string& reason) {
    int ok = stbi_write_png(tmp.c_str(), int(image.width), int(image.height), 4, image.rgba.data(),
                            int(image.width * 4));
    if (!ok) reason = "stb_image_write could not write the PNG";
    return ok != 0;
  });
}

}  // namespace penumbra::image
