#include "script.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "penumbra/batch/render_job.h"
#include "penumbra/util/error.h"

namespace penumbra::viewer {

std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& source) {
  using Kind = ScriptCommand::Kind;
  struct Shape {
    const char* name;
    Kind kind;
    int numbers;  // numeric arguments, first; -1: after the words, one or more
    int words;    // free-form arguments
  };
  static const Shape kShapes[] = {{"wait-frames", Kind::WaitFrames, 1, 0},
                                  {"wait-samples", Kind::WaitSamples, 1, 0},
                                  {"move", Kind::Move, 3, 0},
                                  {"turn", Kind::Turn, 2, 0},
                                  {"reset-camera", Kind::ResetCamera, 0, 0},
                                  {"set", Kind::Set, 0, 2},
                                  {"scene", Kind::Scene, 0, 1},
                                  {"window-size", Kind::WindowSize, 2, 0},
                                  {"material", Kind::Material, -1, 2},
                                  {"environment", Kind::Environment, 0, 2},
                                  {"screenshot", Kind::Screenshot, 0, 1},
                                  {"capture", Kind::Capture, 0, 1},
                                  {"inject-fault", Kind::InjectFault, 0, 2},
                                  {"quit", Kind::Quit, 0, 0}};
  std::vector<ScriptCommand> commands;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string name;
    if (!(words >> name)) continue;
    std::vector<std::string> args;
    for (std::string w; words >> w;) args.push_back(w);
    const Shape* shape = nullptr;
    for (const auto& s : kShapes)
      if (name == s.name) shape = &s;
    auto fail = [&](const std::string& what) {
      throw Error(fmt::format("{}:{}: {}", source, number, what));
    };
    if (!shape) fail(fmt::format("unknown command '{}'", name));
    const bool variadic = shape->numbers < 0;  // the words, then one or more numbers
    const size_t expected = size_t(variadic ? shape->words + 1 : shape->numbers + shape->words);
    if (variadic ? args.size() < expected : args.size() != expected)
      fail(fmt::format("'{}' takes {}{} argument(s), got {}", name, expected,
                       variadic ? " or more" : "", args.size()));
    ScriptCommand command{shape->kind, args, {}, number};
    const size_t firstNumber = variadic ? size_t(shape->words) : 0;
    const size_t endNumber = variadic ? args.size() : size_t(shape->numbers);
    for (size_t i = firstNumber; i < endNumber; ++i) {
      size_t used = 0;
      float value = 0;
      try {
        value = std::stof(args[i], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != args[i].size() || !std::isfinite(value))
        fail(fmt::format("'{}' is not a number", args[i]));
      command.numbers.push_back(value);
    }
    if ((shape->kind == Kind::WaitFrames || shape->kind == Kind::WaitSamples ||
         shape->kind == Kind::WindowSize) &&
        (command.numbers[0] < 0 || command.numbers[0] != std::floor(command.numbers[0])))
      fail(fmt::format("'{}' needs a whole number >= 0", name));
    if (shape->kind == Kind::InjectFault) {
      if (args[0] != "allocation" && args[0] != "submit")
        fail(fmt::format("inject-fault {}: the site is allocation or submit", args[0]));
      size_t used = 0;
      unsigned long count = 0;
      try {
        count = std::stoul(args[1], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != args[1].size() || count == 0)
        fail(fmt::format("inject-fault: '{}' is not a whole number >= 1", args[1]));
    }
    // The parameter and its value count are known now; the material only
    // once the scene is loaded.
    if (shape->kind == Kind::Material) {
      scene::Material probe;
      try {
        render::setEditableParameter(probe, args[1], command.numbers);
      } catch (const Error& e) {
        fail(e.what());
      }
    }
    commands.push_back(std::move(command));
  }
  return commands;
}

std::vector<ScriptCommand> loadScript(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(fmt::format("cannot read script '{}'", path));
  std::stringstream text;
  text << in.rdbuf();
  return parseScript(text.str(), path);
}

}  // namespace penumbra::viewer
