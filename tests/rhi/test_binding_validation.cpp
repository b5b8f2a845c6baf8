// Binding-set validation of texture and sampler arrays (engine/penumbra/rhi/
// binding_layout.h), fixed and unbounded, on hand-written layouts: no GPU.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include "penumbra/rhi/binding_layout.h"
#include "penumbra/util/error.h"

using namespace penumbra;
using namespace penumbra::rhi;
using Catch::Matchers::ContainsSubstring;

namespace {

// Where this test's t and s bindings start: validation only compares slots,
// so any numbers do.
constexpr uint32_t kFirstT = 32;
constexpr uint32_t kFirstS = 96;

// Validation only reads descs, so stand-ins do without a device.
class FakeTexture final : public ITexture {
 public:
  explicit FakeTexture(TextureUsage usage) { desc_.usage = usage; }
  const TextureDesc& desc() const override { return desc_; }

 private:
  TextureDesc desc_;
};

class FakeSampler final : public ISampler {
 public:
  const SamplerDesc& desc() const override { return desc_; }

 private:
  SamplerDesc desc_;
};

PipelineBindingLayout layoutWith(uint32_t textureArraySize, uint32_t samplerArraySize) {
  PipelineBindingLayout layout;
  addBindingLayoutItem(
      layout, 0, {kFirstT + 3, ResourceType::SampledTexture, textureArraySize, false, 0, "gMaps"},
      "test");
  addBindingLayoutItem(layout, 0,
                       {kFirstS + 1, ResourceType::Sampler, samplerArraySize, false, 0, "gLinear"},
                       "test");
  return layout;
}

BindingSetDesc setWith(size_t textures, size_t samplers) {
  BindingSetDesc set;
  set.debugName = "materials";
  set.items = {
      BindingSetItem::sampledTextures(
          kFirstT + 3, std::vector<TextureHandle>(
                           textures, std::make_shared<FakeTexture>(TextureUsage::Sampled))),
      BindingSetItem::samplers(
          kFirstS + 1, std::vector<SamplerHandle>(samplers, std::make_shared<FakeSampler>()))};
  return set;
}

}  // namespace

TEST_CASE("binding validation: fixed texture and sampler arrays take exactly arraySize elements",
          "[rhi][binding-validation]") {
  const auto layout = layoutWith(3, 1);
  REQUIRE_NOTHROW(validateBindingSet(setWith(3, 1), layout));
  REQUIRE_THROWS_WITH(validateBindingSet(setWith(2, 1), layout),
                      ContainsSubstring("materials") && ContainsSubstring("slot 35") &&
                          ContainsSubstring("gMaps") && ContainsSubstring("array of 3 textures") &&
                          ContainsSubstring("2 were bound"));
  REQUIRE_THROWS_WITH(validateBindingSet(setWith(3, 2), layout),
                      ContainsSubstring("slot 97") && ContainsSubstring("array of 1 samplers"));
  REQUIRE_THROWS_AS(validateBindingSet(setWith(4, 1), layout), Error);
}

TEST_CASE("binding validation: unbounded arrays take 1 to kMaxBindlessDescriptors elements",
          "[rhi][binding-validation]") {
  const auto layout = layoutWith(0, 0);
  REQUIRE_NOTHROW(validateBindingSet(setWith(1, 1), layout));
  REQUIRE_NOTHROW(validateBindingSet(setWith(kMaxBindlessDescriptors, 7), layout));
  REQUIRE_THROWS_WITH(validateBindingSet(setWith(kMaxBindlessDescriptors + 1, 1), layout),
                      ContainsSubstring("slot 35") && ContainsSubstring("unbounded array"));
  REQUIRE_THROWS_WITH(validateBindingSet(setWith(1, 0), layout),
                      ContainsSubstring("slot 97") && ContainsSubstring("0 were bound"));
}

TEST_CASE("binding validation: array sizes must agree between shaders", "[rhi][binding-validation]") {
  PipelineBindingLayout layout = layoutWith(0, 1);
  REQUIRE_THROWS_WITH(
      addBindingLayoutItem(
          layout, 0, {kFirstT + 3, ResourceType::SampledTexture, 8, false, 0, "gOther"}, "b.comp"),
      ContainsSubstring("b.comp") && ContainsSubstring("gMaps"));
}
