// `penumbra compare a.exr b.exr`: per-pixel statistics of two linear images
// and a false-colour difference image.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "commands.h"
#include "image/image_compare.h"
#include "image/image_io.h"

namespace penumbra::app {
namespace {

struct CompareOptions {
  std::string a, b;
  double tolerance = 1e-3;
  double allowedFraction = 0.0;
  std::string diffOut;
};

// Black where equal; blue -> green -> red as |a - b| (max over RGB) grows,
// saturating at `scale`.
image::Image8 falseColourDifference(const image::Image& a, const image::Image& b, double scale) {
  image::Image8 out;
  out.width = a.width;
  out.height = a.height;
  out.rgba.resize(size_t(a.width) * a.height * 4);
  for (size_t i = 0; i < size_t(a.width) * a.height; ++i) {
    double d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, double(std::abs(a.rgba[i * 4 + c] - b.rgba[i * 4 + c])));
    const double t = scale > 0 ? std::min(d / scale, 1.0) : 0.0;
    const double r = std::clamp(2.0 * t - 1.0, 0.0, 1.0);
    const double g = 1.0 - std::abs(2.0 * t - 1.0);
    const double bl = std::clamp(1.0 - 2.0 * t, 0.0, 1.0) * (d > 0 ? 1.0 : 0.0);
    out.rgba[i * 4 + 0] = uint8_t(r * 255.0 + 0.5);
    out.rgba[i * 4 + 1] = uint8_t(d > 0 ? g * 255.0 + 0.5 : 0.0);
    out.rgba[i * 4 + 2] = uint8_t(bl * 255.0 + 0.5);
    out.rgba[i * 4 + 3] = 255;
  }
  return out;
}

int runCompare(const CompareOptions& o) {
  if (!o.diffOut.empty()) image::checkWritable(o.diffOut);
  const auto a = image::loadExr(o.a);
  const auto b = image::loadExr(o.b);
  const auto s = image::compareImages(a, b, o.tolerance);
  fmt::print("images: {} vs {} ({}x{})\n", o.a, o.b, a.width, a.height);
  const auto ma = image::meanRgb(a), mb = image::meanRgb(b);
  fmt::print("mean RGB: a ({:.6g}, {:.6g}, {:.6g})  b ({:.6g}, {:.6g}, {:.6g})\n", ma.r, ma.g, ma.b,
             mb.r, mb.g, mb.b);
  fmt::print("mean absolute difference: {:.6g}\n", s.meanAbsoluteDifference);
  fmt::print("max absolute difference: {:.6g}\n", s.maxAbsoluteDifference);
  fmt::print("pixels beyond relative tolerance {:g}: {} ({:.4f}%)\n", o.tolerance,
             s.pixelsBeyondTolerance, s.fractionBeyondTolerance * 100.0);
  fmt::print("PSNR: {:.2f} dB\n", s.psnr);
  if (s.nonFiniteA || s.nonFiniteB)
    fmt::print("non-finite pixels: {} in a, {} in b\n", s.nonFiniteA, s.nonFiniteB);
  if (!o.diffOut.empty()) {
    image::savePng(o.diffOut, falseColourDifference(a, b, std::max(s.maxAbsoluteDifference, 1e-12)));
    fmt::print("wrote {} (false colour, red = max difference {:.6g})\n", o.diffOut,
               s.maxAbsoluteDifference);
  }
  const bool within = s.fractionBeyondTolerance <= o.allowedFraction && s.nonFiniteA == 0 &&
                      s.nonFiniteB == 0;
  fmt::print("{}\n", within ? "within tolerance" : "NOT within tolerance");
  return within ? 0 : 1;
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand("compare", "Compare two linear EXR images pixel for pixel");
  cmd->add_option("a", o->a, "First image (.exr)")->required()->check(CLI::ExistingFile);
  cmd->add_option("b", o->b, "Second image (.exr)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--tolerance", o->tolerance,
                  "Relative per-channel tolerance: |a-b| <= tol * max(|a|, |b|, 1e-3)")
      ->capture_default_str();
  cmd->add_option("--allowed-fraction", o->allowedFraction,
                  "Fraction of pixels allowed beyond the tolerance for exit code 0")
      ->check(CLI::Range(0.0, 1.0))->capture_default_str();
  cmd->add_option("--diff", o->diffOut, "Write a false-colour difference image (.png)");
  return [o] { return runCompare(*o); };
}

}  // namespace penumbra::app
