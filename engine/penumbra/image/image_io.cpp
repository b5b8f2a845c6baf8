#include "penumbra/image/image_io.h"

#include <fmt/format.h>
#include <stb_image_write.h>
#include <tinyexr.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "penumbra/util/error.h"

namespace penumbra::image {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

namespace {

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

// tinyexr's error message, which is freed here, or `fallback` when it gave none.
std::string takeExrError(const char* err, const char* fallback) {
  std::string reason = err ? err : fallback;
  if (err) FreeEXRErrorMessage(err);
  return reason;
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

// tinyexr's writers leak what they allocated when they cannot open the file
// (found by the sanitizer build: "a failed write leaves no partial file"), so
// the file is created here first and tinyexr only ever writes to one it can.
static bool canCreate(const std::string& tmp, std::string& reason) {
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    reason = "cannot create the file";
    return false;
  }
  std::fclose(f);
  return true;
}

void saveExr(const std::string& path, const Image& image) {
  writeAtomically(path, [&](const std::string& tmp, std::string& reason) {
    if (!canCreate(tmp, reason)) return false;
    const char* err = nullptr;
    // tinyexr: 4 components, FP32 storage (save_as_fp16 = 0).
    int r =
        SaveEXR(image.rgba.data(), int(image.width), int(image.height), 4, 0, tmp.c_str(), &err);
    if (r != TINYEXR_SUCCESS) {
      reason = takeExrError(err, "tinyexr could not write the file");
      return false;
    }
    return true;
  });
}

void saveExrLayers(const std::string& path, const Image& beauty,
                   const std::vector<ExrLayer>& layers, const ExrAttributes& attributes) {
  struct Channel {
    std::string name;
    const Image* image;
    int component;
  };
  std::vector<Channel> channels;
  const char* rgba[] = {"R", "G", "B", "A"};
  for (int k = 0; k < 4; ++k) channels.push_back({rgba[k], &beauty, k});
  for (const auto& layer : layers) {
    if (layer.channels.empty() || layer.channels.size() > 4)
      throw Error(fmt::format("image '{}': layer '{}' needs 1 to 4 channels", path, layer.name));
    if (layer.image.width != beauty.width || layer.image.height != beauty.height)
      throw Error(fmt::format("image '{}': layer '{}' is {}x{}, the image {}x{}", path, layer.name,
                              layer.image.width, layer.image.height, beauty.width, beauty.height));
    for (size_t k = 0; k < layer.channels.size(); ++k)
      channels.push_back({layer.name + "." + layer.channels[k], &layer.image, int(k)});
  }
  std::sort(channels.begin(), channels.end(),
            [](const Channel& a, const Channel& b) { return a.name < b.name; });
  for (size_t i = 1; i < channels.size(); ++i)
    if (channels[i].name == channels[i - 1].name)
      throw Error(fmt::format("image '{}': two channels named '{}'", path, channels[i].name));

  const size_t pixels = size_t(beauty.width) * beauty.height;
  std::vector<std::vector<float>> planes(channels.size(), std::vector<float>(pixels));
  std::vector<unsigned char*> planePointers;
  std::vector<EXRChannelInfo> infos(channels.size());
  std::vector<int> pixelTypes(channels.size(), TINYEXR_PIXELTYPE_FLOAT);
  for (size_t c = 0; c < channels.size(); ++c) {
    for (size_t i = 0; i < pixels; ++i)
      planes[c][i] = channels[c].image->rgba[i * 4 + channels[c].component];
    planePointers.push_back(reinterpret_cast<unsigned char*>(planes[c].data()));
    std::snprintf(infos[c].name, sizeof(infos[c].name), "%s", channels[c].name.c_str());
  }
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = int(channels.size());
  header.channels = infos.data();
  header.pixel_types = pixelTypes.data();
  header.requested_pixel_types = pixelTypes.data();
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
  std::vector<EXRAttribute> custom(attributes.size());
  for (size_t i = 0; i < attributes.size(); ++i) {
    const auto& [name, text] = attributes[i];
    if (name.empty() || name.size() >= sizeof(custom[i].name) || text.size() > (1u << 24))
      throw Error(fmt::format("image '{}': attribute '{}' cannot be written", path, name));
    std::snprintf(custom[i].name, sizeof(custom[i].name), "%s", name.c_str());
    std::snprintf(custom[i].type, sizeof(custom[i].type), "string");
    // tinyexr only reads the value while writing; it is not freed here.
    custom[i].value = reinterpret_cast<unsigned char*>(const_cast<char*>(text.data()));
    custom[i].size = int(text.size());
  }
  header.num_custom_attributes = int(custom.size());
  header.custom_attributes = custom.empty() ? nullptr : custom.data();
  EXRImage exr;
  InitEXRImage(&exr);
  exr.num_channels = int(channels.size());
  exr.width = int(beauty.width);
  exr.height = int(beauty.height);
  exr.images = planePointers.data();
  writeAtomically(path, [&](const std::string& tmp, std::string& reason) {
    if (!canCreate(tmp, reason)) return false;
    const char* err = nullptr;
    if (SaveEXRImageToFile(&exr, &header, tmp.c_str(), &err) != TINYEXR_SUCCESS) {
      reason = takeExrError(err, "tinyexr could not write the file");
      return false;
    }
    return true;
  });
}

const std::string* ExrChannels::attribute(const std::string& name) const {
  for (const auto& [n, text] : attributes)
    if (n == name) return &text;
  return nullptr;
}

const std::vector<float>* ExrChannels::find(const std::string& name) const {
  for (const auto& [n, values] : channels)
    if (n == name) return &values;
  return nullptr;
}

namespace {
// max - min + 1 of a data window, in int64 first: it can overflow an int.
uint64_t exrExtent(int lo, int hi) {
  return hi >= lo ? uint64_t(int64_t(hi) - lo + 1) : 0;
}
}  // namespace

namespace {

// Parses the header of a single-part scanline EXR file into `header`, which
// the caller frees; throws naming the file (having freed it) otherwise.
void parseScanlineHeader(const std::string& path, EXRHeader& header) {
  EXRVersion version;
  InitEXRHeader(&header);
  if (ParseEXRVersionFromFile(&version, path.c_str()) != TINYEXR_SUCCESS || version.multipart ||
      version.tiled)
    throw Error(fmt::format("image '{}': not a single-part scanline OpenEXR file", path));
  const char* err = nullptr;
  // A header that fails part-way has some attributes allocated already
  // (found by fuzzing: tests/fuzz/corpus/image/finding-exr-header-leak).
  if (ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err) != TINYEXR_SUCCESS) {
    FreeEXRHeader(&header);
    throw Error(fmt::format("image '{}': {}", path, takeExrError(err, "unreadable header")));
  }
}

ExrAttributes stringAttributes(const EXRHeader& header) {
  ExrAttributes attributes;
  for (int a = 0; a < header.num_custom_attributes; ++a) {
    const EXRAttribute& attribute = header.custom_attributes[a];
    if (std::string_view(attribute.type) == "string" && attribute.size >= 0)
      attributes.emplace_back(
          attribute.name,
          std::string(reinterpret_cast<const char*>(attribute.value), size_t(attribute.size)));
  }
  return attributes;
}

}  // namespace

ExrChannels loadExrChannels(const std::string& path) {
  EXRHeader header;
  parseScanlineHeader(path, header);
  const EXRBox2i window = header.data_window;
  const uint64_t declaredWidth = exrExtent(window.min_x, window.max_x),
                 declaredHeight = exrExtent(window.min_y, window.max_y);
  const uint64_t declaredPixels = declaredWidth * declaredHeight;
  if (declaredPixels > kMaxExrPixels || header.num_channels > kMaxExrChannels ||
      declaredPixels * uint64_t(std::max(header.num_channels, 0)) > kMaxExrValues) {
    const int channels = header.num_channels;
    FreeEXRHeader(&header);
    throw Error(fmt::format(
        "image '{}': its header declares {} x {} pixels of {} channels, more than the limit of "
        "{} pixels, {} channels and {} values",
        path, declaredWidth, declaredHeight, channels, kMaxExrPixels, kMaxExrChannels,
        kMaxExrValues));
  }
  for (int c = 0; c < header.num_channels; ++c)
    header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  EXRImage exr;
  InitEXRImage(&exr);
  // (A failed load frees the image's planes itself: FreeEXRImage here would
  // free them twice.)
  const char* err = nullptr;
  if (LoadEXRImageFromFile(&exr, &header, path.c_str(), &err) != TINYEXR_SUCCESS) {
    FreeEXRHeader(&header);
    throw Error(fmt::format("image '{}': {}", path, takeExrError(err, "unreadable pixels")));
  }
  ExrChannels result;
  result.attributes = stringAttributes(header);
  result.width = uint32_t(exr.width);
  result.height = uint32_t(exr.height);
  const size_t pixels = size_t(exr.width) * exr.height;
  for (int c = 0; c < header.num_channels; ++c) {
    const float* plane = reinterpret_cast<const float*>(exr.images[c]);
    result.channels.emplace_back(header.channels[c].name,
                                 std::vector<float>(plane, plane + pixels));
  }
  FreeEXRImage(&exr);
  FreeEXRHeader(&header);
  return result;
}

ExrChannels loadExrHeader(const std::string& path) {
  EXRHeader header;
  parseScanlineHeader(path, header);
  const EXRBox2i w = header.data_window;
  ExrChannels result;
  result.attributes = stringAttributes(header);
  const uint64_t width = exrExtent(w.min_x, w.max_x), height = exrExtent(w.min_y, w.max_y);
  FreeEXRHeader(&header);
  if (width > kMaxExrPixels || height > kMaxExrPixels || width * height > kMaxExrPixels)
    throw Error(
        fmt::format("image '{}': its header declares {} x {} pixels, more than the "
                    "limit of {} pixels",
                    path, width, height, kMaxExrPixels));
  result.width = uint32_t(width);
  result.height = uint32_t(height);
  return result;
}

std::pair<uint64_t, uint64_t> exrSize(const std::string& path) {
  EXRHeader header;
  parseScanlineHeader(path, header);
  const EXRBox2i w = header.data_window;
  FreeEXRHeader(&header);
  return {exrExtent(w.min_x, w.max_x), exrExtent(w.min_y, w.max_y)};
}

// Through loadExrChannels rather than tinyexr's LoadEXR, which leaks on some
// malformed files (found by fuzzing: tests/fuzz/corpus/image/
// finding-exr-loadexr-leak); this way every error path frees what it parsed.
// As LoadEXR: R, G, B and A (1 when absent), or one channel as grey.
Image loadExr(const std::string& path) {
  ExrChannels exr = loadExrChannels(path);
  const std::vector<float>* r = exr.find("R");
  const std::vector<float>* g = exr.find("G");
  const std::vector<float>* b = exr.find("B");
  const std::vector<float>* a = exr.find("A");
  if (!(r && g && b)) {
    if (exr.channels.size() != 1)
      throw Error(
          fmt::format("image '{}': no R, G and B channels and not a single-channel image", path));
    r = g = b = &exr.channels.front().second;
    a = nullptr;
  }
  Image image{exr.width, exr.height};
  const size_t pixels = size_t(exr.width) * exr.height;
  for (size_t i = 0; i < pixels; ++i) {
    image.rgba[i * 4 + 0] = (*r)[i];
    image.rgba[i * 4 + 1] = (*g)[i];
    image.rgba[i * 4 + 2] = (*b)[i];
    image.rgba[i * 4 + 3] = a ? (*a)[i] : 1.0f;
  }
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
