#pragma once
// Names and one-line descriptions of the commands that need the graphics and experiments
// libraries: fspm-full registers them, fspm lists them in its --help and hands them over
// (forwarded_commands.cpp). One table, so the two listings cannot drift apart.
#include <array>

namespace fspm::cli {

struct FullCommand {
  const char* name;
  const char* description;
};

inline constexpr FullCommand kRunCommand{"run",
                                         "Run a parameter sweep described by an experiment file"};
inline constexpr FullCommand kCompareCommand{
    "compare", "Compute an experiment's [[comparison]] distances and t-tests over its results"};
inline constexpr FullCommand kReportCommand{
    "report", "Write DIR/report.md: what was run, tables, plots and renders of a sweep's results"};
inline constexpr FullCommand kResultsCommand{"results",
                                             "Export, summarize and merge sweep results"};
inline constexpr FullCommand kMeshCommand{
    "mesh", "Mesh a tree: generalized cylinders along its chains, leaves as quads"};
inline constexpr FullCommand kRenderCommand{
    "render", "Offscreen figure of a tree or a scene of trees with VTK"};
inline constexpr FullCommand kViewCommand{
    "view",
    "Real-time viewer: drag to orbit, right-drag to pan, wheel to zoom, [ ] growth steps, "
    "S shadows, R reset, Esc quit"};

inline constexpr FullCommand kDecodeCommand{
    "decode",
    "Decode a cluster-based tree (.clusters): skeleton mesh and clusters textured with "
    "L-system patches"};

inline constexpr FullCommand kCrownCommand{
    "crown", "A tree crown from one photograph (Argudo 2014): mesh and cubemaps"};

inline constexpr std::array<FullCommand, 9> kFullCommands = {
    kRunCommand,    kCompareCommand, kReportCommand, kResultsCommand, kMeshCommand,
    kRenderCommand, kViewCommand,    kDecodeCommand, kCrownCommand};

}  // namespace fspm::cli
