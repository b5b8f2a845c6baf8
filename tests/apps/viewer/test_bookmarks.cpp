// Camera bookmarks in the viewer's settings file (apps/viewer/bookmarks.h).
#include <catch2/catch_test_macros.hpp>
#include <filesystem>
#include <fstream>

#include "bookmarks.h"

using namespace penumbra;

TEST_CASE("bookmarks: saved per scene, read back by a new store, removable", "[viewer]") {
  const auto dir = std::filesystem::temp_directory_path() / "penumbra-bookmarks-test";
  std::filesystem::remove_all(dir);
  const std::string path = (dir / "nested" / "viewer.json").string();  // directories are created
  scene::Camera camera;
  camera.position = {0.1f, 0.2f, 1.0f / 3.0f};
  camera.forward = {0, 0, -1};
  camera.verticalFovDegrees = 55.0f;
  {
    viewer::BookmarkStore store(path);
    CHECK(store.list("cornell-box").empty());
    store.save("cornell-box", {"door", camera});
    store.save("material-test", {"front", scene::Camera{}});
  }
  viewer::BookmarkStore reread(path);
  const auto list = reread.list("cornell-box");
  REQUIRE(list.size() == 1);
  CHECK(list[0].name == "door");
  CHECK(list[0].camera.position == camera.position);  // bit for bit
  CHECK(list[0].camera.forward == camera.forward);
  CHECK(list[0].camera.verticalFovDegrees == 55.0f);
  CHECK(reread.list("material-test").size() == 1);
  reread.remove("cornell-box", "door");
  CHECK(viewer::BookmarkStore(path).list("cornell-box").empty());
  CHECK(viewer::BookmarkStore(path).list("material-test").size() == 1);

  // A damaged file does not stop the viewer: no bookmarks, a warning.
  std::ofstream(path) << "{ not json";
  CHECK(viewer::BookmarkStore(path).list("material-test").empty());
  std::filesystem::remove_all(dir);
}
