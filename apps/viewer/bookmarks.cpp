#include "bookmarks.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "penumbra/scene/json_reading.h"
#include "penumbra/util/error.h"
#include "penumbra/util/json_nesting.h"
#include "penumbra/util/log.h"

namespace penumbra::viewer {
namespace {
using nlohmann::json;
json vec3(glm::vec3 v) {
  return json::array({v.x, v.y, v.z});
}
// The settings file is the user's own, but it is still read as untrusted
// text: bounded nesting, every field type- and range-checked, so a damaged
// or hand-edited file ends in a warning that names the field.
constexpr size_t kMaxNesting = 16;

glm::vec3 readNonZero(const json& value, const std::string& where) {
  const glm::vec3 v = scene::readVec3(value, where);
  if (!(glm::length(v) > 0.0f) || !std::isfinite(glm::length(v)))
    throw Error(fmt::format("{}: must be a non-zero direction of finite length", where));
  return v;
}

Bookmark readBookmark(const json& b, const std::string& where) {
  if (!b.is_object()) scene::throwWrongType(where, "bookmark", "an object", b);
  Bookmark bookmark;
  bookmark.name = scene::requireString(b, "name", where);
  const json& c = scene::require(b, "camera", where);
  const std::string camera = where + " camera";
  bookmark.camera.position =
      scene::readVec3(scene::require(c, "position", camera), camera + ".position");
  // Directions are kept as written (saved views come back bit for bit), but
  // a zero one would normalise to NaN.
  bookmark.camera.forward = readNonZero(scene::require(c, "forward", camera), camera + ".forward");
  bookmark.camera.up = readNonZero(scene::require(c, "up", camera), camera + ".up");
  bookmark.camera.verticalFovDegrees = scene::requireFloat(c, "verticalFovDegrees", camera);
  if (!(bookmark.camera.verticalFovDegrees > 0.0f && bookmark.camera.verticalFovDegrees < 180.0f))
    throw Error(fmt::format("{}: \"verticalFovDegrees\" {} is not in (0, 180)", camera,
                            bookmark.camera.verticalFovDegrees));
  bookmark.camera.orthographicHeight = scene::readFloat(c, "orthographicHeight", 0.0f, camera);
  if (!(bookmark.camera.orthographicHeight >= 0.0f && bookmark.camera.orthographicHeight <= 1e9f))
    throw Error(fmt::format(
        "{}: \"orthographicHeight\" must be 0 (perspective) or positive, at most 1e9", camera));
  bookmark.camera.aspectRatio = scene::readFloat(c, "aspectRatio", 0.0f, camera);
  if (bookmark.camera.aspectRatio < 0.0f)
    throw Error(fmt::format("{}: \"aspectRatio\" must be 0 (the image's) or positive", camera));
  return bookmark;
}
}  // namespace

std::string BookmarkStore::defaultPath() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    return std::string(xdg) + "/penumbra/viewer.json";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::string(home) + "/.config/penumbra/viewer.json";
  return "penumbra-viewer.json";
}

BookmarkStore::BookmarkStore(std::string path) : path_(std::move(path)) {
  std::ifstream in(path_, std::ios::binary);
  if (!in) return;  // no file yet: no bookmarks
  try {
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    if (auto at = json_nesting::firstTooDeep(text, kMaxNesting))
      throw Error(fmt::format("JSON nests deeper than {} levels at byte {}", kMaxNesting, *at));
    const json doc = json::parse(text);
    const json& bookmarks = scene::require(doc, "bookmarks", "the file");
    if (!bookmarks.is_object())
      scene::throwWrongType("the file", "bookmarks", "an object", bookmarks);
    for (const auto& [scene, list] : bookmarks.items()) {
      const std::string where = fmt::format("bookmarks of '{}'", scene);
      if (!list.is_array()) scene::throwWrongType("bookmarks", scene, "an array", list);
      for (size_t i = 0; i < list.size(); ++i)
        entries_.emplace_back(scene, readBookmark(list[i], fmt::format("{} [{}]", where, i)));
    }
  } catch (const std::exception& e) {
    // A damaged settings file must not keep the viewer from starting.
    readProblem_ = e.what();
    log::warning("viewer settings '{}' ignored: {}", path_, readProblem_);
    entries_.clear();
  }
}

std::vector<Bookmark> BookmarkStore::list(const std::string& scene) const {
  std::vector<Bookmark> out;
  for (const auto& [s, b] : entries_)
    if (s == scene) out.push_back(b);
  return out;
}

void BookmarkStore::save(const std::string& scene, const Bookmark& bookmark) {
  remove(scene, bookmark.name);
  entries_.emplace_back(scene, bookmark);
  write();
}

void BookmarkStore::remove(const std::string& scene, const std::string& name) {
  std::erase_if(entries_, [&](const auto& e) { return e.first == scene && e.second.name == name; });
  write();
}

void BookmarkStore::write() const {
  json doc;
  doc["bookmarks"] = json::object();
  for (const auto& [scene, b] : entries_)
    doc["bookmarks"][scene].push_back({{"name", b.name},
                                       {"camera",
                                        {{"position", vec3(b.camera.position)},
                                         {"forward", vec3(b.camera.forward)},
                                         {"up", vec3(b.camera.up)},
                                         {"verticalFovDegrees", b.camera.verticalFovDegrees},
                                         {"orthographicHeight", b.camera.orthographicHeight},
                                         {"aspectRatio", b.camera.aspectRatio}}}});
  std::error_code ec;
  const auto dir = std::filesystem::path(path_).parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  std::ofstream out(path_);
  out << doc.dump(2) << "\n";
  if (!out) throw Error(fmt::format("cannot write viewer settings '{}'", path_));
}

}  // namespace penumbra::viewer
