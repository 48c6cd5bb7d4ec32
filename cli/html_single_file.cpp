#include "cli/html_single_file.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Replaces every `open` + NAME + `close` in `page` by what `inline_of(NAME)` gives.
template <typename F>
void inline_references(std::string& page, const std::string& open, const std::string& close,
                       F inline_of) {
  for (std::size_t at = page.find(open); at != std::string::npos; at = page.find(open, at)) {
    const std::size_t name_at = at + open.size();
    const std::size_t end = page.find(close, name_at);
    if (end == std::string::npos) break;
    const std::string replacement = inline_of(page.substr(name_at, end - name_at));
    page.replace(at, end + close.size() - at, replacement);
    at += replacement.size();
  }
}

std::string read_beside(const fs::path& dir, const std::string& name) {
  const fs::path file = dir / name;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    throw IoError("the HTML report names " + name + ", which is missing", file.string());
  }
  return read_text_input_file(file.string());
}

}  // namespace

std::string script_safe(std::string text) {
  for (std::size_t at = 0; (at = text.find('<', at)) != std::string::npos; ++at) {
    const std::string next = lower(text.substr(at, 7));
    if (next == "</scrip" || next.rfind("<!--", 0) == 0) text.insert(at + 1, "\\");
  }
  return text;
}

std::uintmax_t write_single_file_report(const fs::path& report_dir, const fs::path& out) {
  std::string page = read_beside(report_dir, "index.html");
  inline_references(page, "<link rel=\"stylesheet\" href=\"", "\">", [&](const std::string& n) {
    return "<style>\n" + read_beside(report_dir, n) + "\n</style>";
  });
  inline_references(page, "<script src=\"", "\"></script>", [&](const std::string& n) {
    return "<script>\n" + script_safe(read_beside(report_dir, n)) + "\n</script>";
  });
  // The trees after the page's script, which keeps each until a view asks for it.
  std::vector<fs::path> trees;
  std::error_code ec;
  if (fs::is_directory(report_dir / "trees", ec)) {
    for (const auto& e : fs::directory_iterator(report_dir / "trees")) {
      if (e.path().extension() == ".js") trees.push_back(e.path());
    }
  }
  std::sort(trees.begin(), trees.end());
  std::string scripts;
  for (const fs::path& t : trees) {
    scripts += "<script>" + script_safe(read_text_input_file(t.string())) + "</script>\n";
  }
  const std::size_t body_end = page.rfind("</body>");
  page.insert(body_end == std::string::npos ? page.size() : body_end, scripts);
  write_file_atomically(out.string(), [&](std::ostream& o) { o << page; });
  return page.size();
}

}  // namespace fspm::cli
