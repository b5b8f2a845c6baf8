#pragma once
// The answers a study's rows give: per technique and sample count the mean
// error and time over the seeds (with 95 % confidence intervals), the
// error-versus-time Pareto front, the technique with the lowest error within
// a time budget, the fastest one that reaches a target error, and each
// technique's convergence slope (d log relMSE / d log spp: -1 for unbiased
// Monte Carlo, flatter where bias remains, as with a clamp or a denoiser).
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::study {

// One row as the analysis needs it (StudyRow, or a line of results.csv).
struct Measurement {
  std::string technique;
  uint32_t spp = 0;
  uint32_t seed = 0;
  double gpuMs = 0;
  double relMse = 0;
  double mape = 0;
  double ssim = 0;
  double bias = 0;
};

// A mean over seeds and the half-width of its 95 % confidence interval
// (Student's t; NaN with one seed).
struct Estimate {
  double mean = 0;
  double halfWidth = 0;
  bool excludesZero() const { return !(halfWidth != halfWidth) && std::abs(mean) > halfWidth; }
};
Estimate estimate(const std::vector<double>& values);

struct PointSummary {
  std::string technique;
  uint32_t spp = 0;
  uint32_t seeds = 0;
  Estimate gpuMs, relMse, mape, ssim, bias;
  double efficiency() const { return 1.0 / (relMse.mean * gpuMs.mean); }  // 1/(relMSE x ms)
};
// One summary per (technique, spp), in the order they first appear.
std::vector<PointSummary> summarize(const std::vector<Measurement>& rows);

// Indices of the summaries no other beats in both mean time and mean
// relMSE, sorted by time.
std::vector<size_t> paretoFront(const std::vector<PointSummary>& points);
// The lowest mean relMSE among the points whose mean time is within the budget.
std::optional<size_t> bestWithinBudget(const std::vector<PointSummary>& points, double budgetMs);
// The fastest point whose mean relMSE is at most the target.
std::optional<size_t> fastestForError(const std::vector<PointSummary>& points, double targetRelMse);

struct ConvergenceSlope {
  std::string technique;
  double slope = 0;      // of log relMSE on log spp, least squares over the spp values
  double intercept = 0;  // log relMSE at 1 spp
  size_t points = 0;     // spp values it was fitted to (at least 2)
};
// For each technique with at least two spp values.
std::vector<ConvergenceSlope> convergenceSlopes(const std::vector<PointSummary>& points);

}  // namespace penumbra::study
