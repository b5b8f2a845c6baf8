// libFuzzer target: render settings and records (`penumbra render --settings`).
#include "fuzz_support.h"
#include "penumbra/batch/render_job.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace penumbra;
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expectCleanRejection([&] { (void)render::renderJobFromJson(text, "fuzz.json"); });
  return 0;
}
