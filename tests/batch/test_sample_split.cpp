// Sample-split renders (batch/sample_split.h, batch/partial_render.h): the
// block tree's covers, the merge's bit-identity for any split, the piece
// file and the merge's refusals. Host-side; the GPU half (pieces rendered on
// lavapipe merge to the single render) is tests/apps/cli_merge.sh.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "penumbra/batch/partial_render.h"
#include "penumbra/batch/sample_split.h"
#include "penumbra/image/image_io.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using Catch::Matchers::ContainsSubstring;
using render::SampleRange;
using render::SampleTree;

namespace {

// Every block-aligned range of small trees: its cover's nodes are
// contiguous, exactly the range, each one as large as it can be (its
// parent would not fit in the range), at most two per level.
void checkCovers(uint32_t total, uint32_t block) {
  const SampleTree tree(total, block);
  std::vector<uint32_t> bounds;
  for (uint32_t s = 0; s < total; s += block) bounds.push_back(s);
  bounds.push_back(total);
  for (size_t a = 0; a < bounds.size(); ++a)
    for (size_t b = a + 1; b < bounds.size(); ++b) {
      const SampleRange range{bounds[a], bounds[b]};
      const auto nodes = tree.cover(range);
      uint32_t at = range.begin;
      std::vector<int> perLevel(32, 0);
      for (const auto& node : nodes) {
        REQUIRE(tree.exists(node));
        const SampleRange covered = tree.samples(node);
        REQUIRE(covered.begin == at);
        at = covered.end;
        ++perLevel[node.level];
        // Maximal: the parent covers samples outside the range.
        const SampleTree::Node parent{node.level + 1, node.index / 2};
        if (node.level < tree.root().level) {
          const SampleRange p = tree.samples(parent);
          CHECK((p.begin < range.begin || p.end > range.end || p == covered));
        }
      }
      REQUIRE(at == range.end);
      for (int count : perLevel) CHECK(count <= 2);
    }
}

// Synthetic block sums: the tree's arithmetic without a GPU. Leaves hold
// values of very different magnitudes (fireflies among dim pixels), where
// float addition order shows.
render::NodeSums sumsFor(const SampleTree& tree, const SampleRange& range) {
  std::function<image::Image(SampleTree::Node)> value = [&](SampleTree::Node node) {
    if (node.level == 0) {
      image::Image leaf(5, 3);
      std::mt19937 rng(node.index * 7919u + 13u);
      std::uniform_real_distribution<float> u(0.0f, 1.0f);
      for (size_t i = 0; i < leaf.rgba.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
          const float x = u(rng);
          leaf.rgba[i + c] = x < 0.05f ? x * 2e5f : x * 1e-3f;
        }
      return leaf;
    }
    image::Image sum = value({node.level - 1, node.index * 2});
    const SampleTree::Node right{node.level - 1, node.index * 2 + 1};
    if (tree.exists(right)) {
      const image::Image r = value(right);
      for (size_t i = 0; i < sum.rgba.size(); ++i) sum.rgba[i] += r.rgba[i];
    }
    return sum;
  };
  render::NodeSums sums;
  sums.nodes = tree.cover(range);
  for (const auto& node : sums.nodes) sums.sums.push_back(value(node));
  return sums;
}

render::PartialRender piece(const SampleTree& tree, const SampleRange& range, uint32_t seed = 1) {
  render::PartialRender p;
  p.identity = {"scenehash", "settingshash", 5, 3, seed, tree.totalSpp(), tree.blockSpp(), "test"};
  p.sceneName = "test";
  p.range = range;
  p.device = "test device";
  p.sums = sumsFor(tree, range);
  return p;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "penumbra-sample-split";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

}  // namespace

TEST_CASE("sample split: covers are exact, maximal and at most two nodes a level", "[split]") {
  for (uint32_t total : {1u, 2u, 5u, 16u, 17u, 64u, 100u, 127u, 128u, 129u})
    for (uint32_t block : {1u, 3u, 16u}) checkCovers(total, block);
  const SampleTree tree(64, 16);
  CHECK(tree.blockCount() == 4);
  CHECK(tree.cover({0, 64}) == std::vector<SampleTree::Node>{tree.root()});
  CHECK(tree.cover({16, 64}) == std::vector<SampleTree::Node>{{0, 1}, {1, 1}});
  // The last block may be short: 100 samples are 6 blocks of 16 and one of 4.
  const SampleTree ragged(100, 16);
  CHECK(ragged.blockCount() == 7);
  CHECK(ragged.samples({0, 6}) == SampleRange{96, 100});
  CHECK(ragged.cover({64, 100}) == std::vector<SampleTree::Node>{{2, 1}});
}

TEST_CASE("sample split: ranges off block boundaries or past the total are refused", "[split]") {
  const SampleTree tree(100, 16);
  CHECK_THROWS_WITH(tree.checkRange({8, 32}, "--samples"),
                    ContainsSubstring("multiples of the samples per frame (16)"));
  CHECK_THROWS_WITH(tree.checkRange({0, 101}, "--samples"), ContainsSubstring("within 0:100"));
  CHECK_NOTHROW(tree.checkRange({96, 100}, "--samples"));
  CHECK_THROWS_WITH(render::parseSampleRange("16:8", "--samples"),
                    ContainsSubstring("FIRST < END"));
  CHECK_THROWS_WITH(render::parseSampleRange("a:8", "--samples"), ContainsSubstring("'a:8'"));
  CHECK(render::parseSampleRange("16:48", "--samples") == SampleRange{16, 48});
  CHECK_THROWS_AS(SampleTree(64, 17), Error);
}

TEST_CASE("sample split: shards cover the render in near-equal whole blocks", "[split]") {
  for (uint32_t total : {64u, 100u, 1000u})
    for (uint32_t k : {1u, 2u, 3u, 7u, 200u}) {
      const SampleTree tree(total, 16);
      const auto ranges = tree.split(k);
      REQUIRE(ranges.size() == std::min(k, tree.blockCount()));
      uint32_t at = 0;
      for (const auto& r : ranges) {
        CHECK(r.begin == at);
        CHECK_NOTHROW(tree.checkRange(r, "shard"));
        at = r.end;
      }
      CHECK(at == total);
    }
}

// The claim the farm rests on: however the render is split and in whatever
// order the pieces come, the merge adds the same floats in the same order
// as the render of all samples at once.
TEST_CASE("sample split: any split, in any order, merges to the single render's bits", "[split]") {
  const SampleTree tree(200, 16);  // 13 blocks, the last of 8 samples
  const render::PartialRender whole = piece(tree, {0, 200});
  const render::MergedRender single = render::mergePartialRenders({whole}, {"whole"}, false);
  CHECK(single.samples == 200);
  std::mt19937 rng(2024);
  for (uint32_t k : {1u, 2u, 3u, 7u}) {
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<SampleRange> ranges = tree.split(k);
      if (trial > 0) {  // random block-aligned cut points too
        std::vector<uint32_t> cuts;
        for (uint32_t b = 1; b < tree.blockCount(); ++b) cuts.push_back(b * 16);
        std::shuffle(cuts.begin(), cuts.end(), rng);
        cuts.resize(k - 1);
        cuts.push_back(0);
        cuts.push_back(200);
        std::sort(cuts.begin(), cuts.end());
        ranges.clear();
        for (size_t i = 0; i + 1 < cuts.size(); ++i) ranges.push_back({cuts[i], cuts[i + 1]});
      }
      std::vector<render::PartialRender> pieces;
      std::vector<std::string> names;
      for (const auto& r : ranges) {
        pieces.push_back(piece(tree, r));
        names.push_back(render::formatSampleRange(r));
      }
      std::shuffle(pieces.begin(), pieces.end(), rng);
      const auto merged = render::mergePartialRenders(pieces, names, false);
      REQUIRE(merged.samples == 200);
      REQUIRE(merged.image.rgba == single.image.rgba);
    }
  }
  // The order matters in float: a plain running sum of the same leaves gives
  // other bits, so the equality above is not one any order would pass.
  image::Image sequential(5, 3);
  for (uint32_t b = 0; b < tree.blockCount(); ++b) {
    const SampleTree::Node leaf{0, b};
    const render::NodeSums s = sumsFor(tree, tree.samples(leaf));
    for (size_t i = 0; i < sequential.rgba.size(); ++i) sequential.rgba[i] += s.sums[0].rgba[i];
  }
  CHECK(render::meanOf(sequential, 200).rgba != single.image.rgba);
}

