#pragma once
// A render split by samples, so that its pieces can run on different
// machines (`penumbra render --samples A:B --total-spp N`, `penumbra merge`,
// `penumbra farm`) and still add up to exactly the image one machine makes.
//
// The samples of an N-sample render fall into blocks of `blockSpp` (one GPU
// frame each; the last block may be shorter). Each block is rendered as a
// mean of its own from its first global sample index, so the per-sample
// random streams and the frame's stratification are those of the whole
// render, whichever piece renders it. Blocks are summed in one fixed order,
// a binary tree over block indices:
//
//   leaf j           = (mean of block j) * (samples of block j)
//   node (level L, i) covers blocks [i 2^L, (i+1) 2^L) clipped to the block
//                    count: left child + right child, or the left child alone
//                    when the right one lies past the last block.
//   the image        = root / N
//
// A piece [A, B) stores the largest tree nodes inside its blocks (at most
// two per level), and merging fills in the nodes above from its children by
// the same rule. Every node's value is therefore computed the same way
// however the render was split, so the merged image is bit-identical to the
// render of [0, N) on the same device, for any split and any order of pieces.
// (A plain `penumbra render --spp N` keeps a running mean, a different
// summation order: it agrees within float rounding, docs/farm.md.)
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "penumbra/image/image.h"
#include "penumbra/render/path_tracer.h"

namespace penumbra::render {

// Samples [begin, end) of a render.
struct SampleRange {
  uint32_t begin = 0, end = 0;
  uint32_t count() const { return end - begin; }
  bool operator==(const SampleRange&) const = default;
};
// "A:B" -> {A, B}; throws penumbra::Error naming `flag` unless two whole
// numbers with A < B.
SampleRange parseSampleRange(const std::string& text, const char* flag);
std::string formatSampleRange(const SampleRange& range);  // "A:B"

// The block tree of a render of `totalSpp` samples in blocks of `blockSpp`.
class SampleTree {
 public:
  struct Node {
    uint32_t level = 0, index = 0;
    bool operator==(const Node&) const = default;
  };
  // Throws penumbra::Error unless 1 <= blockSpp <= 16 and 1 <= totalSpp.
  SampleTree(uint32_t totalSpp, uint32_t blockSpp);
  uint32_t totalSpp() const { return totalSpp_; }
  uint32_t blockSpp() const { return blockSpp_; }
  uint32_t blockCount() const { return blockCount_; }
  Node root() const { return {rootLevel_, 0}; }
  // Whether the node holds any block (a node past the last block does not).
  bool exists(Node node) const;
  // The blocks a node covers, [first, last), and its samples.
  std::pair<uint32_t, uint32_t> blocks(Node node) const;
  SampleRange samples(Node node) const;
  SampleRange blockSamples(uint32_t block) const;
  // Throws penumbra::Error (naming `flag`) unless the range lies in [0, N)
  // and starts and ends on block boundaries (or at N): pieces are whole
  // blocks, so each block is one GPU frame wherever it is rendered.
  void checkRange(const SampleRange& range, const char* flag) const;
  // The largest nodes that exactly cover the range's blocks, in order.
  std::vector<Node> cover(const SampleRange& range) const;
  // `pieces` near-equal block-aligned ranges that cover [0, N) (fewer if
  // there are fewer blocks); the farm's shards.
  std::vector<SampleRange> split(uint32_t pieces) const;

 private:
  uint32_t totalSpp_, blockSpp_, blockCount_, rootLevel_;
};

// The sums of one piece: the cover() nodes of its range, each a linear RGB
// sum of that node's samples (alpha unused).
struct NodeSums {
  std::vector<SampleTree::Node> nodes;
  std::vector<image::Image> sums;
};

// Renders the range's blocks with `tracer` (its camera and scene as set) and
// returns their tree sums. `progress` gets the samples done so far; `stats`,
// if given, the GPU time and rays of every frame. The tracer's accumulation
// is left holding the last block.
NodeSums renderSampleRange(PathTracer& tracer, const PathTracerSettings& settings,
                           const SampleTree& tree, const SampleRange& range,
                           const std::function<void(uint32_t)>& progress = {},
                           FrameStats* stats = nullptr);

// Adds up a render's tree from its nodes given in sample order, holding at
// most one image per tree level: the merge streams pieces through it one at
// a time. Each node is folded into its parent by the tree's rule as soon as
// its sibling arrives (or at once when it has none), so the root's value is
// the same floats added in the same order however the nodes were grouped
// into pieces. An empty image stands for samples that are missing: a parent
// of an empty child takes the other child's value.
class SampleTreeFold {
 public:
  explicit SampleTreeFold(const SampleTree& tree) : tree_(tree) {}
  // The next node: its first block must follow the last block added (throws
  // penumbra::Error otherwise).
  void add(SampleTree::Node node, image::Image sum);
  // The root's value once every block has been added (throws otherwise);
  // empty when every node was.
  image::Image result();

 private:
  struct Entry {
    SampleTree::Node node;
    image::Image sum;
  };
  const SampleTree& tree_;
  std::vector<Entry> waiting_;  // left children whose right sibling has not come yet
  uint32_t nextBlock_ = 0;
};

// sum / samples per pixel, alpha 1: the image of a merged render.
image::Image meanOf(const image::Image& sum, uint64_t samples);

}  // namespace penumbra::render
