#include "render/tone_mapping.h"

namespace penumbra::render {

const std::vector<ToneMapOperator>& allToneMapOperators() {
  static const std::vector<ToneMapOperator> all = {
      ToneMapOperator::Clamp, ToneMapOperator::Reinhard, ToneMapOperator::AcesFitted};
  return all;
}

}  // namespace penumbra::render
