#pragma once
// Names read from files end up in JSON (documents, --json output, glTF),
// which must be UTF-8: check text where it is read.

#include <cstddef>
#include <string>
#include <string_view>

namespace mq {

// The offset of the first byte that breaks UTF-8 (overlong forms, surrogates
// and code points past U+10FFFF included), or npos when the text is valid.
size_t firstInvalidUtf8(std::string_view text);

// `text` with each invalid byte replaced by U+FFFD.
std::string repairedUtf8(std::string_view text);

}  // namespace mq
