#include "penumbra/batch/render_output.h"

#include <fmt/format.h>

#include "penumbra/render/tonemapper.h"
#include "penumbra/util/error.h"

namespace penumbra::render {

void saveRender(PathTracer& tracer, const rhi::TextureHandle& image, const std::string& path,
                const ToneMapping& toneMapping, const std::vector<image::ExrLayer>& layers) {
  if (image::formatFromPath(path) == image::FileFormat::Exr) {
    if (layers.empty())
      image::saveExr(path, tracer.readback(image));
    else
      image::saveExrLayers(path, tracer.readback(image), layers);
    return;
  }
  Tonemapper tonemapper(tracer.device());
  image::savePng(path, tonemapper.run(image, toneMapping.exposure, toneMapping.toneOperator));
}

void saveRender(rhi::IDevice* device, const image::Image& image, const std::string& path,
                const ToneMapping& toneMapping) {
  if (image::formatFromPath(path) == image::FileFormat::Exr) {
    image::saveExr(path, image);
    return;
  }
  if (!device) throw Error(fmt::format("output '{}': a PNG needs a device to tone-map on", path));
  rhi::TextureDesc desc;
  desc.width = image.width;
  desc.height = image.height;
  desc.format = rhi::Format::RGBA32_FLOAT;
  desc.usage = rhi::TextureUsage::Storage | rhi::TextureUsage::CopyDest;
  desc.debugName = "image to tone-map";
  rhi::TextureHandle texture = device->createTexture(desc);
  rhi::CommandListHandle upload = device->createCommandList("image upload");
  upload->open();
  upload->writeTexture(texture.get(), image.rgba.data(), image.rgba.size() * sizeof(float));
  upload->close();
  device->submit(upload.get());
  device->waitForIdle();
  Tonemapper tonemapper(*device);
  image::savePng(path, tonemapper.run(texture, toneMapping.exposure, toneMapping.toneOperator));
}

}  // namespace penumbra::render
