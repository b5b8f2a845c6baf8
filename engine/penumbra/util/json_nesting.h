#pragma once
// How deeply JSON text nests, measured on the raw text before any parser
// sees it. Parsers and the code that walks their trees (nlohmann::json's
// copies and comparisons, tinygltf's conversion of "extras" into its own
// values) recurse once per level of arrays and objects: a file of a million
// '[' is a few megabytes and overflows the stack. This scan is iterative, so
// it bounds the depth whatever parser comes next (docs/security.md).
#include <cstddef>
#include <optional>
#include <string_view>

namespace penumbra::json_nesting {

// The byte offset of the first '[' or '{' that opens level maxDepth + 1
// (the document's outermost array or object is level 1), or nothing if the
// text never nests deeper than maxDepth. Brackets inside strings do not
// count; a backslash escapes the next character there. Malformed text is
// scanned as far as it goes: along any prefix a parser accepts, this depth
// is the parser's, so a parser that stops at an error never goes deeper.
inline std::optional<size_t> firstTooDeep(std::string_view text, size_t maxDepth) {
  size_t depth = 0;
  bool inString = false, escaped = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

}  // namespace penumbra::json_nesting
