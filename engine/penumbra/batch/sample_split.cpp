#include "penumbra/batch/sample_split.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <map>

#include "penumbra/util/error.h"

namespace penumbra::render {

SampleRange parseSampleRange(const std::string& text, const char* flag) {
  const size_t colon = text.find(':');
  auto whole = [&](std::string_view s, uint32_t& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && end == s.data() + s.size();
  };
  SampleRange r;
  if (colon == std::string::npos || !whole(std::string_view(text).substr(0, colon), r.begin) ||
      !whole(std::string_view(text).substr(colon + 1), r.end) || r.begin >= r.end)
    throw Error(
        fmt::format("{} '{}': expected FIRST:END, two whole numbers with FIRST < END "
                    "(samples FIRST to END - 1)",
                    flag, text));
  return r;
}

std::string formatSampleRange(const SampleRange& range) {
  return fmt::format("{}:{}", range.begin, range.end);
}

SampleTree::SampleTree(uint32_t totalSpp, uint32_t blockSpp)
    : totalSpp_(totalSpp), blockSpp_(blockSpp) {
  if (blockSpp < 1 || blockSpp > PathTracer::kMaxSamplesPerFrame)
    throw Error(fmt::format("samples per block (frame) {} is outside 1..{}", blockSpp,
                            PathTracer::kMaxSamplesPerFrame));
  if (totalSpp < 1) throw Error("a render needs at least one sample per pixel");
  blockCount_ = uint32_t((uint64_t(totalSpp) + blockSpp - 1) / blockSpp);
  rootLevel_ = 0;
  while ((uint64_t(1) << rootLevel_) < blockCount_) ++rootLevel_;
}

bool SampleTree::exists(Node node) const {
  return node.level <= rootLevel_ && (uint64_t(node.index) << node.level) < blockCount_;
}

std::pair<uint32_t, uint32_t> SampleTree::blocks(Node node) const {
  const uint64_t first = uint64_t(node.index) << node.level;
  const uint64_t last = std::min<uint64_t>(first + (uint64_t(1) << node.level), blockCount_);
  return {uint32_t(first), uint32_t(last)};
}

SampleRange SampleTree::blockSamples(uint32_t block) const {
  return {block * blockSpp_,
          uint32_t(std::min<uint64_t>(uint64_t(block + 1) * blockSpp_, totalSpp_))};
}

SampleRange SampleTree::samples(Node node) const {
  if (!exists(node))
    throw Error(fmt::format("sample tree: node {}.{} holds no block of {}", node.level, node.index,
                            blockCount_));
  const auto [first, last] = blocks(node);
  return {blockSamples(first).begin, blockSamples(last - 1).end};
}

void SampleTree::checkRange(const SampleRange& range, const char* flag) const {
  if (range.begin >= range.end || range.end > totalSpp_)
    throw Error(fmt::format("{} {}: not a range of samples within 0:{}", flag,
                            formatSampleRange(range), totalSpp_));
  if (range.begin % blockSpp_ != 0 || (range.end % blockSpp_ != 0 && range.end != totalSpp_))
    throw Error(fmt::format(
        "{} {}: pieces start and end on multiples of the samples per frame ({}), or at the "
        "total ({})",
        flag, formatSampleRange(range), blockSpp_, totalSpp_));
}

std::vector<SampleTree::Node> SampleTree::cover(const SampleRange& range) const {
  checkRange(range, "samples");
  uint32_t p = range.begin / blockSpp_;
  const uint32_t q = range.end == totalSpp_ ? blockCount_ : range.end / blockSpp_;
  std::vector<Node> nodes;
  while (p < q) {
    uint32_t level = 0;
    // Grow while the next level's node starts at p and ends within q.
    while (level < rootLevel_ && p % (uint64_t(2) << level) == 0 &&
           std::min<uint64_t>(p + (uint64_t(2) << level), blockCount_) <= q)
      ++level;
    nodes.push_back({level, p >> level});
    p = blocks(nodes.back()).second;
  }
  return nodes;
}

std::vector<SampleRange> SampleTree::split(uint32_t pieces) const {
  if (pieces < 1) throw Error("a render splits into at least one piece");
  const uint32_t n = std::min(pieces, blockCount_);
  std::vector<SampleRange> ranges;
  for (uint32_t k = 0; k < n; ++k) {
    const uint32_t first = uint32_t(uint64_t(k) * blockCount_ / n);
    const uint32_t last = uint32_t(uint64_t(k + 1) * blockCount_ / n);
    ranges.push_back({blockSamples(first).begin, blockSamples(last - 1).end});
  }
  return ranges;
}

namespace {

// The tree's one addition: per channel, in float, RGB only (alpha stays 0).
void addInto(image::Image& sum, const image::Image& other) {
  for (size_t i = 0; i < sum.rgba.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) sum.rgba[i + c] += other.rgba[i + c];
}

image::Image renderNode(PathTracer& tracer, const PathTracerSettings& settings,
                        const SampleTree& tree, SampleTree::Node node, uint32_t& done,
                        const std::function<void(uint32_t)>& progress, FrameStats& stats) {
  if (node.level == 0) {
    const SampleRange block = tree.blockSamples(node.index);
    tracer.startNewMean(block.begin);
    const FrameStats frame = tracer.renderFrame(settings, block.count());
    stats.gpuSeconds += frame.gpuSeconds;
    stats.rays += frame.rays;
    stats.samples += frame.samples;
    image::Image sum = tracer.readback();
    const float count = float(block.count());
    for (size_t i = 0; i < sum.rgba.size(); i += 4) {
      for (size_t c = 0; c < 3; ++c) sum.rgba[i + c] *= count;
      sum.rgba[i + 3] = 0.0f;
    }
    done += block.count();
    if (progress) progress(done);
    return sum;
  }
  image::Image sum =
      renderNode(tracer, settings, tree, {node.level - 1, node.index * 2}, done, progress, stats);
  const SampleTree::Node right{node.level - 1, node.index * 2 + 1};
  if (tree.exists(right))
    addInto(sum, renderNode(tracer, settings, tree, right, done, progress, stats));
  return sum;
}

}  // namespace

NodeSums renderSampleRange(PathTracer& tracer, const PathTracerSettings& settings,
                           const SampleTree& tree, const SampleRange& range,
                           const std::function<void(uint32_t)>& progress, FrameStats* stats) {
  NodeSums result;
  result.nodes = tree.cover(range);
  uint32_t done = 0;
  FrameStats totals;
  for (const auto& node : result.nodes)
    result.sums.push_back(renderNode(tracer, settings, tree, node, done, progress, totals));
  if (stats) *stats = totals;
  return result;
}

void SampleTreeFold::add(SampleTree::Node node, image::Image sum) {
  if (!tree_.exists(node) || tree_.blocks(node).first != nextBlock_)
    throw Error(fmt::format("sample tree: node {}.{} does not follow block {}", node.level,
                            node.index, nextBlock_));
  nextBlock_ = tree_.blocks(node).second;
  const SampleTree::Node root = tree_.root();
  while (node != root) {
    const SampleTree::Node parent{node.level + 1, node.index / 2};
    if (node.index % 2 == 1) {
      // A right child: nodes arrive in block order and fold as soon as they
      // can, so the newest waiting entry is its left sibling.
      if (waiting_.empty() || waiting_.back().node != SampleTree::Node{node.level, node.index - 1})
        throw Error(fmt::format("sample tree: node {}.{} came without its left sibling", node.level,
                                node.index));
      Entry left = std::move(waiting_.back());
      waiting_.pop_back();
      if (left.sum.rgba.empty()) {
        // the right child's value stands
      } else if (sum.rgba.empty()) {
        sum = std::move(left.sum);
      } else {
        addInto(left.sum, sum);
        sum = std::move(left.sum);
      }
    } else if (tree_.exists({node.level, node.index + 1})) {
      break;  // wait for the right sibling
    }
    node = parent;
  }
  waiting_.push_back({node, std::move(sum)});
}

image::Image SampleTreeFold::result() {
  if (nextBlock_ != tree_.blockCount() || waiting_.size() != 1)
    throw Error(
        fmt::format("sample tree: blocks {} to {} were not added", nextBlock_, tree_.blockCount()));
  return std::move(waiting_.back().sum);
}

image::Image meanOf(const image::Image& sum, uint64_t samples) {
  image::Image mean = sum;
  const float n = float(samples);
  for (size_t i = 0; i < mean.rgba.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) mean.rgba[i + c] = sum.rgba[i + c] / n;
    mean.rgba[i + 3] = 1.0f;
  }
  return mean;
}

}  // namespace penumbra::render
