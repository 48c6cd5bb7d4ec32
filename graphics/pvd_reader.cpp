// Reading ParaView .pvd collections (the viewer's growth sequences). The format is a short XML
// list of <DataSet timestep="..." file="..."/> elements; only those two attributes matter here.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "graphics/vtk_readback.hpp"

namespace fspm::graphics {
namespace {

// Value of attribute `name` inside one element's text, or false.
bool attribute_value(const std::string& element, const std::string& name, std::string& value) {
  std::size_t at = 0;
  while ((at = element.find(name + "=", at)) != std::string::npos) {
    const bool word_start = at == 0 || std::isspace(static_cast<unsigned char>(element[at - 1]));
    const std::size_t q = at + name.size() + 1;
    if (word_start && q < element.size() && (element[q] == '"' || element[q] == '\'')) {
      const std::size_t end = element.find(element[q], q + 1);
      if (end == std::string::npos) return false;
      value = element.substr(q + 1, end - q - 1);
      return true;
    }
    at = q;
  }
  return false;
}

}  // namespace

std::vector<PvdStep> read_pvd_file(const std::string& path) {
  const std::string text = read_input_file(path);
  if (text.find("<VTKFile") == std::string::npos || text.find("Collection") == std::string::npos) {
    throw ParseError("not a ParaView collection (expected <VTKFile type=\"Collection\">)", path);
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::vector<PvdStep> steps;
  std::size_t at = 0;
  while ((at = text.find("<DataSet", at)) != std::string::npos) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) throw ParseError("unterminated <DataSet> element", path);
    const std::string element = text.substr(at, end - at);
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    at = end;
    std::string time, file;
    if (!attribute_value(element, "file", file) || file.empty()) {
      throw ParseError("<DataSet> without a file attribute", path, line);
    }
    PvdStep step;
    if (attribute_value(element, "timestep", time)) {
      std::istringstream t(time);
      if (!(t >> step.time))
        throw ParseError("timestep is not a number: '" + time + "'", path, line);
    } else {
      step.time = static_cast<double>(steps.size());
    }
    std::filesystem::path p = file;
    if (p.is_relative()) p = dir / p;
    step.path = p.string();
    steps.push_back(step);
  }
  if (steps.empty()) throw ParseError("the collection lists no data sets", path);
  std::stable_sort(steps.begin(), steps.end(),
                   [](const PvdStep& a, const PvdStep& b) { return a.time < b.time; });
  return steps;
}

}  // namespace fspm::graphics
