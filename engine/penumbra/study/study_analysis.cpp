#include "penumbra/study/study_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::study {
namespace {

// Two-sided 95 % quantiles of Student's t for 1..30 degrees of freedom.
double studentT95(size_t dof) {
  static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                                 2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                                 2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                                 2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  return dof <= 30 ? table[dof - 1] : 1.96;
}

}  // namespace

Estimate estimate(const std::vector<double>& values) {
  Estimate e;
  if (values.empty()) return e;
  double sum = 0;
  for (double v : values) sum += v;
  e.mean = sum / double(values.size());
  if (values.size() < 2) {
    e.halfWidth = std::numeric_limits<double>::quiet_NaN();
    return e;
  }
  double squares = 0;
  for (double v : values) squares += (v - e.mean) * (v - e.mean);
  const double stddev = std::sqrt(squares / double(values.size() - 1));
  e.halfWidth = studentT95(values.size() - 1) * stddev / std::sqrt(double(values.size()));
  return e;
}

std::vector<PointSummary> summarize(const std::vector<Measurement>& rows) {
  struct Group {
    std::string technique;
    uint32_t spp;
    std::vector<double> ms, rel, mape, ssim, bias;
  };
  std::vector<Group> groups;
  for (const Measurement& m : rows) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
      return g.technique == m.technique && g.spp == m.spp;
    });
    if (it == groups.end()) {
      groups.push_back({m.technique, m.spp, {}, {}, {}, {}, {}});
      it = groups.end() - 1;
    }
    it->ms.push_back(m.gpuMs);
    it->rel.push_back(m.relMse);
    it->mape.push_back(m.mape);
    it->ssim.push_back(m.ssim);
    it->bias.push_back(m.bias);
  }
  std::vector<PointSummary> out;
  for (const Group& g : groups) {
    PointSummary p;
    p.technique = g.technique;
    p.spp = g.spp;
    p.seeds = uint32_t(g.ms.size());
    p.gpuMs = estimate(g.ms);
    p.relMse = estimate(g.rel);
    p.mape = estimate(g.mape);
    p.ssim = estimate(g.ssim);
    p.bias = estimate(g.bias);
    out.push_back(p);
  }
  return out;
}

std::vector<size_t> paretoFront(const std::vector<PointSummary>& points) {
  std::vector<size_t> front;
  for (size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;
    for (size_t j = 0; j < points.size() && !dominated; ++j) {
      if (j == i) continue;
      const bool noWorse = points[j].gpuMs.mean <= points[i].gpuMs.mean &&
                           points[j].relMse.mean <= points[i].relMse.mean;
      const bool better = points[j].gpuMs.mean < points[i].gpuMs.mean ||
                          points[j].relMse.mean < points[i].relMse.mean;
      dominated = noWorse && better;
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(),
            [&](size_t a, size_t b) { return points[a].gpuMs.mean < points[b].gpuMs.mean; });
  return front;
}

std::optional<size_t> bestWithinBudget(const std::vector<PointSummary>& points, double budgetMs) {
  std::optional<size_t> best;
  for (size_t i = 0; i < points.size(); ++i)
    if (points[i].gpuMs.mean <= budgetMs &&
        (!best || points[i].relMse.mean < points[*best].relMse.mean))
      best = i;
  return best;
}

std::optional<size_t> fastestForError(const std::vector<PointSummary>& points,
                                      double targetRelMse) {
  std::optional<size_t> best;
  for (size_t i = 0; i < points.size(); ++i)
    if (points[i].relMse.mean <= targetRelMse &&
        (!best || points[i].gpuMs.mean < points[*best].gpuMs.mean))
      best = i;
  return best;
}

std::vector<ConvergenceSlope> convergenceSlopes(const std::vector<PointSummary>& points) {
  std::vector<ConvergenceSlope> slopes;
  std::vector<std::string> techniques;
  for (const auto& p : points)
    if (std::find(techniques.begin(), techniques.end(), p.technique) == techniques.end())
      techniques.push_back(p.technique);
  for (const std::string& t : techniques) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    size_t n = 0;
    for (const auto& p : points) {
      if (p.technique != t || !(p.relMse.mean > 0)) continue;
      const double x = std::log(double(p.spp)), y = std::log(p.relMse.mean);
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
      ++n;
    }
    const double denominator = double(n) * sxx - sx * sx;
    if (n < 2 || denominator <= 0) continue;
    ConvergenceSlope s;
    s.technique = t;
    s.slope = (double(n) * sxy - sx * sy) / denominator;
    s.intercept = (sy - s.slope * sx) / double(n);
    s.points = n;
    slopes.push_back(s);
  }
  return slopes;
}

}  // namespace penumbra::study
