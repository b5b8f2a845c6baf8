#pragma once
// Scripted viewer sessions (--script FILE), for tests and reproducible demos.
// One command per line, '#' starts a comment:
//   wait-frames N          let N frames pass
//   wait-samples N         wait until N samples per pixel have accumulated
//   move R U F             move the camera by metres (right, world up, forward)
//   turn YAW PITCH         turn the camera by degrees (right, up)
//   reset-camera           back to the scene's camera
//   set NAME VALUE         a setting, as in viewer_settings.h ("set spp-per-frame 4")
//   scene NAME|PATH        load a built-in scene or a scene file
//   window-size W H        resize the window (the swapchain follows)
//   environment KEY VALUE  as the Environment menu: map FILE|default|none, rotation DEG,
//                          intensity X, background visible|hidden (recorded in screenshots)
//   material NAME PARAM V  edit a material as the Material menu does: PARAM is
//                          baseColor (V = R G B) or a Disney/Phong parameter
//                          ("material white roughness 0.2"); recorded in screenshots
//   screenshot PATH        the render alone: .exr (linear) or .png (tone-mapped), with
//                          PATH's .json beside it, so `penumbra render --settings` reproduces it
//   capture PATH           a .png of what the window shows: the displayed image (guide
//                          view, denoiser) with the menus when they are on
//   inject-fault SITE N    tests: the Nth device-memory allocation (SITE allocation) or
//                          submit (SITE submit) from now fails as on a full or lost GPU
//                          (rhi/fault_injection.h)
//   quit                   close the viewer (exit status 0)
#include <string>
#include <vector>

namespace penumbra::viewer {

struct ScriptCommand {
  enum class Kind {
    WaitFrames,
    WaitSamples,
    Move,
    Turn,
    ResetCamera,
    Set,
    Scene,
    WindowSize,
    Material,
    Environment,
    Screenshot,
    Capture,
    InjectFault,
    Quit
  };
  Kind kind;
  std::vector<std::string> args;  // as written; numbers already checked
  std::vector<float> numbers;     // move/turn/material: the values; wait-*: the count
  int line = 0;
};

// Throws penumbra::Error "<source>:<line>: ..." on an unknown command or bad arguments.
std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& source);
std::vector<ScriptCommand> loadScript(const std::string& path);

}  // namespace penumbra::viewer
