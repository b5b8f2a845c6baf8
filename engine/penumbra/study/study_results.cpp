#include "penumbra/study/study_results.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "penumbra/batch/render_job.h"
#include "penumbra/util/error.h"

namespace penumbra::study {

const std::string& resultsCsvHeader() {
  static const std::string header = [] {
    std::string h = "technique";
    for (const StudyAxis& axis : studyAxes()) h += fmt::format(",{}", axis.csvColumn);
    return h +
           ",spp,seed,gpu_ms,denoise_ms,rays,relmse,mape,ssim,bias,efficiency,"
           "below_reference_noise";
  }();
  return header;
}

std::string imageName(const std::string& technique, uint32_t spp) {
  std::string name;
  for (char c : technique)
    name += (std::isalnum(static_cast<unsigned char>(c)) || c == '.') ? c : '_';
  return fmt::format("{}-spp{}", name, spp);
}

Measurement measurement(const StudyRow& row) {
  Measurement m;
  m.technique = row.point.technique.label();
  m.spp = row.point.spp;
  m.seed = row.point.seed;
  m.gpuMs = row.gpuMs;
  m.relMse = row.error.relMse;
  m.mape = row.error.mape;
  m.ssim = row.error.ssim;
  m.bias = row.error.bias;
  return m;
}

namespace {

// Enough digits to read back the same double.
std::string number(double v) {
  return fmt::format("{:.17g}", v);
}

}  // namespace

std::string resultsCsv(const std::vector<StudyRow>& rows) {
  std::string out = resultsCsvHeader() + "\n";
  for (const StudyRow& r : rows) {
    const Technique& t = r.point.technique;
    // Technique labels and spelled values hold no comma or quote: no quoting needed.
    out += t.label();
    for (const StudyAxis& axis : studyAxes()) {
      out += ',';
      out += axis.spell(axis.setting->get(t.settings));
    }
    out += fmt::format(",{},{},{},{},{},{},{},{},{},{},{}\n", r.point.spp, r.point.seed,
                       number(r.gpuMs), number(r.denoiseMs), r.rays, number(r.error.relMse),
                       number(r.error.mape), number(r.error.ssim), number(r.error.bias),
                       number(1.0 / (r.error.relMse * r.gpuMs)), r.belowReferenceNoise ? 1 : 0);
  }
  return out;
}

namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    fields.push_back(
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

}  // namespace

namespace {

// A results.csv as named columns; throws naming `source` and the line.
struct CsvTable {
  std::string source;
  std::map<std::string, size_t> column;
  struct Row {
    size_t line;
    std::vector<std::string> fields;
  };
  std::vector<Row> rows;

  const std::string& text(const Row& row, const char* name) const {
    return row.fields[column.at(name)];
  }
  double number(const Row& row, const char* name) const {
    const std::string& field = text(row, name);
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(field, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != field.size() || field.empty() || !std::isfinite(v))
      throw Error(fmt::format("{}: line {}: {} '{}' is not a finite number", source, row.line, name,
                              field));
    return v;
  }
  uint32_t whole(const Row& row, const char* name, double lo) const {
    const double v = number(row, name);
    if (v < lo || v > 4294967295.0 || v != std::floor(v))
      throw Error(fmt::format("{}: line {}: {} '{}' is not a whole number >= {}", source, row.line,
                              name, text(row, name), lo));
    return uint32_t(v);
  }
};

CsvTable readCsv(const std::string& text, const std::string& source,
                 std::initializer_list<const char*> needed) {
  CsvTable table;
  table.source = source;
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) throw Error(fmt::format("{}: empty results file", source));
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> header = splitCsvLine(line);
  for (size_t i = 0; i < header.size(); ++i) table.column[header[i]] = i;
  for (const char* name : needed)
    if (!table.column.count(name))
      throw Error(fmt::format("{}: line 1: the header has no '{}' column", source, name));
  for (size_t lineNumber = 2; std::getline(in, line); ++lineNumber) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> f = splitCsvLine(line);
    if (f.size() != header.size())
      throw Error(fmt::format("{}: line {}: {} fields, the header has {}", source, lineNumber,
                              f.size(), header.size()));
    if (f[table.column.at("technique")].empty())
      throw Error(fmt::format("{}: line {}: empty technique", source, lineNumber));
    table.rows.push_back({lineNumber, std::move(f)});
  }
  if (table.rows.empty()) throw Error(fmt::format("{}: no rows after the header", source));
  return table;
}

}  // namespace

std::vector<Measurement> parseResultsCsv(const std::string& text, const std::string& source) {
  const CsvTable table = readCsv(
      text, source, {"technique", "spp", "seed", "gpu_ms", "relmse", "mape", "ssim", "bias"});
  std::vector<Measurement> rows;
  for (const auto& row : table.rows) {
    Measurement m;
    m.technique = table.text(row, "technique");
    m.spp = table.whole(row, "spp", 1);
    m.seed = table.whole(row, "seed", 0);
    m.gpuMs = table.number(row, "gpu_ms");
    m.relMse = table.number(row, "relmse");
    m.mape = table.number(row, "mape");
    m.ssim = table.number(row, "ssim");
    m.bias = table.number(row, "bias");
    rows.push_back(m);
  }
  return rows;
}

