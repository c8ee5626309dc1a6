// The byte-order mark a spreadsheet may write at the start of a CSV file ("CSV UTF-8" in Excel
// writes EF BB BF). A UTF-8 mark is dropped: the text after it is valid UTF-8, and a reader that
// kept it would see "\xEF\xBB\xBF# key: value" as a data line and report a misleading error. A
// UTF-16 or UTF-32 mark means text the line-based readers cannot read at all: an error that says
// how to save the file; so does a first line with NUL bytes (UTF-16 without a mark).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace impact::pointdriver::fit {

/// Strips a UTF-8 byte-order mark from the start of `first_line`; the error message when the
/// line starts with a UTF-16 or UTF-32 mark instead, or holds a NUL byte (nothing when the line
/// is fine).
inline std::optional<std::string> strip_byte_order_mark(std::string& first_line) {
  const std::string_view line = first_line;
  if (line.starts_with("\xEF\xBB\xBF")) {
    first_line.erase(0, 3);
    return std::nullopt;
  }
  // UTF-32 LE (FF FE 00 00) before UTF-16 LE (FF FE), which it starts with.
  const char* encoding = line.starts_with(std::string_view("\xFF\xFE\0\0", 4))          ? "UTF-32"
                         : line.starts_with(std::string_view("\0\0\xFE\xFF", 4))        ? "UTF-32"
                         : line.starts_with("\xFF\xFE") || line.starts_with("\xFE\xFF") ? "UTF-16"
                                                                                        : nullptr;
  const char* save = "save it as UTF-8 or ASCII (e.g. \"CSV UTF-8\" or \"CSV\" in a spreadsheet)";
  if (encoding == nullptr && line.find('\0') != std::string_view::npos) {
    // Without a mark: every other byte of ASCII text is NUL, which would cut a message quoting
    // the line short on a terminal.
    return std::string(
               "the first line holds NUL bytes: UTF-16 or UTF-32 text without a "
               "byte-order mark, or not text at all; ") +
           save;
  }
  if (encoding == nullptr) return std::nullopt;
  return std::string("the file is ") + encoding + " text (it starts with a " + encoding +
         " byte-order mark): " + save;
}

}  // namespace impact::pointdriver::fit
