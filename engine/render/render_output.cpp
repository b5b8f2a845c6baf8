#include "render/render_output.h"

#include "render/tonemapper.h"

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

}  // namespace penumbra::render