std::vector<StudyRow> parseStudyRows(const std::string& text, const std::string& source,
                                     const std::vector<StudyPoint>& points) {
  const CsvTable table = readCsv(text, source,
                                 {"technique", "spp", "seed", "gpu_ms", "denoise_ms", "rays",
                                  "relmse", "mape", "ssim", "bias", "below_reference_noise"});
  std::vector<StudyRow> rows;
  for (const auto& row : table.rows) {
    const std::string& technique = table.text(row, "technique");
    const uint32_t spp = table.whole(row, "spp", 1), seed = table.whole(row, "seed", 0);
    const auto point = std::find_if(points.begin(), points.end(), [&](const StudyPoint& p) {
      return p.spp == spp && p.seed == seed && p.technique.label() == technique;
    });
    if (point == points.end())
      throw Error(fmt::format("{}: line {}: '{}' at {} spp, seed {} is not a point of this study",
                              source, row.line, technique, spp, seed));
    StudyRow r;
    r.point = *point;
    r.gpuMs = table.number(row, "gpu_ms");
    r.denoiseMs = table.number(row, "denoise_ms");
    const double rays = table.number(row, "rays");
    if (rays < 0 || rays != std::floor(rays) || rays > 1.8e19)
      throw Error(fmt::format("{}: line {}: rays '{}' is not a count", source, row.line,
                              table.text(row, "rays")));
    r.rays = uint64_t(rays);
    r.error = {table.number(row, "relmse"), table.number(row, "mape"), table.number(row, "ssim"),
               table.number(row, "bias")};
    r.belowReferenceNoise = table.whole(row, "below_reference_noise", 0) != 0;
    rows.push_back(r);
  }
  return rows;
}

namespace {

nlohmann::json estimateJson(const Estimate& e) {
  nlohmann::json j;
  j["mean"] = e.mean;
  if (std::isfinite(e.halfWidth))
    j["ci95"] = e.halfWidth;
  else
    j["ci95"] = nullptr;
  return j;
}

}  // namespace

std::string resultsJson(const StudyContext& c, const std::vector<StudyRow>& rows,
                        const std::vector<PointSummary>& summaries) {
  nlohmann::json doc;
  doc["format"] = "penumbra-study";
  doc["version"] = 1;
  doc["scene"] = c.scene;
  doc["width"] = c.width;
  doc["height"] = c.height;
  doc["device"] = c.device;
  doc["api"] = c.api;
  doc["backend"] = c.backend;
  doc["commit"] = c.commit;
  doc["budgetMs"] = c.budgetMs;
  nlohmann::json ref;
  ref["source"] = c.referenceSource;
  ref["spp"] = c.referenceSpp;
  ref["seed"] = c.referenceSeed;
  if (c.referenceNoiseRelMse >= 0)
    ref["noiseRelMse"] = c.referenceNoiseRelMse;
  else
    ref["noiseRelMse"] = nullptr;
  doc["reference"] = ref;
  nlohmann::json list = nlohmann::json::array();
  for (const StudyRow& r : rows) {
    const Technique& t = r.point.technique;
    nlohmann::json j;
    j["technique"] = t.label();
    for (const StudyAxis& axis : studyAxes()) {
      const double v = axis.setting->get(t.settings);
      nlohmann::json& field = j[std::string(axis.jsonKey)];
      switch (axis.setting->type) {
        case render::SettingType::Count:
          field = uint64_t(v);
          break;
        case render::SettingType::Number:
          field = v;
          break;
        case render::SettingType::Flag:
          if (axis.onWord == "on")
            field = v != 0.0;
          else
            field = axis.spell(v);
          break;
        case render::SettingType::Choice:
          field = axis.spell(v);
          break;
      }
    }
    j["spp"] = r.point.spp;
    j["seed"] = r.point.seed;
    j["gpuMs"] = r.gpuMs;
    j["denoiseMs"] = r.denoiseMs;
    j["rays"] = r.rays;
    j["relMse"] = r.error.relMse;
    j["mape"] = r.error.mape;
    j["ssim"] = r.error.ssim;
    j["bias"] = r.error.bias;
    j["belowReferenceNoise"] = r.belowReferenceNoise;
    list.push_back(j);
  }
  doc["rows"] = list;
  nlohmann::json points = nlohmann::json::array();
  for (const PointSummary& p : summaries) {
    nlohmann::json j;
    j["technique"] = p.technique;
    j["spp"] = p.spp;
    j["seeds"] = p.seeds;
    j["gpuMs"] = estimateJson(p.gpuMs);
    j["relMse"] = estimateJson(p.relMse);
    j["mape"] = estimateJson(p.mape);
    j["ssim"] = estimateJson(p.ssim);
    j["bias"] = estimateJson(p.bias);
    j["efficiency"] = p.efficiency();
    j["image"] = "images/" + imageName(p.technique, p.spp) + ".png";
    points.push_back(j);
  }
  doc["summaries"] = points;
  nlohmann::json front = nlohmann::json::array();
  for (size_t i : paretoFront(summaries))
    front.push_back({{"technique", summaries[i].technique}, {"spp", summaries[i].spp}});
  doc["paretoFront"] = front;
  if (auto best = bestWithinBudget(summaries, c.budgetMs))
    doc["bestWithinBudget"] = {{"technique", summaries[*best].technique},
                               {"spp", summaries[*best].spp}};
  else
    doc["bestWithinBudget"] = nullptr;
  nlohmann::json slopes = nlohmann::json::array();
  for (const auto& s : convergenceSlopes(summaries))
    slopes.push_back({{"technique", s.technique}, {"slope", s.slope}, {"points", s.points}});
  doc["convergenceSlopes"] = slopes;
  return doc.dump(1) + "\n";
}

}  // namespace penumbra::study
