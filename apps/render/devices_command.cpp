#include <fmt/format.h>

#include "backend_factory.h"
#include "commands.h"

namespace penumbra::app {

Command addDevicesCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("devices", "List devices and their ray-tracing support");
  auto backend = std::make_shared<std::string>("vulkan");
  cmd->add_option("--backend", *backend, "Backend: vulkan | d3d12")->capture_default_str();
  return [backend] {
    auto adapters = backends::listAdapters(*backend);
    if (adapters.empty()) fmt::print("no {} devices\n", *backend);
    for (const auto& a : adapters) {
      fmt::print("{}: {} ({}, {}, {})\n", a.index, a.name, rhi::adapterTypeName(a.type), a.apiVersion,
                 a.driver);
      fmt::print("   ray tracing pipeline: {}  acceleration structure: {}  ray query: {}\n",
                 a.rayTracingPipeline ? "yes" : "no", a.accelerationStructure ? "yes" : "no",
                 a.rayQuery ? "yes" : "no");
      if (a.supportsRayTracing())
        fmt::print("   max recursion {}, shader handle {} B, record align {} B, table align {} B\n",
                   a.maxRecursionDepth, a.shaderTable.handleSize, a.shaderTable.recordAlignment,
                   a.shaderTable.tableAlignment);
    }
    return 0;
  };
}

}  // namespace penumbra::app
