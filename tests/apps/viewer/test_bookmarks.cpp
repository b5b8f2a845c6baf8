// Camera bookmarks in the viewer's settings file (apps/viewer/bookmarks.h).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
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
    scene::Camera top = camera;
    top.orthographicHeight = 2.5f;
    store.save("implicit-surfaces", {"top", top});
  }
  viewer::BookmarkStore reread(path);
  const auto list = reread.list("cornell-box");
  REQUIRE(list.size() == 1);
  CHECK(list[0].name == "door");
  CHECK(list[0].camera.position == camera.position);  // bit for bit
  CHECK(list[0].camera.forward == camera.forward);
  CHECK(list[0].camera.verticalFovDegrees == 55.0f);
  CHECK_FALSE(list[0].camera.orthographic());
  REQUIRE(reread.list("implicit-surfaces").size() == 1);
  CHECK(reread.list("implicit-surfaces")[0].camera.orthographicHeight == 2.5f);
  CHECK(reread.list("material-test").size() == 1);
  reread.remove("cornell-box", "door");
  CHECK(viewer::BookmarkStore(path).list("cornell-box").empty());
  CHECK(viewer::BookmarkStore(path).list("material-test").size() == 1);

  // A damaged file does not stop the viewer: no bookmarks, a warning.
  std::ofstream(path) << "{ not json";
  CHECK(viewer::BookmarkStore(path).list("material-test").empty());
  CHECK_FALSE(viewer::BookmarkStore(path).readProblem().empty());
  std::filesystem::remove_all(dir);
}

TEST_CASE("bookmarks: a damaged settings file is ignored with the field named", "[viewer]") {
  const auto dir = std::filesystem::temp_directory_path() / "penumbra-bookmarks-damaged";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "viewer.json").string();
  const std::string good =
      R"({"name": "a", "camera": {"position": [0, 0, 1], "forward": [0, 0, -1], "up": [0, 1, 0], )"
      R"("verticalFovDegrees": 40}})";
  auto problemOf = [&](const std::string& text) {
    std::ofstream(path, std::ios::trunc) << text;
    viewer::BookmarkStore store(path);
    if (!store.readProblem().empty()) CHECK(store.list("s").empty());  // all or nothing
    return store.readProblem();
  };
  CHECK(problemOf(R"({"bookmarks": {"s": [)" + good + "]}}").empty());
  CHECK(viewer::BookmarkStore(path).list("s").size() == 1);

  using Catch::Matchers::ContainsSubstring;
  CHECK_THAT(problemOf(R"({"bookmarks": {"s": [)" + good + R"(, {"name": 5}]}})"),
             ContainsSubstring("bookmarks of 's' [1]: \"name\" is not a string (got a number)"));
  std::string zeroForward = good;
  zeroForward.replace(zeroForward.find("[0, 0, -1]"), 10, "[0, 0, 0]");
  CHECK_THAT(problemOf(R"({"bookmarks": {"s": [)" + zeroForward + "]}}"),
             ContainsSubstring("camera.forward: must be a non-zero direction"));
  std::string hugeFov = good;
  hugeFov.replace(hugeFov.find("40"), 2, "1e300");
  CHECK_THAT(problemOf(R"({"bookmarks": {"s": [)" + hugeFov + "]}}"),
             ContainsSubstring("\"verticalFovDegrees\" 1e+300 does not fit a float"));
  std::string tallOrtho = good;
  tallOrtho.replace(tallOrtho.find("40}"), 3, R"(40, "orthographicHeight": 2e9})");
  CHECK_THAT(problemOf(R"({"bookmarks": {"s": [)" + tallOrtho + "]}}"),
             ContainsSubstring("\"orthographicHeight\" must be 0 (perspective) or positive, at "
                               "most 1e9"));
  CHECK_THAT(problemOf(R"({"bookmarks": [1]})"),
             ContainsSubstring("\"bookmarks\" is not an object (got an array)"));
  // Nesting is refused before the parser recurses into it.
  CHECK_THAT(problemOf(std::string(100000, '[')), ContainsSubstring("JSON nests deeper than 16"));
  std::filesystem::remove_all(dir);
}
