#pragma once
// Penumbra's render hardware interface: the API-neutral shape of buffers,
// textures, acceleration structures, pipelines, shader tables and command
// lists. Backends (backends/vulkan, backends/d3d12) implement it.
#include "penumbra/rhi/command_list.h"
#include "penumbra/rhi/device.h"
#include "penumbra/rhi/pipeline.h"
#include "penumbra/rhi/resources.h"
#include "penumbra/rhi/types.h"
