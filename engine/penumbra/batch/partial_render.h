#pragma once
// A piece of a sample-split render (batch/sample_split.h) as a file, and
// the merge of pieces into the final image.
//
// The file is an OpenEXR image: R, G, B, A hold the mean of the piece's own
// samples (any EXR viewer shows it), and one layer per stored tree node,
// "sum.L<level>.I<index>" with R, G, B, holds that node's sum. The header's
// string attribute "penumbra.partial" is a JSON document naming the render
// (scene and settings hashes, size, seed, total samples, samples per block,
// the build), the piece (its sample range, device, nodes) and a hash of the
// sums, so a file that was changed after it was written is refused.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "penumbra/batch/render_job.h"
#include "penumbra/batch/sample_split.h"
#include "penumbra/image/image.h"
#include "penumbra/render/tone_mapping.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// What identifies one render: pieces merge only if all of it agrees.
struct SplitRenderIdentity {
  std::string sceneHash;     // scene::contentHash of the scene as rendered
  std::string settingsHash;  // splitSettingsHash
  uint32_t width = 0, height = 0;
  uint32_t seed = 0;
  uint32_t totalSpp = 0, blockSpp = 0;
  std::string build;  // the commit the renderer was built from
  bool operator==(const SplitRenderIdentity&) const = default;
};

// Everything but the scene that decides the image: every identity setting
// of the table (render_settings.h: seed, guides, samples per frame and the
// pipeline included), each fed in by its key, then the camera rendered and
// the size.
std::string splitSettingsHash(const RenderSettings& settings, const scene::Camera& camera,
                              uint32_t width, uint32_t height);

struct PartialRender {
  SplitRenderIdentity identity;
  std::string sceneName;    // for messages
  ToneMapping toneMapping;  // how a merged PNG is tone-mapped
  SampleRange range;
  std::string device;    // the adapter that rendered it
  std::string sumsHash;  // of the sums as written (content_hash.h)
  NodeSums sums;         // empty when only the description was read
};

// Atomic (a temporary file renamed into place): an interrupted write leaves
// no file that merge could take. `.exr` only.
void savePartialRender(const std::string& path, const PartialRender& piece);
// Throws penumbra::Error naming the file: not an EXR, not a partial render,
// a malformed description, layers missing or of the wrong size, sums that
// do not match their hash (a changed or damaged file), nodes that do not
// cover the range stated.
PartialRender loadPartialRender(const std::string& path);
// The piece a file describes, from its header alone (sums empty; the same
// checks on the description, none on the sums): merge looks at every piece
// before it loads any.
PartialRender loadPartialRenderDescription(const std::string& path);

struct MergedRender {
  image::Image image;       // linear RGB mean, alpha 1
  ToneMapping toneMapping;  // the piece with the first samples' (the order given does not matter)
  uint64_t samples = 0;
  std::vector<SampleRange> missing;  // empty unless merged with allowPartial
  std::vector<std::string> devices;  // the distinct devices that rendered the pieces
};
// Merges pieces (names: their files, for messages). Throws penumbra::Error
// in one line: pieces of different renders (naming the field that differs
// and both files), overlapping pieces (naming both), or, unless
// `allowPartial`, missing samples (naming the ranges). All of that is checked
// on the pieces' descriptions before any sums are read. `loadSums`, if
// given, returns piece k's sums when the merge reaches it (in sample order,
// once each, so a merge of files holds one piece at a time); otherwise the
// pieces' own sums are used.
MergedRender mergePartialRenders(const std::vector<PartialRender>& pieces,
                                 const std::vector<std::string>& names, bool allowPartial,
                                 const std::function<NodeSums(size_t)>& loadSums = {});

}  // namespace penumbra::render
