// `penumbra study`: what accuracy costs in time, for one scene on one
// device (engine/study, docs/ARCHITECTURE.md "Studies").
#include <fmt/format.h>
#ifdef _WIN32
#include <process.h>
#else
#include <unistd.h>
#endif

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "backend_factory.h"
#include "commands.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/batch/sample_split.h"
#include "penumbra/image/image_io.h"
#include "penumbra/scene/json_reading.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/study/study_analysis.h"
#include "penumbra/study/study_results.h"
#include "penumbra/study/study_runner.h"
#include "penumbra/util/error.h"
#include "penumbra_commit.h"
#include "progress.h"

namespace penumbra::app {
namespace {

struct StudyOptions {
  SceneOptions scene{"cornell-box", "64x64"};
  std::string spp = "1,4,16,64";
  // Each study axis's comma-separated values, by settings key
  // (study::studyAxes(): --integrator, --max-depth, --pipeline, ...).
  std::map<std::string, std::string> axes;
  uint32_t seeds = 3;
  uint32_t firstSeed = 1;
  uint32_t repeats = 3;
  std::string reference;
  uint32_t referenceSpp = 1024;
  uint32_t referenceSeed = 1000003;
  uint32_t referenceMaxDepth = 64;
  double budgetMs = 33.3;
  double targetRelMse = 0.0;
  std::string out;
  std::string analyze;
  DeviceOptions device;
  // A study split into jobs (docs/farm.md): the reference alone, a range of
  // points, or the gathering of the parts' rows into the results.
  bool referenceOnly = false;
  std::string points;  // "A:B"
  bool gather = false;
  bool countPoints = false;
};

// A comma-separated list, each item through `parse`; one line naming the
// flag and the item otherwise.
template <class T, class Parse>
std::vector<T> parseList(const std::string& flag, const std::string& text, Parse parse,
                         const char* expected) {
  std::vector<T> values;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::optional<T> v = parse(item);
    if (!v) throw Error(fmt::format("{} '{}': '{}' is not {}", flag, text, item, expected));
    values.push_back(*v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

std::optional<double> parseNumber(const std::string& s) {
  size_t used = 0;
  try {
    const double v = std::stod(s, &used);
    if (used == s.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::optional<uint32_t> parseCount(const std::string& s, uint32_t lo, uint32_t hi) {
  const auto v = parseNumber(s);
  if (!v || *v != std::floor(*v) || *v < lo || *v > hi) return std::nullopt;
  return uint32_t(*v);
}

study::StudySpec makeSpec(const StudyOptions& o) {
  study::StudySpec spec;
  spec.spp = parseList<uint32_t>(
      "--spp", o.spp, [](const std::string& s) { return parseCount(s, 1, 1u << 20); },
      "a sample count 1..1048576");
  // The technique axes: the settings table's entries, their names and ranges.
  for (const study::StudyAxis& axis : study::studyAxes()) {
    const auto given = o.axes.find(std::string(axis.setting->key));
    if (given == o.axes.end()) continue;
    std::string expected = axis.setting->expected();
    if (axis.setting->type == render::SettingType::Flag)
      expected = fmt::format("{} or {}", axis.onWord, axis.offWord);
    spec.sweepValues(
        axis.setting->key,
        parseList<double>(
            fmt::format("--{}", axis.option), given->second,
            [&](const std::string& item) { return axis.parse(item); }, expected.c_str()));
  }
  spec.seeds = o.seeds;
  spec.firstSeed = o.firstSeed;
  return spec;
}

// "mean +- half-width", scaled by `scale` (100 for percent); the mean alone
// with one seed.
std::string ci(const study::Estimate& e, const char* format, double scale = 1.0,
               const char* unit = "") {
  const std::string mean = fmt::format(fmt::runtime(format), e.mean * scale) + unit;
  if (!std::isfinite(e.halfWidth)) return mean;
  return mean + " +- " + fmt::format(fmt::runtime(format), std::abs(e.halfWidth * scale)) + unit;
}

// The answers, printed: the summaries, the Pareto front, the budget and
// target-error answers, the convergence slopes and the biases.
void printAnswers(const std::vector<study::PointSummary>& points, double budgetMs,
                  double targetRelMse) {
  fmt::print("{:<28} {:>6} {:>10} {:>24} {:>22} {:>7} {:>12}\n", "technique", "spp", "GPU ms",
             "relMSE (95% CI)", "bias (95% CI)", "SSIM", "1/(relMSE ms)");
  for (const auto& p : points)
    fmt::print("{:<28} {:>6} {:>10.3f} {:>24} {:>22} {:>7.4f} {:>12.4g}\n", p.technique, p.spp,
               p.gpuMs.mean, ci(p.relMse, "{:.3e}"), ci(p.bias, "{:.2f}", 100.0, "%"), p.ssim.mean,
               p.efficiency());
  auto name = [&](size_t i) {
    return fmt::format("{} at {} spp ({:.3f} ms, relMSE {:.3e})", points[i].technique,
                       points[i].spp, points[i].gpuMs.mean, points[i].relMse.mean);
  };
  fmt::print("Pareto front (no other point both faster and lower in error):\n");
  for (size_t i : study::paretoFront(points)) fmt::print("  {}\n", name(i));
  if (auto best = study::bestWithinBudget(points, budgetMs))
    fmt::print("within {:g} ms: the lowest error is {}\n", budgetMs, name(*best));
  else
    fmt::print("within {:g} ms: no point of the study fits\n", budgetMs);
  if (targetRelMse > 0) {
    if (auto fastest = study::fastestForError(points, targetRelMse))
      fmt::print("relMSE <= {:g}: the fastest is {}\n", targetRelMse, name(*fastest));
    else
      fmt::print("relMSE <= {:g}: no point of the study reaches it\n", targetRelMse);
  }
  fmt::print("convergence, relMSE ~ spp^slope (-1: unbiased Monte Carlo; flatter: bias left):\n");
  for (const auto& s : study::convergenceSlopes(points))
    fmt::print("  {:<28} slope {:+.3f} over {} spp values\n", s.technique, s.slope, s.points);
  // The bias at each technique's largest spp, where noise hides it least.
  for (const auto& p : points) {
    bool largest = true;
    for (const auto& q : points)
      if (q.technique == p.technique && q.spp > p.spp) largest = false;
    if (largest && p.bias.excludesZero())
      fmt::print("biased: {} at {} spp: mean {:+.3f}% +- {:.3f}% (95% CI excludes 0)\n",
                 p.technique, p.spp, 100.0 * p.bias.mean, 100.0 * p.bias.halfWidth);
  }
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("{}: cannot read", path));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Removes what a study wrote if it fails before its results are complete:
// no partial output is left behind.
class OutputGuard {
 public:
  void add(const std::filesystem::path& p) { written_.push_back(p); }
  void keep() { written_.clear(); }
  ~OutputGuard() {
    std::error_code ignored;
    for (const auto& p : written_) std::filesystem::remove(p, ignored);
  }

 private:
  std::vector<std::filesystem::path> written_;
};

// report.html's previews: the centre of each image at full resolution, so a
// 1080p study's folder stays a few megabytes and its noise looks as rendered.
constexpr uint32_t kPreviewMaxWidth = 256;

void savePreview(const std::filesystem::path& path, const image::Image& image) {
  image::savePng(path.string(), image::encodeSrgb8(image::centreCrop(image, kPreviewMaxWidth)));
}

// The plots and report.html (scripts/study_report.py), when Python with
// matplotlib is there; otherwise how to make them.
void makeReport(const std::string& dir) {
  const std::string script = PENUMBRA_SOURCE_DIR "/scripts/study_report.py";
  const std::string how = fmt::format(
      "report: python3 {} {} makes the plots and report.html (needs python3-matplotlib)", script,
      dir);
#ifdef _WIN32
  fmt::print("{}\n", how);
#else
  if (!std::filesystem::exists(script)) {
    fmt::print("report: {} is not here (run it from a Penumbra checkout on {})\n", script, dir);
    return;
  }
  // Debian's interpreter has python3-matplotlib; one earlier on PATH may not.
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    const std::string probe = fmt::format("{} -c 'import matplotlib' >/dev/null 2>&1", python);
    if (std::system(probe.c_str()) != 0) continue;
    const std::string run = fmt::format("{} '{}' '{}'", python, script, dir);
    std::fflush(stdout);
    if (std::system(run.c_str()) != 0) fmt::print("report: {} failed\n", run);
    return;
  }
  fmt::print("{}\n", how);
#endif
}

uint32_t referenceSppOf(const StudyOptions& o) {
  return (o.referenceSpp + 1) / 2 * 2;
}

// What a cached reference was rendered from (DIR/reference.txt's first line).
std::string referenceKey(const StudyOptions& o) {
  const auto [width, height] = parseImageSize(o.scene.size);
  return fmt::format("{} {}x{} {} spp seed {} depth {}", o.scene.scene, width, height,
                     referenceSppOf(o), o.referenceSeed, o.referenceMaxDepth);
}

// The reference cached in DIR for these options, if any. A cache whose
// noise line is damaged is stale, not an error: it is rendered again.
std::optional<study::Reference> cachedReference(const StudyOptions& o,
                                                const std::filesystem::path& dir) {
  const auto cachedImage = dir / "reference.exr", cachedKey = dir / "reference.txt";
  if (!std::filesystem::exists(cachedImage) || !std::filesystem::exists(cachedKey)) return {};
  const std::string cached = readFile(cachedKey.string()), key = referenceKey(o);
  if (cached.rfind(key + "\n", 0) != 0) return {};
  std::string noise = cached.substr(key.size() + 1);
  if (!noise.empty() && noise.back() == '\n') noise.pop_back();
  const std::optional<double> noiseRelMse = parseNumber(noise);
  if (!noiseRelMse) return {};
  study::Reference reference;
  reference.image = image::loadExr(cachedImage.string());
  reference.source = cachedImage.string() + " (cached)";
  reference.spp = referenceSppOf(o);
  reference.seed = o.referenceSeed;
  reference.noiseRelMse = *noiseRelMse;
  return reference;
}

// Written whole or not at all (a killed job leaves no half file).
void writeAtomically(const std::filesystem::path& path, const std::string& text) {
  // Unique per host and process: a requeued task may still run elsewhere.
  char host[256] = "host";
#ifdef _WIN32
  const long pid = _getpid();
#else
  gethostname(host, sizeof host - 1);
  const long pid = getpid();
#endif
  const std::filesystem::path tmp = fmt::format("{}.tmp-{}-{}", path.string(), host, pid);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.good()) throw Error(fmt::format("{}: cannot write it", path.string()));
  }
  std::filesystem::rename(tmp, path);
}

study::StudyContext studyContext(const StudyOptions& o, uint32_t width, uint32_t height,
                                 const study::Reference& reference) {
  study::StudyContext context;
  context.scene = o.scene.scene;
  context.width = width;
  context.height = height;
  context.commit = PENUMBRA_COMMIT;
  context.referenceSource = reference.source;
  context.referenceSpp = reference.spp;
  context.referenceSeed = reference.seed;
  context.referenceNoiseRelMse = reference.noiseRelMse;
  context.budgetMs = o.budgetMs;
  return context;
}

// results.csv, results.json, the answers and the report.
void writeResults(const StudyOptions& o, const std::filesystem::path& dir,
                  const study::StudyContext& context, const std::vector<study::StudyRow>& rows,
                  OutputGuard& written) {
  std::vector<study::Measurement> measurements;
  for (const auto& r : rows) measurements.push_back(study::measurement(r));
  const auto summaries = study::summarize(measurements);
  const auto csvPath = dir / "results.csv", jsonPath = dir / "results.json";
  std::ofstream(csvPath) << study::resultsCsv(rows);
  written.add(csvPath);
  std::ofstream(jsonPath) << study::resultsJson(context, rows, summaries);
  written.add(jsonPath);
  if (context.referenceNoiseRelMse >= 0)
    fmt::print(
        "reference: {}, {} spp (seeds {} and {}), its own relMSE about {:.3e}: errors "
        "below twice that are not claimed (below_reference_noise)\n",
        context.referenceSource, context.referenceSpp, context.referenceSeed,
        context.referenceSeed + 1, context.referenceNoiseRelMse);
  else
    fmt::print("reference: {} (its own noise unknown)\n", context.referenceSource);
  printAnswers(summaries, o.budgetMs, o.targetRelMse);
  written.keep();
  fmt::print("wrote {} and {} ({} rows), images in {}\n", csvPath.string(), jsonPath.string(),
             rows.size(), (dir / "images").string());
  makeReport(o.out);
}

// --gather: the parts' rows (DIR/points/points-A-B.csv), every point of the
// study exactly once and all measured on one device with one build, into
// the results a single run writes.
int gatherStudy(const StudyOptions& o, const std::vector<study::StudyPoint>& points,
                const std::filesystem::path& dir, study::Reference reference) {
  const auto [width, height] = parseImageSize(o.scene.size);
  if (!o.reference.empty()) {
    // Given by the user: already loaded and checked by runStudy.
  } else if (std::optional<study::Reference> cached = cachedReference(o, dir)) {
    reference = std::move(*cached);
  } else {
    throw Error(fmt::format("study --gather: '{}' holds no reference for this study", o.out));
  }
  std::vector<std::filesystem::path> parts;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "points", ec))
    if (entry.path().extension() == ".csv") parts.push_back(entry.path());
  std::sort(parts.begin(), parts.end());
  if (parts.empty())
    throw Error(fmt::format("study --gather: no parts in '{}' (run the study with --points A:B)",
                            (dir / "points").string()));
  std::vector<std::optional<study::StudyRow>> rows(points.size());
  std::vector<std::string> from(points.size());
  study::StudyContext context = studyContext(o, width, height, reference);
  std::string firstPart;
  for (const auto& part : parts) {
    const std::string source = part.string();
    nlohmann::json where;
    try {
      where = nlohmann::json::parse(
          readFile((part.parent_path() / (part.stem().string() + ".json")).string()));
    } catch (const nlohmann::json::exception& e) {
      throw Error(fmt::format("{}: its .json beside it is unreadable ({})", source, e.what()));
    }
    const std::string device = scene::requireString(where, "device", source + " (.json)");
    const std::string commit = scene::requireString(where, "commit", source + " (.json)");
    if (firstPart.empty()) {
      firstPart = source;
      context.device = device;
      context.api = scene::requireString(where, "api", source + " (.json)");
      context.backend = scene::requireString(where, "backend", source + " (.json)");
      context.commit = commit;
    } else if (device != context.device || commit != context.commit) {
      throw Error(
          fmt::format("study --gather: '{}' was measured on {} (build {}), '{}' on {} "
                      "(build {}): times of different devices or builds do not compare",
                      firstPart, context.device, context.commit, source, device, commit));
    }
    for (study::StudyRow& row : study::parseStudyRows(readFile(source), source, points)) {
      size_t i = 0;
      while (!(points[i].spp == row.point.spp && points[i].seed == row.point.seed &&
               points[i].technique == row.point.technique))
        ++i;
      if (rows[i])
        throw Error(fmt::format(
            "study --gather: '{}' and '{}' both hold '{}' at {} spp, seed {} "
            "(a part of an earlier split? remove the stale one)",
            from[i], source, row.point.technique.label(), row.point.spp, row.point.seed));
      rows[i] = std::move(row);
      from[i] = source;
    }
  }
  std::vector<study::StudyRow> ordered;
  size_t missing = 0;
  std::string firstMissing;
  for (size_t i = 0; i < points.size(); ++i) {
    if (rows[i]) {
      ordered.push_back(*rows[i]);
    } else if (missing++ == 0) {
      firstMissing = fmt::format("point {}: '{}' at {} spp, seed {}", i,
                                 points[i].technique.label(), points[i].spp, points[i].seed);
    }
  }
  if (missing > 0)
    throw Error(
        fmt::format("study --gather: {} of {} points have no row (the first: {}); run "
                    "their --points and gather again",
                    missing, points.size(), firstMissing));
  fmt::print("gathered {} rows from {} parts, measured on {} (build {})\n", ordered.size(),
             parts.size(), context.device, context.commit);
  if (!reference.image.rgba.empty()) {
    const auto preview = dir / "reference.png";
    savePreview(preview, reference.image);
  }
  OutputGuard written;
  writeResults(o, dir, context, ordered, written);
  return 0;
}

// The --reference image, checked against the study's size; without one,
// the seeds the rendered reference would use are checked against the points'.
study::Reference givenReference(const StudyOptions& o, const study::StudySpec& spec, uint32_t width,
                                uint32_t height) {
  study::Reference reference;
  if (o.reference.empty()) {
    study::checkReferenceIndependence(spec, o.referenceSeed);
    return reference;
  }
  reference.image = image::loadExr(o.reference);
  reference.source = o.reference;
  if (reference.image.width != width || reference.image.height != height)
    throw Error(fmt::format("--reference '{}': {}x{}, the study renders {}x{}", o.reference,
                            reference.image.width, reference.image.height, width, height));
  return reference;
}

// The rendered reference: cached beside the results (the same scene, size,
// samples and seed render the same reference), or rendered and cached now.
study::Reference renderOrCachedReference(const StudyOptions& o, const std::filesystem::path& dir,
                                         study::StudyRunner& runner,
                                         const std::function<void(uint32_t)>& report) {
  if (std::optional<study::Reference> cached = cachedReference(o, dir)) return std::move(*cached);
  // The parts of a split study share one reference, rendered once
  // before them (--reference-only): they never race to write it.
  if (!o.points.empty())
    throw Error(
        fmt::format("study --points: '{}' holds no reference for this study yet; run "
                    "the same study with --reference-only first",
                    o.out));
  study::Technique referenceTechnique;
  referenceTechnique.settings.tracer.maxDepth = o.referenceMaxDepth;
  study::Reference reference =
      runner.renderReference(referenceTechnique, referenceSppOf(o), o.referenceSeed, report);
  const auto cachedImage = dir / "reference.exr", cachedKey = dir / "reference.txt";
  image::saveExr(cachedImage.string(), reference.image);
  writeAtomically(cachedKey, fmt::format("{}\n{:.17g}\n", referenceKey(o), reference.noiseRelMse));
  return reference;
}

// Measures points first..end-1 against the reference; the first seed's
// image of each point is kept (linear, and a preview for the report).
template <class Report>
std::vector<study::StudyRow> measurePoints(study::StudyRunner& runner,
                                           const std::vector<study::StudyPoint>& points,
                                           size_t first, size_t end, const study::StudySpec& spec,
                                           const study::Reference& reference,
                                           const std::filesystem::path& dir, OutputGuard& written,
                                           const Report& report, uint64_t done) {
  std::vector<study::StudyRow> rows;
  for (size_t i = first; i < end; ++i) {
    const study::StudyPoint& point = points[i];
    rows.push_back(runner.run(point, reference, report(done)));
    done += point.spp;
    if (point.seed == spec.firstSeed) {
      const std::string name = study::imageName(point.technique.label(), point.spp);
      const auto exr = dir / "images" / (name + ".exr"), png = dir / "images" / (name + ".png");
      image::saveExr(exr.string(), runner.lastImage());
      written.add(exr);
      savePreview(png, runner.lastImage());
      written.add(png);
    }
  }
  return rows;
}

// A part of a split study: its rows and where they were measured, for --gather.
int writePart(const std::filesystem::path& dir, const study::StudyContext& context, size_t first,
              size_t end, const std::vector<study::StudyRow>& rows, OutputGuard& written) {
  const auto part = dir / "points" / fmt::format("points-{}-{}", first, end);
  std::filesystem::create_directories(part.parent_path());
  nlohmann::json where;
  where["device"] = context.device;
  where["api"] = context.api;
  where["backend"] = context.backend;
  where["commit"] = context.commit;
  writeAtomically(part.string() + ".json", where.dump(2) + "\n");
  writeAtomically(part.string() + ".csv", study::resultsCsv(rows));
  written.keep();
  fmt::print("wrote {}.csv ({} rows; `penumbra study ... --gather` makes the results)\n",
             part.string(), rows.size());
  return 0;
}

int runStudy(const StudyOptions& o, const CLI::App& cmd) {
  if (!o.analyze.empty()) {
    const auto rows = study::parseResultsCsv(readFile(o.analyze), o.analyze);
    printAnswers(study::summarize(rows), o.budgetMs, o.targetRelMse);
    return 0;
  }
  if (o.out.empty()) throw Error("study: --out DIR is required (where the results go)");
  if (!(o.budgetMs > 0)) throw Error("--budget-ms: must be > 0");
  if (cmd.count("--reference") && cmd.count("--reference-spp"))
    throw Error("study: --reference and --reference-spp exclude each other");
  // Everything that can fail on bad input fails before any rendering starts.
  const study::StudySpec spec = makeSpec(o);
  const std::vector<study::StudyPoint> points = study::expandStudy(spec);
  const auto [width, height] = parseImageSize(o.scene.size);
  // A scene without light is lit as `render` lights it (the default environment).
  const scene::Scene scene = [&] {
    scene::Scene loaded = scene::loadScene(o.scene.scene);
    render::applyEnvironmentChoice(loaded, {});
    return loaded;
  }();
  study::Reference reference = givenReference(o, spec, width, height);
  if (int(!o.points.empty()) + int(o.referenceOnly) + int(o.gather) > 1)
    throw Error("study: --points, --reference-only and --gather exclude each other");
  if (o.referenceOnly && !o.reference.empty())
    throw Error("study --reference-only: --reference names a reference already");
  if (o.countPoints) {  // for `penumbra farm study`, which splits the points
    fmt::print("{}\n", points.size());
    return 0;
  }
  const std::filesystem::path dir(o.out);
  std::error_code ec;
  std::filesystem::create_directories(dir / "images", ec);
  if (ec) throw Error(fmt::format("--out '{}': cannot create it ({})", o.out, ec.message()));
  if (o.gather) return gatherStudy(o, points, dir, reference);
  // The points this run renders: all, or a part of a split study.
  size_t first = 0, end = points.size();
  if (!o.points.empty()) {
    const render::SampleRange range = render::parseSampleRange(o.points, "--points");
    if (range.end > points.size())
      throw Error(fmt::format("--points {}: the study has points 0:{}", o.points, points.size()));
    first = range.begin;
    end = range.end;
  }
  OutputGuard written;

  auto device = backends::createDevice(o.device.backend, o.device.createInfo());
  const auto& adapter = device->adapter();
  fmt::print("device: {} ({}) via {}; commit {}\n", adapter.name, adapter.apiVersion,
             device->backendName(), PENUMBRA_COMMIT);
  fmt::print("scene: {}, {}x{}; {} points ({} techniques x {} spp values x {} seeds){}\n",
             scene.name, width, height, points.size(), points.size() / spec.spp.size() / spec.seeds,
             spec.spp.size(), spec.seeds,
             o.points.empty() ? "" : fmt::format("; this part: points {}", o.points));
  std::fflush(stdout);

  study::StudyRunner runner(*device, scene, width, height);
  runner.setTimingRepeats(o.repeats);
  uint64_t total = 0;
  for (size_t i = first; i < end && !o.referenceOnly; ++i) total += points[i].spp;
  const bool renderReference = o.reference.empty();
  const uint32_t referenceSpp = referenceSppOf(o);
  if (renderReference) total += referenceSpp;
  // The progress bar counts samples of every render, in millions if need be.
  Progress progress(uint32_t(std::min<uint64_t>(total, 0xffffffffu)));
  uint64_t done = 0;
  auto report = [&](uint64_t base) {
    return [&, base](uint32_t samples) { progress.update(uint32_t(base + samples)); };
  };

  if (renderReference) {
    reference = renderOrCachedReference(o, dir, runner, report(0));
    done += referenceSpp;
  }
  if (o.referenceOnly) {
    progress.finish();
    fmt::print("reference: {}, {} spp, in {}\n", reference.source, reference.spp, o.out);
    return 0;
  }
  const auto referencePreview = dir / "reference.png";
  if (o.points.empty()) {
    savePreview(referencePreview, reference.image);
    written.add(referencePreview);
  }
  const std::vector<study::StudyRow> rows =
      measurePoints(runner, points, first, end, spec, reference, dir, written, report, done);
  progress.finish();
  if (o.device.validation && device->validationMessageCount() > 0) {
    fmt::print(stderr, "error: {} validation message(s)\n", device->validationMessageCount());
    return 1;
  }

  study::StudyContext context = studyContext(o, width, height, reference);
  context.device = adapter.name;
  context.api = adapter.apiVersion;
  context.backend = device->backendName();
  if (!o.points.empty()) return writePart(dir, context, first, end, rows, written);
  writeResults(o, dir, context, rows, written);
  return 0;
}

}  // namespace

Command addStudyCommand(CLI::App& app) {
  auto o = std::make_shared<StudyOptions>();
  auto* cmd = app.add_subcommand(
      "study",
      "What accuracy costs in time: render a sweep of techniques and sample counts, each timed "
      "on the GPU and compared with a reference; write results.csv/json and print the answers");
  addSceneOptions(*cmd, o->scene, "Built-in scene name, scene file or glTF file");
  cmd->add_option("--spp", o->spp, "Samples per pixel, comma separated")->capture_default_str();
  // One option per study axis, from the settings table.
  for (const study::StudyAxis& axis : study::studyAxes()) {
    const render::Setting& setting = *axis.setting;
    std::string& values = o->axes[std::string(setting.key)];
    values = axis.spell(setting.get(render::RenderSettings{}));
    std::string help = fmt::format("{} (comma separated)", setting.help);
    if (setting.type == render::SettingType::Flag)
      help = fmt::format("{}: {}, {} (comma separated)", setting.label, axis.onWord, axis.offWord);
    cmd->add_option(fmt::format("--{}", axis.option), values, help)->capture_default_str();
  }
  cmd->add_option("--seeds", o->seeds, "Seeds per point (for confidence intervals)")
      ->check(CLI::Range(1u, 1000u))
      ->capture_default_str();
  cmd->add_option("--first-seed", o->firstSeed, "The first of the points' seeds")
      ->capture_default_str();
  cmd->add_option("--repeats", o->repeats,
                  "Timed renders per point; the median time counts (a shared GPU's times vary)")
      ->check(CLI::Range(1u, 100u))
      ->capture_default_str();
  cmd->add_option("--reference", o->reference,
                  "Reference image (.exr, the study's size), e.g. another renderer's; default: "
                  "rendered by Penumbra (--reference-spp)");
  cmd->add_option("--reference-spp", o->referenceSpp,
                  "Samples of the rendered reference (two independent halves)")
      ->check(CLI::Range(2u, 1u << 24))
      ->capture_default_str();
  cmd->add_option("--reference-seed", o->referenceSeed,
                  "Seed of the rendered reference's first half (the second: +1); must not be a "
                  "point's seed")
      ->capture_default_str();
  cmd->add_option("--reference-max-depth", o->referenceMaxDepth,
                  "Maximum bounces of the rendered reference (MIS)")
      ->check(CLI::Range(1u, 1024u))
      ->capture_default_str();
  cmd->add_option("--budget-ms", o->budgetMs, "Time budget for the 'lowest error' answer")
      ->capture_default_str();
  cmd->add_option("--target-relmse", o->targetRelMse,
                  "Target error for the 'fastest technique' answer (0 = not asked)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--out", o->out, "Folder for results.csv, results.json, images/, reference");
  cmd->add_option("--analyze", o->analyze,
                  "Print the answers of an existing results.csv instead of rendering");
  addDeviceOptions(*cmd, o->device);
  cmd->add_flag("--reference-only", o->referenceOnly,
                "Split study, step 1: render and cache the reference in --out, nothing else");
  cmd->add_option("--points", o->points,
                  "Split study, step 2: measure points A to B-1 only (rows in OUT/points/)");
  cmd->add_flag("--gather", o->gather,
                "Split study, step 3: gather the parts' rows into results.csv/json and answers");
  cmd->add_flag("--count-points", o->countPoints, "Print how many points the study has")->group("");
  return [o, cmd] { return runStudy(*o, *cmd); };
}

}  // namespace penumbra::app
