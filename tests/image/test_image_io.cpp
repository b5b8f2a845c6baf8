#include <unistd.h>

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "penumbra/image/image_io.h"
#include "penumbra/util/error.h"
#include "test_data.h"

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

TEST_CASE("EXR layers: the beauty as R, G, B, A and each layer's named channels read back exactly",
          "[image]") {
  image::Image beauty{3, 2}, albedo{3, 2}, depth{3, 2};
  for (size_t i = 0; i < beauty.rgba.size(); ++i) {
    beauty.rgba[i] = 0.5f + float(i);
    albedo.rgba[i] = 1.0f / (1.0f + float(i));
    depth.rgba[i] = 100.0f - float(i);
  }
  const auto path = (scratchDir() / "layers.exr").string();
  image::saveExrLayers(path, beauty,
                       {{"albedo", {"R", "G", "B"}, albedo}, {"depth", {"Z"}, depth}});
  const image::ExrChannels read = image::loadExrChannels(path);
  REQUIRE(read.width == 3);
  REQUIRE(read.height == 2);
  REQUIRE(read.channels.size() == 8);
  // OpenEXR lists channels sorted by name.
  for (size_t c = 1; c < read.channels.size(); ++c)
    CHECK(read.channels[c - 1].first < read.channels[c].first);
  const struct {
    const char* name;
    const image::Image* image;
    int component;
  } expected[] = {{"R", &beauty, 0},        {"G", &beauty, 1},        {"B", &beauty, 2},
                  {"A", &beauty, 3},        {"albedo.R", &albedo, 0}, {"albedo.G", &albedo, 1},
                  {"albedo.B", &albedo, 2}, {"depth.Z", &depth, 0}};
  for (const auto& e : expected) {
    INFO("channel " << e.name);
    const std::vector<float>* values = read.find(e.name);
    REQUIRE(values);
    for (size_t p = 0; p < 6; ++p) CHECK((*values)[p] == e.image->rgba[p * 4 + e.component]);
  }
  // A plain reader sees the beauty image.
  const image::Image plain = image::loadExr(path);
  CHECK(plain.rgba == beauty.rgba);
  // Bad layers fail before anything is written.
  const auto bad = (scratchDir() / "bad-layers.exr").string();
  CHECK_THROWS_WITH(image::saveExrLayers(bad, beauty, {{"albedo", {"R"}, image::Image{2, 2}}}),
                    Catch::Matchers::ContainsSubstring("layer 'albedo' is 2x2"));
  CHECK_THROWS_WITH(image::saveExrLayers(bad, beauty, {{"x", {"R"}, albedo}, {"x", {"R"}, depth}}),
                    Catch::Matchers::ContainsSubstring("two channels named 'x.R'"));
  CHECK_THROWS_WITH(image::saveExrLayers(bad, beauty, {{"x", {}, albedo}}),
                    Catch::Matchers::ContainsSubstring("1 to 4 channels"));
  CHECK_FALSE(fs::exists(bad));
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

// A fuzz finding (tests/fuzz/corpus/image/finding-exr-header-leak): an EXR
// header whose channel list parses and whose data window does not. The
// header's allocations were leaked on that path; the sanitizer build's
// LeakSanitizer fails this test if they are again, and every build checks the
// file is refused with a reason.
TEST_CASE("an EXR header that fails part-way is refused and freed", "[image]") {
  const std::string path = test::dataPath("images/exr_header_fails_late.exr");
  // A missing file would be refused with its path too: make sure it is there.
  REQUIRE(fs::file_size(path) == 651);
  REQUIRE_THROWS_WITH(image::exrSize(path), Catch::Matchers::ContainsSubstring(path));
  REQUIRE_THROWS_WITH(image::loadExrChannels(path), Catch::Matchers::ContainsSubstring(path));
  REQUIRE_THROWS_WITH(image::loadExr(path), Catch::Matchers::ContainsSubstring(path));
}

// tinyexr allocates what the header's data window declares before it reads a
// pixel: a small file that declares 60000 x 60000 pixels must be refused from
// its header, naming the limit, not end in bad_alloc. (An image of
// kMaxExrPixels itself decodes: every render up to 16384 x 16384 is read back.)
TEST_CASE("an EXR that declares more pixels than the limit is refused from its header", "[image]") {
  const auto path = scratchDir() / "declares-huge.exr";
  image::Image img{2, 2};
  img.rgba.assign(16, 0.5f);
  image::saveExr(path.string(), img);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    bytes = buffer.str();
  }
  // "dataWindow\0box2i\0" + int32 size 16 + xMin yMin xMax yMax (little endian).
  const std::string attribute("dataWindow\0box2i\0", 17);
  const size_t at = bytes.find(attribute);
  REQUIRE(at != std::string::npos);
  const int32_t window[4] = {0, 0, 59999, 59999};
  std::memcpy(&bytes[at + attribute.size() + 4], window, sizeof window);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;

  REQUIRE(image::exrSize(path.string()) == std::pair<uint64_t, uint64_t>{60000, 60000});
  // (Matchers are built in place: a composed matcher kept in a variable
  // refers to temporaries.)
  for (auto load : {+[](const std::string& p) { image::loadExrChannels(p); },
                    +[](const std::string& p) { image::loadExr(p); }})
    REQUIRE_THROWS_WITH(load(path.string()),
                        Catch::Matchers::ContainsSubstring("declares 60000 x 60000 pixels") &&
                            Catch::Matchers::ContainsSubstring("more than the limit of 268435456"));
  fs::remove(path);
}
