#pragma once
// The one way a rendered image becomes a file, for `penumbra render` and the
// viewer's screenshots: by the path's extension, a linear EXR (with AOV
// layers beside the beauty image when given) or a tone-mapped PNG (the
// tone-mapping pass, as the viewer displays it). Both writes are atomic
// (image_io.h): a failure leaves no partial file.
#include <string>
#include <vector>

#include "penumbra/image/image_io.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/render/tone_mapping.h"

namespace penumbra::render {

// `image`: the tracer's accumulation or a denoiser's output, on the tracer's device.
void saveRender(PathTracer& tracer, const rhi::TextureHandle& image, const std::string& path,
                const ToneMapping& toneMapping, const std::vector<image::ExrLayer>& layers = {});
// The same for an image on the host (a merged split render): a PNG is
// tone-mapped by the same pass on `device`, which an EXR does not need.
void saveRender(rhi::IDevice* device, const image::Image& image, const std::string& path,
                const ToneMapping& toneMapping);

}  // namespace penumbra::render
