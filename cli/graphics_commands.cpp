// fspm mesh | render | view: the graphics commands, one file each (cli/mesh_command.cpp,
// cli/render_command.cpp, cli/view_command.cpp) over the input loading of io/.
#include "cli/commands.hpp"
#include "cli/graphics_options.hpp"

namespace fspm::cli {

void add_graphics_commands(CLI::App& app) {
  add_mesh_command(app);
  add_render_command(app);
  add_view_command(app);
}

}  // namespace fspm::cli
