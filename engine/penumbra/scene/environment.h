#pragma once
// The environment: radiance arriving from infinitely far away, as an
// equirectangular map (shaders/shared/environment.hlsli gives the directions:
// the top row looks up (+y), the centre column along -z, u grows towards +x).
// It lights rays that leave the scene and is sampled by next-event estimation.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace penumbra::scene {

struct Environment {
  uint32_t width = 0, height = 0;   // 0: no environment
  std::vector<glm::vec3> radiance;  // linear RGB, row-major, top row first
  std::string source;  // where it came from, for messages ("sky.exr", "colour", "default")
  float rotationDegrees = 0.0f;   // about +y, counter-clockwise seen from above
  float intensity = 1.0f;         // multiplies the radiance
  bool visibleBackground = true;  // camera rays that miss see it (else black)
  bool present() const { return width > 0 && height > 0; }
};

// An HDR equirectangular image: OpenEXR (.exr) or Radiance RGBE (.hdr).
// Throws penumbra::Error naming the file: unreadable, not an HDR image, or
// with values that are negative or not finite.
Environment loadEnvironmentMap(const std::string& path);
// A uniform environment of this radiance (a small map, so that sampling
// still follows sin(theta)).
Environment constantEnvironment(const glm::vec3& radiance);
// The environment of a scene that has no light of its own: a neutral grey
// studio, brighter above than below, with a broad soft key light high in
// front on the left, so shapes read as in a glTF viewer. Made here rather
// than shipped as a file, so every build has it.
Environment defaultEnvironment();

// The largest map validateEnvironment takes: 16384x8192 (or any shape of
// that many texels, no side over 16384).
inline constexpr uint32_t kMaxEnvironmentWidth = 16384;
inline constexpr uint64_t kMaxEnvironmentTexels = uint64_t(16384) * 8192;

// At most kMaxEnvironmentTexels, finite rotation and intensity >= 0, width x height finite
// radiances >= 0; throws penumbra::Error naming the environment's source.
void validateEnvironment(const Environment& environment);

}  // namespace penumbra::scene
