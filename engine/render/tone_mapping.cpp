#include "render/tone_mapping.h"

namespace penumbra::render {

const char* toneMapOperatorName(ToneMapOperator op) {
  switch (op) {
    case ToneMapOperator::Clamp:
      return "clamp";
    case ToneMapOperator::Reinhard:
      return "reinhard";
    case ToneMapOperator::AcesFitted:
      return "aces";
  }
  return "?";
}

std::optional<ToneMapOperator> parseToneMapOperator(std::string_view name) {
  for (ToneMapOperator op : allToneMapOperators())
    if (name == toneMapOperatorName(op)) return op;
  return std::nullopt;
}

const std::vector<ToneMapOperator>& allToneMapOperators() {
  static const std::vector<ToneMapOperator> all = {
      ToneMapOperator::Clamp, ToneMapOperator::Reinhard, ToneMapOperator::AcesFitted};
  return all;
}

}  // namespace penumbra::render