// Merging files streams them: every piece is checked from its description
// first, then its sums are asked for once, in sample order, and folded in
// (render::SampleTreeFold), so a merge holds one piece at a time.
TEST_CASE("sample split: a streamed merge reads each piece once, in sample order", "[split]") {
  const SampleTree tree(200, 16);
  const render::MergedRender single =
      render::mergePartialRenders({piece(tree, {0, 200})}, {"whole"}, false);
  std::vector<render::PartialRender> described;
  std::vector<render::NodeSums> stored;
  std::vector<std::string> names;
  for (const SampleRange& r : std::vector<SampleRange>{{96, 128}, {0, 16}, {128, 200}, {16, 96}}) {
    render::PartialRender p = piece(tree, r);
    stored.push_back(std::move(p.sums));
    p.sums = {};
    described.push_back(std::move(p));
    names.push_back(render::formatSampleRange(r));
  }
  std::vector<uint32_t> asked;
  auto load = [&](size_t k) {
    asked.push_back(described[k].range.begin);
    return stored[k];
  };
  const auto merged = render::mergePartialRenders(described, names, false, load);
  CHECK(asked == std::vector<uint32_t>{0, 16, 96, 128});
  CHECK(merged.samples == 200);
  CHECK(merged.image.rgba == single.image.rgba);

  // Refusals come from the descriptions alone: no sums are read.
  asked.clear();
  auto overlapping = described;
  overlapping[0].range = {80, 128};
  CHECK_THROWS_WITH(render::mergePartialRenders(overlapping, names, false, load),
                    ContainsSubstring("overlap"));
  CHECK(asked.empty());
  // Sums that are not the nodes the description names are refused.
  auto wrongNodes = [&](size_t k) {
    render::NodeSums sums = stored[k];
    if (described[k].range.begin == 16) sums.nodes.pop_back();
    return sums;
  };
  CHECK_THROWS_WITH(render::mergePartialRenders(described, names, false, wrongNodes),
                    ContainsSubstring("'16:96' does not hold the tree nodes of samples 16:96"));
}

