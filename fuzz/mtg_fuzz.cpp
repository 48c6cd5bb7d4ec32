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

// Codes up to 1 MiB: the 256 MiB the writers allow would make a few hundred bytes of deep "+.+"
// nesting cost a second each, and the refusal above 1 MiB is the same code path.
constexpr std::uint64_t kFuzzCodeBytes = std::uint64_t{1} << 20;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = (fspm::set_warning_handler([](const std::string&) {}), true);
  (void)quiet;
  try {
    const fspm::Mtg g =
        fspm::read_mtg(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    std::ostringstream again;
    fspm::write_mtg(g, again, "again", kFuzzCodeBytes);
    try {
      (void)fspm::read_mtg(again.str(), "again");
    } catch (const fspm::Error&) {
    }
    const fspm::TreeGraph t = fspm::mtg_to_tree(g);
    std::ostringstream out;
    fspm::write_mtg(t, out, "out", kFuzzCodeBytes);
  } catch (const fspm::Error&) {
  }
  return 0;
}
