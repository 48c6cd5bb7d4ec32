#include "lsystem/turtle.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/memory_budget.hpp"
#include "lsystem/turtle_core.hpp"
#include "lsystem/turtle_graph_builder.hpp"

namespace fspm::lsystem {
namespace {

std::string lower(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c != ' ' && c != '\t')
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::vector<double> numbers(std::string_view text, const std::string& file, int line, int column) {
  std::vector<double> out;
  std::string buffer(text);
  for (char& c : buffer) {
    if (c == ',') c = ' ';
  }
  const char* p = buffer.c_str();
  for (;;) {
    while (*p == ' ' || *p == '\t') ++p;
    if (!*p) break;
    // Trailing words such as units ("pixels", "p") end the list; strtod would read "nan",
    // "inf" (and the start of "nanometres") as numbers.
    if (std::isalpha(static_cast<unsigned char>(*p))) break;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    const int at = column + static_cast<int>(p - buffer.c_str());
    if (end == p) throw ParseError("expected a number", file, line, at);
    if (!std::isfinite(v)) {
      throw ParseError("expected a finite number, got '" +
                           std::string(p, static_cast<std::size_t>(end - p)) + "'",
                       file, line, at);
    }
    out.push_back(v);
    p = end;
  }
  return out;
}

// cpfg reads `initial line width: w [unit]`: no unit selects the polygon line style (model
// units), a word starting with 'p' (pixels) the pixel style, one with 's' or 'c' cylinders.
LineWidthUnit initial_width_unit(std::string_view value) {
  const auto word = std::find_if(value.begin(), value.end(), [](char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0;
  });
  if (word != value.end() && std::tolower(static_cast<unsigned char>(*word)) == 'p') {
    return LineWidthUnit::kPixel;
  }
  return LineWidthUnit::kModel;
}

// `line style: pixel | polygon | cylinder` (or cpfg's 1 | 2 | 3).
LineWidthUnit line_style_unit(std::string_view value, const std::string& file, int line,
                              int column) {
  const std::string style = lower(value);
  if (style == "pixel" || style == "1") return LineWidthUnit::kPixel;
  if (style == "polygon" || style == "cylinder" || style == "2" || style == "3") {
    return LineWidthUnit::kModel;
  }
  throw ParseError("expected a line style: pixel, polygon or cylinder", file, line, column);
}

// Largest side of the box around every drawn point (internode and organ ends, leaf vertices).
double largest_extent(const Interpretation& out) {
  Eigen::AlignedBox3d box;
  for (NodeId n = 0; n < out.tree.size(); ++n) {
    box.extend(out.tree.start(n));
    box.extend(out.tree.end(n));
  }
  for (const LeafPolygon& leaf : out.leaves) {
    for (const Eigen::Vector3d& v : leaf.vertices) box.extend(v);
  }
  return box.isEmpty() ? 0.0 : box.sizes().maxCoeff();
}

}  // namespace

TurtleSettings parse_view(std::string_view text, const std::string& name, TurtleSettings s) {
  std::istringstream in{std::string(text)};
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = lower(line.substr(0, colon));
    const std::string_view value = std::string_view(line).substr(colon + 1);
    const int column = static_cast<int>(colon) + 2;
    auto one = [&](const char* what) {
      const auto v = numbers(value, name, line_no, column);
      if (v.empty()) throw ParseError(std::string("expected ") + what, name, line_no, column);
      return v[0];
    };
    if (key == "anglefactor") {
      const double n = one("an angle factor (the angle is 360 / n)");
      if (n == 0.0) throw ParseError("angle factor must not be 0", name, line_no, column);
      s.angle_deg = 360.0 / n;
    } else if (key == "angleincrement") {
      s.angle_deg = one("an angle increment in degrees");
    } else if (key == "initiallinewidth") {
      s.initial_line_width = one("a line width");
      s.line_width_unit = initial_width_unit(value);
    } else if (key == "linestyle") {
      s.line_width_unit = line_style_unit(value, name, line_no, column);
    } else if (key == "linewidthincrement") {
      s.line_width_increment = one("a line width increment");
    } else if (key == "tropismdirection") {
      const auto v = numbers(value, name, line_no, column);
      if (v.size() < 3) {
        throw ParseError("expected three numbers x,y,z for the tropism direction", name, line_no,
                         column);
      }
      s.tropism_direction = Eigen::Vector3d(v[0], -v[2], v[1]);  // cpfg y-up -> fspm z-up
    } else if (key == "initialelasticity") {
      s.initial_elasticity = one("an elasticity");
    } else if (key == "elasticityincrement") {
      s.elasticity_increment = one("an elasticity increment");
    } else if (key == "step" || key == "initialstep") {
      s.step = one("a step length");
    }
  }
  return s;
}

TurtleSettings read_view_file(const std::string& path, TurtleSettings base) {
  return parse_view(read_text_input_file(path), path, base);
}

TurtleSettings view_for_lsystem(const std::string& lsystem_path) {
  std::filesystem::path p(lsystem_path);
  p.replace_extension(".v");
  std::error_code ec;
  if (std::filesystem::is_regular_file(p, ec)) return read_view_file(p.string());
  return {};
}

Interpretation interpret(const ModuleString& s, const SymbolTable& symbols,
                         const TurtleSettings& settings) {
  Interpretation out;
  const auto actions = detail::action_table(symbols);
  std::size_t drawn = 0;
  for (SymbolId sym : s.symbols()) {
    const auto a = actions[sym];
    drawn += (a == detail::Action::kForward || a == detail::Action::kForwardNoVertex) ? 1 : 0;
  }
  // Two attributes (color_index, leaf_area) and a colour per drawn module.
  check_memory(static_cast<double>(drawn) * (TreeGraph::bytes_per_node(2) + sizeof(double)),
               "the tree of " + std::to_string(drawn) + " drawn modules");
  out.tree.reserve(drawn);
  detail::GraphBuilder builder(out);
  builder.colors_.reserve(drawn);
  detail::walk(s, actions, settings, builder);
  if (settings.line_width_unit == LineWidthUnit::kPixel) {
    // Pixel widths: the plant spans kPixelsAcrossPlant pixels of the picture they were drawn in.
    const double units_per_pixel = largest_extent(out) / kPixelsAcrossPlant;
    for (NodeId n : builder.line_width_nodes_) {
      out.tree.set_radius(n, out.tree.radius(n) * units_per_pixel);
    }
  }
  builder.store_attributes();
  return out;
}

}  // namespace fspm::lsystem
