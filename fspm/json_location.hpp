#pragma once
// Line and column of a place in a JSON text named by a JSON pointer ("/obstacles/1/height"), so
// an error about a checked value can point at the line, as a syntax error does.
#include <string>
#include <string_view>

namespace fspm {

struct TextPosition {
  int line = 0;  // 1-based; 0 when not found
  int column = 0;
};

// Position of the value at `pointer` in the valid JSON `text` or, when the last token names an
// object key, of that key ("/a/b": the "b" of object /a). Line 0 when the pointer is not there.
TextPosition json_pointer_position(std::string_view text, std::string_view pointer);

}  // namespace fspm
