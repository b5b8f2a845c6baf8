// `penumbra merge`: the pieces of a split render (`render --samples A:B
// --total-spp N`) into the final image (batch/partial_render.h).
#include <fmt/format.h>

#include <memory>

#include "backend_factory.h"
#include "commands.h"
#include "penumbra/batch/partial_render.h"
#include "penumbra/batch/render_output.h"
#include "penumbra/image/image_io.h"
#include "penumbra/render/shader_binding_offsets.h"
#include "penumbra/util/error.h"

namespace penumbra::app {
namespace {

struct MergeOptions {
  std::vector<std::string> pieces;
  std::string out;
  bool allowPartial = false;
  std::string backend = "vulkan";
  int device = -1;
};

int runMerge(const MergeOptions& o) {
  if (o.pieces.empty()) throw Error("merge: no pieces given");
  image::checkWritable(o.out);
  // Every piece's description first (a refusal costs no pixel reads), then
  // each piece's sums when the merge reaches it: one piece in memory at a time.
  std::vector<render::PartialRender> pieces;
  for (const auto& path : o.pieces) pieces.push_back(render::loadPartialRenderDescription(path));
  auto loadSums = [&](size_t k) {
    render::PartialRender piece = render::loadPartialRender(o.pieces[k]);
    if (!(piece.identity == pieces[k].identity && piece.range == pieces[k].range &&
          piece.sumsHash == pieces[k].sumsHash))
      throw Error(fmt::format("piece '{}': changed while it was being merged", o.pieces[k]));
    return std::move(piece.sums);
  };
  const render::MergedRender merged =
      render::mergePartialRenders(pieces, o.pieces, o.allowPartial, loadSums);
  const auto& id = pieces[0].identity;
  fmt::print("render: {} {}x{}, seed {}, {} samples in frames of {}, build {}\n",
             pieces[0].sceneName, id.width, id.height, id.seed, id.totalSpp, id.blockSpp, id.build);
  fmt::print("pieces: {}; samples merged: {} of {}\n", pieces.size(), merged.samples, id.totalSpp);
  for (const auto& missing : merged.missing)
    fmt::print("missing: samples {} (--allow-partial: the image holds the others)\n",
               render::formatSampleRange(missing));
  for (const auto& device : merged.devices) fmt::print("rendered on: {}\n", device);
  if (merged.devices.size() > 1)
    fmt::print(
        "note: pieces from {} devices agree with one device's render within float "
        "rounding, not bit for bit\n",
        merged.devices.size());
  rhi::DeviceHandle device;
  if (image::formatFromPath(o.out) == image::FileFormat::Png) {
    rhi::DeviceCreateInfo info;
    info.adapterIndex = o.device;
    info.bindingOffsets = render::kShaderBindingOffsets;
    device = backends::createDevice(o.backend, info);
  }
  render::saveRender(device.get(), merged.image, o.out, merged.toneMapping);
  fmt::print("wrote {}\n", o.out);
  return 0;
}

}  // namespace

Command addMergeCommand(CLI::App& app) {
  auto o = std::make_shared<MergeOptions>();
  auto* cmd = app.add_subcommand(
      "merge", "Merge the pieces of a split render (render --samples A:B) into the final image");
  cmd->add_option("pieces", o->pieces, "Pieces (.exr) written by render --samples, in any order")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->out,
                  "Final image: .exr (linear float) or .png (tone-mapped as the render asked)")
      ->required();
  cmd->add_flag("--allow-partial", o->allowPartial,
                "Merge the samples present when some are missing (and say which)");
  cmd->add_option("--backend", o->backend, "Backend that tone-maps a .png: vulkan | d3d12")
      ->capture_default_str();
  cmd->add_option("--device", o->device, "Adapter index that tone-maps a .png (-1 = default)")
      ->capture_default_str();
  return [o] { return runMerge(*o); };
}

}  // namespace penumbra::app
