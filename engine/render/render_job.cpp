#include "render/render_job.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "util/error.h"

namespace penumbra::render {
namespace {

using nlohmann::json;

json toJson(glm::vec3 v) {
  return json::array({v.x, v.y, v.z});
}

template <class Enum>
struct Named {
  Enum value;
  const char* name;
};
constexpr Named<Integrator> kIntegrators[] = {{Integrator::Path, "path"},
                                              {Integrator::Whitted, "whitted"}};
constexpr Named<SamplingStrategy> kStrategies[] = {{SamplingStrategy::Uniform, "uniform"},
                                                   {SamplingStrategy::Cosine, "cosine"},
                                                   {SamplingStrategy::Bsdf, "bsdf"},
                                                   {SamplingStrategy::Nee, "nee"},
                                                   {SamplingStrategy::Mis, "mis"}};
constexpr Named<MisHeuristic> kHeuristics[] = {{MisHeuristic::Power, "power"},
                                               {MisHeuristic::Balance, "balance"}};

template <class Enum, size_t N>
const char* nameOf(const Named<Enum> (&table)[N], Enum value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

template <class Enum, size_t N>
std::optional<Enum> parseName(const Named<Enum> (&table)[N], std::string_view name) {
  for (const auto& entry : table)
    if (name == entry.name) return entry.value;
  return std::nullopt;
}

class Reader {
 public:
  Reader(const json& document, const std::string& source) : doc_(document), source_(source) {}

  template <class T>
  void read(const char* key, T& out) const {
    if (!doc_.contains(key)) return;
    try {
      out = doc_.at(key).get<T>();
    } catch (const json::exception&) {
      fail(key, "has the wrong type");
    }
  }
  glm::vec3 vec3(const json& value, const std::string& key) const {
    if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
        !value[2].is_number())
      fail(key, "must be an array of 3 numbers");
    return {value[0].get<float>(), value[1].get<float>(), value[2].get<float>()};
  }
  template <class Enum>
  void readEnum(const char* key, Enum& out, std::optional<Enum> (*parse)(std::string_view)) const {
    std::string name;
    read(key, name);
    if (name.empty()) return;
    auto value = parse(name);
    if (!value) fail(key, fmt::format("'{}' is not a known value", name));
    out = *value;
  }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw Error(fmt::format("{}: \"{}\" {}", source_, key, what));
  }

 private:
  const json& doc_;
  const std::string& source_;
};

}  // namespace

const char* integratorName(Integrator integrator) {
  return nameOf(kIntegrators, integrator);
}
const char* strategyName(SamplingStrategy strategy) {
  return nameOf(kStrategies, strategy);
}
const char* misHeuristicName(MisHeuristic heuristic) {
  return nameOf(kHeuristics, heuristic);
}
std::optional<Integrator> parseIntegrator(std::string_view name) {
  return parseName(kIntegrators, name);
}
std::optional<SamplingStrategy> parseStrategy(std::string_view name) {
  return parseName(kStrategies, name);
}
std::optional<MisHeuristic> parseMisHeuristic(std::string_view name) {
  return parseName(kHeuristics, name);
}

std::string renderJobToJson(const RenderJob& job) {
  json doc;
  doc["format"] = "penumbra-render";
  doc["version"] = 1;
  doc["scene"] = job.scene;
  doc["vary"] = job.vary;
  doc["set"] = job.set;
  if (job.camera) {
    doc["camera"] = {{"position", toJson(job.camera->position)},
                     {"forward", toJson(job.camera->forward)},
                     {"up", toJson(job.camera->up)},
                     {"verticalFovDegrees", job.camera->verticalFovDegrees}};
  }
  doc["width"] = job.width;
  doc["height"] = job.height;
  doc["spp"] = job.spp;
  doc["sppPerFrame"] = job.sppPerFrame;
  const auto& s = job.settings;
  doc["integrator"] = integratorName(s.integrator);
  doc["strategy"] = strategyName(s.strategy);
  doc["misHeuristic"] = misHeuristicName(s.misHeuristic);
  doc["maxDepth"] = s.maxDepth;
  doc["russianRoulette"] = s.russianRoulette;
  doc["rouletteStartDepth"] = s.rouletteStartDepth;
  doc["radianceClamp"] = s.radianceClamp;
  doc["seed"] = s.seed;
  doc["exposure"] = job.toneMapping.exposure;
  doc["toneMapping"] = toneMapOperatorName(job.toneMapping.toneOperator);
  doc["allEffects"] = job.allEffects;
  // nlohmann writes floats with max_digits10 digits: they read back exactly.
  return doc.dump(2) + "\n";
}

