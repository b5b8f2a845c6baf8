#pragma once
// A 128-bit content hash (XXH3-128, Debian's libxxhash, header-only here) fed
// field by field. It names what a render was made of: pieces of a render
// split across machines (batch/sample_split.h) merge only when their scene
// and settings hashes agree. Not a cryptographic hash: it guards against
// accidents (another scene, another seed), not against forgery.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#define XXH_INLINE_ALL
#include <xxhash.h>

namespace penumbra {

class ContentHash {
 public:
  ContentHash() : state_(XXH3_createState()) { XXH3_128bits_reset(state_); }
  ~ContentHash() { XXH3_freeState(state_); }
  ContentHash(const ContentHash&) = delete;
  ContentHash& operator=(const ContentHash&) = delete;

  void bytes(const void* data, size_t size) { XXH3_128bits_update(state_, data, size); }
  // Arithmetic values and arrays of them (glm vectors, matrices) by their
  // bytes; each is only ever compared with the same build's, so byte order
  // and layout are the same on both sides.
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  // Length first: ("ab", "c") and ("a", "bc") must differ.
  void text(std::string_view s) {
    value(uint64_t(s.size()));
    bytes(s.data(), s.size());
  }
  template <class T>
  void array(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value(uint64_t(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  // 32 lowercase hex digits.
  std::string hex() const {
    const XXH128_hash_t h = XXH3_128bits_digest(state_);
    static const char* digits = "0123456789abcdef";
    std::string out(32, '0');
    for (int i = 0; i < 16; ++i) {
      out[size_t(i)] = digits[(h.high64 >> (60 - 4 * i)) & 15];
      out[size_t(16 + i)] = digits[(h.low64 >> (60 - 4 * i)) & 15];
    }
    return out;
  }

 private:
  XXH3_state_t* state_;
};

}  // namespace penumbra
