#pragma once
// Camera bookmarks, kept in the viewer's settings file (JSON) rather than
// beside scene files: built-in scenes have no file of their own to sit beside,
// and scene directories may be read-only. Keyed by the scene's name as given
// (built-in name or path). File: --config FILE, else
// $XDG_CONFIG_HOME/penumbra/viewer.json, else ~/.config/penumbra/viewer.json.
#include <string>
#include <vector>

#include "penumbra/scene/scene.h"

namespace penumbra::viewer {

struct Bookmark {
  std::string name;
  scene::Camera camera;
};

class BookmarkStore {
 public:
  explicit BookmarkStore(std::string path);
  static std::string defaultPath();
  const std::string& path() const { return path_; }
  std::vector<Bookmark> list(const std::string& scene) const;
  // Why the file was ignored ("" when it was read or absent): a damaged file
  // leaves the viewer without bookmarks and a warning, never unable to start.
  const std::string& readProblem() const { return readProblem_; }
  // Adds or replaces the bookmark `name` of `scene` and writes the file.
  void save(const std::string& scene, const Bookmark& bookmark);
  void remove(const std::string& scene, const std::string& name);

 private:
  void write() const;
  std::string path_;
  std::string readProblem_;
  std::vector<std::pair<std::string, Bookmark>> entries_;  // (scene, bookmark)
};

}  // namespace penumbra::viewer
