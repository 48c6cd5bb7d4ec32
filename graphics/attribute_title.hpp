#pragma once
// The legend title of a node attribute: its name, with the unit and the meaning of the attributes
// fspm writes itself, so that a coloured picture explains itself.
#include <string>
#include <string_view>

namespace fspm::graphics {

// "light" -> "light\nshare of the\nopen sky"; "displacement" -> "displacement\n(m)"; other
// names unchanged. Lines are separated by '\n'.
std::string attribute_title(std::string_view name);

}  // namespace fspm::graphics
