#pragma once
// Penumbra's render hardware interface: the API-neutral shape of buffers,
// textures, acceleration structures, pipelines, shader tables and command
// lists. Backends (backends/vulkan, backends/d3d12) implement it.
#include "rhi/command_list.h"
#include "rhi/device.h"
#include "rhi/pipeline.h"
#include "rhi/resources.h"
#include "rhi/types.h"
