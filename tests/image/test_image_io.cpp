#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <unistd.h>

#include <filesystem>

#include "image/image_io.h"
#include "util/error.h"

using namespace penumbra;
namespace fs = std::filesystem;

namespace {
fs::path scratchDir() {
  auto dir = fs::temp_directory_path() / ("penumbra-image-io-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}
}  // namespace

TEST_CASE("EXR round trip keeps linear float values", "[image]") {
  image::Image img{3, 2};
  const float values[] = {0.0f, 1e-6f, 0.5f, 1.0f, 17.0f, 12345.5f};
  for (uint32_t i = 0; i < 6; ++i) {
    float* p = img.pixel(i % 3, i / 3);
    p[0] = values[i];
    p[1] = values[i] * 2.0f;
    p[2] = values[i] * 0.25f;
    p[3] = 1.0f;
  }
  const auto path = (scratchDir() / "roundtrip.exr").string();
  image::saveExr(path, img);
  auto back = image::loadExr(path);
  REQUIRE(back.width == 3);
  REQUIRE(back.height == 2);
  REQUIRE(back.rgba == img.rgba);
  fs::remove(path);
}

TEST_CASE("output paths are checked before rendering", "[image]") {
  const auto dir = scratchDir();
  REQUIRE_NOTHROW(image::checkWritable((dir / "ok.png").string()));
  REQUIRE_FALSE(fs::exists(dir / "ok.png"));  // the check leaves nothing behind
  REQUIRE_THROWS_WITH(image::checkWritable((dir / "x.jpg").string()),
                      Catch::Matchers::ContainsSubstring("unknown image type"));
  REQUIRE_THROWS_WITH(image::checkWritable((dir / "missing" / "x.png").string()),
                      Catch::Matchers::ContainsSubstring("does not exist"));
}

TEST_CASE("a failed write leaves no partial file", "[image]") {
  const auto dir = scratchDir();
  const auto target = dir / "blocked.exr";
  // A directory where the temporary file should go makes the write fail.
  fs::create_directories(target.string() + ".tmp-" + std::to_string(::getpid()));
  image::Image img{4, 4};
  REQUIRE_THROWS_AS(image::saveExr(target.string(), img), Error);
  REQUIRE_FALSE(fs::exists(target));
  fs::remove_all(dir);
}

TEST_CASE("PNG output is written whole", "[image]") {
  image::Image8 img;
  img.width = 2;
  img.height = 2;
  img.rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 10, 20, 30, 255};
  const auto path = scratchDir() / "small.png";
  image::savePng(path.string(), img);
  REQUIRE(fs::file_size(path) > 8);
  fs::remove(path);
}
