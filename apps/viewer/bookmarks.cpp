#include "bookmarks.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "util/error.h"
#include "util/log.h"

namespace penumbra::viewer {
namespace {
using nlohmann::json;
json vec3(glm::vec3 v) {
  return json::array({v.x, v.y, v.z});
}
glm::vec3 vec3(const json& j) {
  return {j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>()};
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
  std::ifstream in(path_);
  if (!in) return;  // no file yet: no bookmarks
  try {
    json doc = json::parse(in);
    for (auto& [scene, list] : doc.at("bookmarks").items())
      for (const auto& b : list) {
        Bookmark bookmark;
        bookmark.name = b.at("name").get<std::string>();
        const auto& c = b.at("camera");
        bookmark.camera.position = vec3(c.at("position"));
        bookmark.camera.forward = vec3(c.at("forward"));
        bookmark.camera.up = vec3(c.at("up"));
        bookmark.camera.verticalFovDegrees = c.at("verticalFovDegrees").get<float>();
        bookmark.camera.aspectRatio = c.value("aspectRatio", 0.0f);
        entries_.emplace_back(scene, bookmark);
      }
  } catch (const json::exception& e) {
    // A damaged settings file must not keep the viewer from starting.
    log::warning("viewer settings '{}' ignored: {}", path_, e.what());
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
                                         {"aspectRatio", b.camera.aspectRatio}}}});
  std::error_code ec;
  const auto dir = std::filesystem::path(path_).parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  std::ofstream out(path_);
  out << doc.dump(2) << "\n";
  if (!out) throw Error(fmt::format("cannot write viewer settings '{}'", path_));
}

}  // namespace penumbra::viewer