// With samples missing, a node whose child is missing takes the other
// child's value: in 4 blocks with blocks 1 and 2 missing, the root is
// block 0 + block 3 (computed here by hand from the synthetic leaves).
TEST_CASE("sample split: a partial merge adds the blocks present in tree order", "[split]") {
  const SampleTree tree(64, 16);
  const auto merged =
      render::mergePartialRenders({piece(tree, {48, 64}), piece(tree, {0, 16})}, {"d", "e"}, true);
  REQUIRE(merged.samples == 32);
  const image::Image first = sumsFor(tree, {0, 16}).sums[0], last = sumsFor(tree, {48, 64}).sums[0];
  image::Image expected(5, 3);
  for (size_t i = 0; i < expected.rgba.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c)
      expected.rgba[i + c] = (first.rgba[i + c] + last.rgba[i + c]) / 32.0f;
    expected.rgba[i + 3] = 1.0f;
  }
  CHECK(merged.image.rgba == expected.rgba);
}

TEST_CASE("sample split: the fold takes nodes in block order only", "[split]") {
  const SampleTree tree(64, 16);
  render::SampleTreeFold fold(tree);
  CHECK_THROWS_WITH(fold.add({0, 1}, image::Image(5, 3)),
                    ContainsSubstring("node 0.1 does not follow block 0"));
  fold.add({0, 0}, image::Image(5, 3));
  CHECK_THROWS_WITH(fold.add({0, 2}, image::Image(5, 3)),
                    ContainsSubstring("does not follow block 1"));
  CHECK_THROWS_WITH(fold.result(), ContainsSubstring("blocks 1 to 4 were not added"));
  fold.add({0, 1}, image::Image(5, 3));
  fold.add({1, 1}, image::Image(5, 3));
  CHECK(fold.result().rgba.size() == 5 * 3 * 4);
}

TEST_CASE("sample split: a piece file round-trips bit for bit", "[split]") {
  const SampleTree tree(100, 16);
  const render::PartialRender p = piece(tree, {32, 100});
  const std::string path = scratch("round-trip.exr");
  render::savePartialRender(path, p);
  const render::PartialRender back = render::loadPartialRender(path);
  CHECK(back.identity == p.identity);
  CHECK(back.range == p.range);
  CHECK(back.device == p.device);
  REQUIRE(back.sums.nodes == p.sums.nodes);
  for (size_t k = 0; k < p.sums.sums.size(); ++k)
    CHECK(back.sums.sums[k].rgba == p.sums.sums[k].rgba);
  // The description alone comes from the header: the same piece, no sums.
  const render::PartialRender described = render::loadPartialRenderDescription(path);
  CHECK(described.identity == p.identity);
  CHECK(described.range == p.range);
  CHECK(described.sumsHash == back.sumsHash);
  CHECK(described.sums.nodes.empty());
  std::filesystem::remove(path);
}

