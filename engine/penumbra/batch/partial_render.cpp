#include "penumbra/batch/partial_render.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <nlohmann/json.hpp>

#include "penumbra/image/image_io.h"
#include "penumbra/scene/json_reading.h"
#include "penumbra/util/content_hash.h"
#include "penumbra/util/error.h"

namespace penumbra::render {
namespace {

constexpr const char* kAttribute = "penumbra.partial";
constexpr const char* kFormat = "penumbra-partial";
constexpr int kVersion = 1;

std::string layerName(SampleTree::Node node) {
  return fmt::format("sum.L{}.I{}", node.level, node.index);
}

std::string sumsHash(const NodeSums& sums) {
  ContentHash h;
  for (size_t k = 0; k < sums.nodes.size(); ++k) {
    h.value(sums.nodes[k].level);
    h.value(sums.nodes[k].index);
    h.array(sums.sums[k].rgba);
  }
  return h.hex();
}

uint32_t readCount(const nlohmann::json& doc, const char* key, uint32_t lo, uint32_t hi,
                   const std::string& where) {
  return uint32_t(scene::toInteger(scene::require(doc, key, where), where, key, lo, hi));
}

}  // namespace

std::string splitSettingsHash(const RenderSettings& settings, const scene::Camera& camera,
                              uint32_t width, uint32_t height) {
  ContentHash h;
  // By name, so a setting added to the table is in the hash without another
  // line here (tests/render/test_partial_render.cpp flips each one).
  for (const Setting& setting : renderSettingsTable()) {
    if (!setting.identity) continue;
    h.text(setting.key);
    h.value(setting.get(settings));
  }
  h.value(camera.position);
  h.value(camera.forward);
  h.value(camera.up);
  for (float v : {camera.verticalFovDegrees, camera.orthographicHeight, camera.aspectRatio,
                  camera.apertureRadius, camera.focusDistance})
    h.value(v);
  h.value(camera.apertureBlades);
  h.value(width);
  h.value(height);
  return h.hex();
}

void savePartialRender(const std::string& path, const PartialRender& piece) {
  if (image::formatFromPath(path) != image::FileFormat::Exr)
    throw Error(fmt::format("output '{}': a piece of a split render is an .exr file", path));
  const auto& id = piece.identity;
  nlohmann::json doc;
  doc["format"] = kFormat;
  doc["version"] = kVersion;
  doc["scene"] = piece.sceneName;
  doc["sceneHash"] = id.sceneHash;
  doc["settingsHash"] = id.settingsHash;
  doc["width"] = id.width;
  doc["height"] = id.height;
  doc["seed"] = id.seed;
  doc["totalSpp"] = id.totalSpp;
  doc["blockSpp"] = id.blockSpp;
  doc["build"] = id.build;
  doc["exposure"] = piece.toneMapping.exposure;
  doc["toneMapping"] = toneMapOperatorName(piece.toneMapping.toneOperator);
  doc["samples"] = {piece.range.begin, piece.range.end};
  doc["device"] = piece.device;
  doc["nodes"] = nlohmann::json::array();
  for (const auto& node : piece.sums.nodes) doc["nodes"].push_back({node.level, node.index});
  doc["sumsHash"] = sumsHash(piece.sums);

  std::vector<image::ExrLayer> layers;
  for (size_t k = 0; k < piece.sums.nodes.size(); ++k)
    layers.push_back({layerName(piece.sums.nodes[k]), {"R", "G", "B"}, piece.sums.sums[k]});
  // The piece's own mean, for EXR viewers: any summation order serves.
  image::Image sum(id.width, id.height);
  for (const auto& nodeSum : piece.sums.sums)
    for (size_t i = 0; i < sum.rgba.size(); ++i) sum.rgba[i] += nodeSum.rgba[i];
  saveExrLayers(path, meanOf(sum, piece.range.count()), layers, {{kAttribute, doc.dump()}});
}

namespace {

// The piece a file's header describes (no sums), and the tree nodes its
// description lists, checked against its range; throws naming the file.
PartialRender describedPiece(const image::ExrChannels& exr, const std::string& where) {
  const std::string* text = exr.attribute(kAttribute);
  if (!text)
    throw Error(
        fmt::format("{}: not a piece of a split render (no '{}' attribute; made by "
                    "`penumbra render --samples A:B --total-spp N`)",
                    where, kAttribute));
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(*text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(fmt::format("{}: its description is not JSON ({})", where, e.what()));
  }
  if (scene::requireString(doc, "format", where) != kFormat ||
      scene::toInteger(scene::require(doc, "version", where), where, "version", 0, 1 << 30) !=
          kVersion)
    throw Error(fmt::format("{}: not a {} version {} description", where, kFormat, kVersion));

  PartialRender piece;
  auto& id = piece.identity;
  piece.sceneName = scene::requireString(doc, "scene", where);
  id.sceneHash = scene::requireString(doc, "sceneHash", where);
  id.settingsHash = scene::requireString(doc, "settingsHash", where);
  id.width = readCount(doc, "width", 1, 16384, where);
  id.height = readCount(doc, "height", 1, 16384, where);
  id.seed = readCount(doc, "seed", 0, UINT32_MAX, where);
  id.totalSpp = readCount(doc, "totalSpp", 1, kMaxSamplesPerPixel, where);
  id.blockSpp = readCount(doc, "blockSpp", 1, PathTracer::kMaxSamplesPerFrame, where);
  id.build = scene::requireString(doc, "build", where);
  piece.toneMapping.exposure = scene::requireFloat(doc, "exposure", where);
  const std::string op = scene::requireString(doc, "toneMapping", where);
  const auto parsed = parseToneMapOperator(op);
  if (!parsed) throw Error(fmt::format("{}: unknown \"toneMapping\" '{}'", where, op));
  piece.toneMapping.toneOperator = *parsed;
  piece.device = scene::requireString(doc, "device", where);
  const nlohmann::json& samples = scene::require(doc, "samples", where);
  if (!samples.is_array() || samples.size() != 2)
    throw Error(fmt::format("{}: \"samples\" is not [first, end]", where));
  piece.range = {uint32_t(scene::toInteger(samples[0], where, "samples", 0, id.totalSpp)),
                 uint32_t(scene::toInteger(samples[1], where, "samples", 0, id.totalSpp))};

  if (exr.width != id.width || exr.height != id.height)
    throw Error(fmt::format("{}: the image is {}x{}, its description says {}x{}", where, exr.width,
                            exr.height, id.width, id.height));
  const SampleTree tree(id.totalSpp, id.blockSpp);
  tree.checkRange(piece.range, where.c_str());
  const auto expected = tree.cover(piece.range);
  const nlohmann::json& nodes = scene::require(doc, "nodes", where);
  if (!nodes.is_array() || nodes.size() != expected.size())
    throw Error(fmt::format("{}: \"nodes\" do not cover samples {}", where,
                            formatSampleRange(piece.range)));
  for (size_t k = 0; k < expected.size(); ++k) {
    const nlohmann::json& n = nodes[k];
    if (!n.is_array() || n.size() != 2 ||
        SampleTree::Node{uint32_t(scene::toInteger(n[0], where, "nodes", 0, 31)),
                         uint32_t(scene::toInteger(n[1], where, "nodes", 0, UINT32_MAX))} !=
            expected[k])
      throw Error(fmt::format("{}: \"nodes\" do not cover samples {}", where,
                              formatSampleRange(piece.range)));
  }
  piece.sumsHash = scene::requireString(doc, "sumsHash", where);
  return piece;
}

}  // namespace

PartialRender loadPartialRenderDescription(const std::string& path) {
  return describedPiece(image::loadExrHeader(path), fmt::format("piece '{}'", path));
}

PartialRender loadPartialRender(const std::string& path) {
  const image::ExrChannels exr = image::loadExrChannels(path);
  const std::string where = fmt::format("piece '{}'", path);
  PartialRender piece = describedPiece(exr, where);
  const auto& id = piece.identity;
  const size_t pixels = size_t(id.width) * id.height;
  for (const SampleTree::Node& node : SampleTree(id.totalSpp, id.blockSpp).cover(piece.range)) {
    image::Image sum(id.width, id.height);
    for (size_t c = 0; c < 3; ++c) {
      const std::string channel = layerName(node) + "." + "RGB"[c];
      const std::vector<float>* values = exr.find(channel);
      if (!values || values->size() != pixels)
        throw Error(fmt::format("{}: channel '{}' is missing", where, channel));
      for (size_t i = 0; i < pixels; ++i) sum.rgba[i * 4 + c] = (*values)[i];
    }
    piece.sums.nodes.push_back(node);
    piece.sums.sums.push_back(std::move(sum));
  }
  if (sumsHash(piece.sums) != piece.sumsHash)
    throw Error(
        fmt::format("{}: its sums do not match the hash written with them (the file "
                    "was changed or damaged after it was rendered)",
                    where));
  return piece;
}

namespace {

// The first field in which two identities differ, as "<field> <a> vs <b>".
std::string difference(const SplitRenderIdentity& a, const SplitRenderIdentity& b) {
  if (a.sceneHash != b.sceneHash)
    return fmt::format("scene content {} vs {}", a.sceneHash, b.sceneHash);
  if (a.width != b.width || a.height != b.height)
    return fmt::format("size {}x{} vs {}x{}", a.width, a.height, b.width, b.height);
  if (a.seed != b.seed) return fmt::format("seed {} vs {}", a.seed, b.seed);
  if (a.totalSpp != b.totalSpp)
    return fmt::format("total samples {} vs {}", a.totalSpp, b.totalSpp);
  if (a.blockSpp != b.blockSpp)
    return fmt::format("samples per frame {} vs {}", a.blockSpp, b.blockSpp);
  if (a.settingsHash != b.settingsHash)
    return fmt::format("render settings {} vs {}", a.settingsHash, b.settingsHash);
  if (a.build != b.build) return fmt::format("build {} vs {}", a.build, b.build);
  return "";
}

}  // namespace

MergedRender mergePartialRenders(const std::vector<PartialRender>& pieces,
                                 const std::vector<std::string>& names, bool allowPartial,
                                 const std::function<NodeSums(size_t)>& loadSums) {
  if (pieces.empty()) throw Error("merge: no pieces given");
  const SplitRenderIdentity& id = pieces[0].identity;
  for (size_t k = 1; k < pieces.size(); ++k)
    if (const std::string d = difference(id, pieces[k].identity); !d.empty())
      throw Error(fmt::format("merge: '{}' and '{}' are pieces of different renders ({})", names[0],
                              names[k], d));
  std::vector<size_t> order(pieces.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return pieces[a].range.begin < pieces[b].range.begin; });
  MergedRender merged;
  merged.toneMapping = pieces[order[0]].toneMapping;
  uint32_t next = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    const SampleRange& r = pieces[order[k]].range;
    if (k > 0 && r.begin < pieces[order[k - 1]].range.end)
      throw Error(fmt::format("merge: '{}' (samples {}) and '{}' (samples {}) overlap",
                              names[order[k - 1]], formatSampleRange(pieces[order[k - 1]].range),
                              names[order[k]], formatSampleRange(r)));
    if (r.begin > next) merged.missing.push_back({next, r.begin});
    next = r.end;
  }
  if (next < id.totalSpp) merged.missing.push_back({next, id.totalSpp});
  if (!merged.missing.empty() && !allowPartial) {
    std::string list;
    for (const auto& m : merged.missing) list += (list.empty() ? "" : ", ") + formatSampleRange(m);
    throw Error(
        fmt::format("merge: samples {} of 0:{} are missing (no piece holds them; "
                    "--allow-partial merges what is there)",
                    list, id.totalSpp));
  }
  for (const auto& piece : pieces)
    if (std::find(merged.devices.begin(), merged.devices.end(), piece.device) ==
        merged.devices.end())
      merged.devices.push_back(piece.device);

  // Pieces and gaps in sample order through the fold: one piece's sums in
  // memory at a time, plus at most one waiting node per tree level.
  const SampleTree tree(id.totalSpp, id.blockSpp);
  SampleTreeFold fold(tree);
  auto addGap = [&](SampleRange gap) {
    for (const auto& node : tree.cover(gap)) fold.add(node, {});
  };
  uint32_t at = 0;
  for (size_t k : order) {
    const SampleRange& r = pieces[k].range;
    if (r.begin > at) addGap({at, r.begin});
    NodeSums sums = loadSums ? loadSums(k) : pieces[k].sums;
    const size_t values = size_t(id.width) * id.height * 4;
    if (sums.nodes != tree.cover(r) || sums.sums.size() != sums.nodes.size() ||
        std::any_of(sums.sums.begin(), sums.sums.end(),
                    [&](const image::Image& sum) { return sum.rgba.size() != values; }))
      throw Error(fmt::format("merge: '{}' does not hold the tree nodes of samples {}", names[k],
                              formatSampleRange(r)));
    for (size_t n = 0; n < sums.nodes.size(); ++n) fold.add(sums.nodes[n], std::move(sums.sums[n]));
    merged.samples += r.count();
    at = r.end;
  }
  if (at < id.totalSpp) addGap({at, id.totalSpp});
  merged.image = meanOf(fold.result(), merged.samples);
  return merged;
}

}  // namespace penumbra::render
