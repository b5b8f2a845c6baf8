#include "penumbra/scene/environment.h"

#include <fmt/format.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "penumbra/image/image_io.h"
#include "penumbra/util/error.h"

namespace penumbra::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The unit direction of map coordinates (u, v), as environment.hlsli.
glm::vec3 mapDirection(double u, double v) {
  const double theta = v * kPi, phi = (u - 0.5) * 2.0 * kPi;
  return glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta),
                   -std::sin(theta) * std::cos(phi));
}

// The environment limits (validateEnvironment) on the size a map's header
// declares, before it is decoded: the decoders allocate that much (16 bytes
// a texel as RGBA float) however little the file holds.
void checkDeclaredSize(const std::string& path, uint64_t width, uint64_t height) {
  if (width > kMaxEnvironmentWidth || height > kMaxEnvironmentWidth ||
      width * height > kMaxEnvironmentTexels)
    throw Error(fmt::format(
        "environment '{}': its header declares {}x{} texels, more than 16384x8192 ({} texels)",
        path, width, height, kMaxEnvironmentTexels));
}

}  // namespace

Environment loadEnvironmentMap(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw Error(fmt::format("environment '{}': no such file", path));
  Environment env;
  env.source = path;
  const std::string ext = image::lowerExtension(path);
  if (ext == ".exr") {
    image::Image img;
    std::pair<uint64_t, uint64_t> declared;
    try {
      declared = image::exrSize(path);
    } catch (const Error& e) {
      throw Error(fmt::format("environment: {}", e.what()));
    }
    checkDeclaredSize(path, declared.first, declared.second);
    try {
      img = image::loadExr(path);
    } catch (const Error& e) {
      throw Error(fmt::format("environment: {}", e.what()));
    }
    env.width = img.width;
    env.height = img.height;
    env.radiance.resize(size_t(img.width) * img.height);
    for (size_t i = 0; i < env.radiance.size(); ++i)
      env.radiance[i] = glm::vec3(img.rgba[i * 4], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2]);
  } else if (ext == ".hdr") {
    if (!stbi_is_hdr(path.c_str()))
      throw Error(fmt::format("environment '{}': not a Radiance HDR (RGBE) image", path));
    int w = 0, h = 0, components = 0;
    if (!stbi_info(path.c_str(), &w, &h, &components))
      throw Error(fmt::format("environment '{}': {}", path, stbi_failure_reason()));
    checkDeclaredSize(path, uint64_t(std::max(w, 0)), uint64_t(std::max(h, 0)));
    float* data = stbi_loadf(path.c_str(), &w, &h, &components, 3);
    if (!data) throw Error(fmt::format("environment '{}': {}", path, stbi_failure_reason()));
    env.width = uint32_t(w);
    env.height = uint32_t(h);
    env.radiance.resize(size_t(w) * h);
    for (size_t i = 0; i < env.radiance.size(); ++i)
      env.radiance[i] = glm::vec3(data[i * 3], data[i * 3 + 1], data[i * 3 + 2]);
    stbi_image_free(data);
  } else {
    throw Error(fmt::format(
        "environment '{}': not an HDR image (an equirectangular .exr or .hdr is expected)", path));
  }
  validateEnvironment(env);
  return env;
}

Environment constantEnvironment(const glm::vec3& radiance) {
  Environment env;
  env.width = 64;
  env.height = 32;
  env.radiance.assign(size_t(env.width) * env.height, radiance);
  env.source = fmt::format("colour ({}, {}, {})", radiance.x, radiance.y, radiance.z);
  validateEnvironment(env);
  return env;
}

Environment defaultEnvironment() {
  Environment env;
  env.width = 512;
  env.height = 256;
  env.source = "default studio";
  env.radiance.resize(size_t(env.width) * env.height);
  // The key light's axis: 45 degrees up, 40 degrees to the left of -z.
  const glm::vec3 key = glm::normalize(mapDirection(0.5 - 40.0 / 360.0, 0.25));
  const float keyCos = std::cos(glm::radians(12.0f));
  for (uint32_t y = 0; y < env.height; ++y)
    for (uint32_t x = 0; x < env.width; ++x) {
      const glm::vec3 d = mapDirection((x + 0.5) / env.width, (y + 0.5) / env.height);
      // Smooth from a bright ceiling (0.9) to the horizon (0.6) to a darker floor (0.25).
      const float up = d.y;
      float level = up >= 0.0f ? 0.6f + 0.3f * std::sqrt(up) : 0.6f - 0.35f * std::sqrt(-up);
      // The key: a disk of 12 degrees whose edge fades over its outer third.
      const float c = glm::dot(d, key);
      if (c > keyCos) level += 12.0f * std::min(1.0f, (c - keyCos) / (1.0f - keyCos) * 3.0f);
      env.radiance[size_t(y) * env.width + x] = glm::vec3(level);
    }
  return env;
}

}  // namespace penumbra::scene