TEST_CASE("sample split: merge refuses other renders, overlaps, gaps and damaged pieces",
          "[split]") {
  const SampleTree tree(64, 16);
  const auto a = piece(tree, {0, 32}), b = piece(tree, {32, 64});
  CHECK_THROWS_WITH(render::mergePartialRenders({a, piece(tree, {32, 64}, 2)}, {"a", "b"}, false),
                    ContainsSubstring("'a' and 'b' are pieces of different renders (seed 1 vs 2)"));
  auto otherScene = b;
  otherScene.identity.sceneHash = "another";
  CHECK_THROWS_WITH(render::mergePartialRenders({a, otherScene}, {"a", "b"}, false),
                    ContainsSubstring("scene content scenehash vs another"));
  CHECK_THROWS_WITH(render::mergePartialRenders({a, a}, {"a", "a2"}, false),
                    ContainsSubstring("'a' (samples 0:32) and 'a2' (samples 0:32) overlap"));
  CHECK_THROWS_WITH(render::mergePartialRenders({a, piece(tree, {16, 64})}, {"a", "c"}, false),
                    ContainsSubstring("overlap"));
  const auto d = piece(tree, {48, 64});
  CHECK_THROWS_WITH(render::mergePartialRenders({d}, {"d"}, false),
                    ContainsSubstring("samples 0:48 of 0:64 are missing"));
  const auto partial = render::mergePartialRenders({d, piece(tree, {0, 16})}, {"d", "e"}, true);
  CHECK(partial.samples == 32);
  CHECK(partial.missing == std::vector<SampleRange>{{16, 48}});

  // Files: not a piece, truncated, changed after writing.
  const std::string path = scratch("damaged.exr");
  render::savePartialRender(path, a);
  const std::string description = *image::loadExrChannels(path).attribute("penumbra.partial");
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    bytes = buffer.str();
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  CHECK_THROWS_WITH(render::loadPartialRender(path), ContainsSubstring(path));
  // A file rewritten with other sums under the original description: the
  // sums' hash finds it. A description that disagrees with the image: named.
  auto rewrite = [&](const render::NodeSums& sums, const std::string& text) {
    // The piece file's layout (batch/partial_render.h): one layer per node.
    std::vector<image::ExrLayer> layers;
    for (size_t k = 0; k < sums.nodes.size(); ++k)
      layers.push_back({"sum.L" + std::to_string(sums.nodes[k].level) + ".I" +
                            std::to_string(sums.nodes[k].index),
                        {"R", "G", "B"},
                        sums.sums[k]});
    image::saveExrLayers(path, image::Image(5, 3), layers, {{"penumbra.partial", text}});
  };
  render::NodeSums changed = a.sums;
  changed.sums[0].rgba[4] += 1.0f;
  rewrite(changed, description);
  CHECK_THROWS_WITH(render::loadPartialRender(path),
                    ContainsSubstring("do not match the hash written with them"));
  rewrite(a.sums, description);
  CHECK_NOTHROW(render::loadPartialRender(path));  // the rewrite itself is faithful
  std::string wider = description;
  wider.replace(wider.find("\"width\":5"), 9, "\"width\":6");
  rewrite(a.sums, wider);
  CHECK_THROWS_WITH(render::loadPartialRender(path),
                    ContainsSubstring("the image is 5x3, its description says 6x3"));
  std::string otherNodes = description;
  otherNodes.replace(otherNodes.find("\"samples\":[0,32]"), 16, "\"samples\":[0,48]");
  rewrite(a.sums, otherNodes);
  CHECK_THROWS_WITH(render::loadPartialRender(path),
                    ContainsSubstring("\"nodes\" do not cover samples 0:48"));
  render::NodeSums missingLayer = a.sums;
  missingLayer.nodes[0].index += 1;  // written under another node's name
  rewrite(missingLayer, description);
  CHECK_THROWS_WITH(render::loadPartialRender(path),
                    ContainsSubstring("channel 'sum.L1.I0.R' is missing"));
  image::Image plain(5, 3);
  image::saveExr(path, plain);
  CHECK_THROWS_WITH(render::loadPartialRender(path),
                    ContainsSubstring("not a piece of a split render"));
  std::filesystem::remove(path);
}
