#include "graphics/attribute_title.hpp"

namespace fspm::graphics {

std::string attribute_title(std::string_view name) {
  // The growth model's leaves carry the mean light of their leaves and its internodes the light
  // their bud sensed, both relative to the open sky (docs/environment.md).
  // Lines of a few words: the scalar bar shrinks its title to fit its width.
  if (name == "light") return "light\nshare of the\nopen sky";
  if (name == "displacement") return "displacement\n(m)";
  if (name == "leaf_density") return "leaf density\nrelative to the\ntree before\nadaptation";
  return std::string(name);
}

}  // namespace fspm::graphics