RenderJob renderJobFromJson(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(fmt::format("{}: not valid JSON ({})", source, e.what()));
  }
  if (!doc.is_object() || doc.value("format", "") != "penumbra-render")
    throw Error(fmt::format(
        "{}: not a penumbra render settings file (\"format\": \"penumbra-render\")", source));
  if (doc.value("version", 0) != 1)
    throw Error(fmt::format("{}: unsupported version (this build reads version 1)", source));
  Reader r(doc, source);
  RenderJob job;
  r.read("scene", job.scene);
  r.read("vary", job.vary);
  r.read("set", job.set);
  if (doc.contains("camera")) {
    const json& c = doc["camera"];
    if (!c.is_object()) r.fail("camera", "must be an object");
    scene::Camera camera;
    for (const char* key : {"position", "forward", "up"})
      if (!c.contains(key)) r.fail(std::string("camera.") + key, "is missing");
    camera.position = r.vec3(c["position"], "camera.position");
    camera.forward = r.vec3(c["forward"], "camera.forward");
    camera.up = r.vec3(c["up"], "camera.up");
    if (c.contains("verticalFovDegrees")) {
      if (!c["verticalFovDegrees"].is_number())
        r.fail("camera.verticalFovDegrees", "must be a number");
      camera.verticalFovDegrees = c["verticalFovDegrees"].get<float>();
    }
    job.camera = camera;
  }
  r.read("width", job.width);
  r.read("height", job.height);
  r.read("spp", job.spp);
  r.read("sppPerFrame", job.sppPerFrame);
  auto& s = job.settings;
  r.readEnum("integrator", s.integrator, &parseIntegrator);
  r.readEnum("strategy", s.strategy, &parseStrategy);
  r.readEnum("misHeuristic", s.misHeuristic, &parseMisHeuristic);
  r.read("maxDepth", s.maxDepth);
  r.read("russianRoulette", s.russianRoulette);
  r.read("rouletteStartDepth", s.rouletteStartDepth);
  r.read("radianceClamp", s.radianceClamp);
  r.read("seed", s.seed);
  r.read("exposure", job.toneMapping.exposure);
  r.readEnum("toneMapping", job.toneMapping.toneOperator, &parseToneMapOperator);
  r.read("allEffects", job.allEffects);
  if (job.width < 1 || job.width > 16384 || job.height < 1 || job.height > 16384)
    r.fail("width/height", "must be 1..16384");
  if (job.spp < 1) r.fail("spp", "must be at least 1");
  if (job.sppPerFrame < 1 || job.sppPerFrame > PathTracer::kMaxSamplesPerFrame)
    r.fail("sppPerFrame", "must be 1..16");
  return job;
}

void saveRenderJob(const std::string& path, const RenderJob& job) {
  std::ofstream out(path, std::ios::binary);
  out << renderJobToJson(job);
  if (!out) throw Error(fmt::format("cannot write render settings '{}'", path));
}

RenderJob loadRenderJob(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read render settings '{}'", path));
  std::stringstream text;
  text << in.rdbuf();
  return renderJobFromJson(text.str(), path);
}

}  // namespace penumbra::render
