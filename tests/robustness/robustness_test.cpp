// Robustness catalogue: wrong input, pathological input and failing output, each run through the
// `fspm` executable as a user would. Every case names its arguments (with redirections where the
// case is about them), the exit code, a pattern of the one-line message, and output files that
// must not appear or change.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "tests/cli/run_command.hpp"
#include "tests/robustness/measured_run.hpp"

namespace fspm::testing {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string name;
  // Written into the case's scratch directory ({dir} and {src} expanded); "@PATH" copies the
  // file PATH.
  std::map<std::string, std::string> files;
  std::vector<std::string> setup;  // fspm commands that must succeed first
  std::string args;                // {dir}: scratch directory, {src}: source tree
  int exit_code;
  std::string message;                 // regex searched in stderr
  std::vector<std::string> untouched;  // files of {dir} that must not appear or change
  std::string shell_prefix;            // e.g. a lower file size limit; runs after the setup
  // When not 0, the command's peak resident memory (getrusage) must stay below this many MiB:
  // the request was refused before its memory was taken.
  std::uint64_t max_rss_mib = 0;

  Case(std::string name_, std::map<std::string, std::string> files_,
       std::vector<std::string> setup_, std::string args_, int exit_code_, std::string message_,
       std::vector<std::string> untouched_ = {}, std::string shell_prefix_ = {},
       std::uint64_t max_rss_mib_ = 0)
      : name(std::move(name_)),
        files(std::move(files_)),
        setup(std::move(setup_)),
        args(std::move(args_)),
        exit_code(exit_code_),
        message(std::move(message_)),
        untouched(std::move(untouched_)),
        shell_prefix(std::move(shell_prefix_)),
        max_rss_mib(max_rss_mib_) {}
};

std::string repeat(const std::string& s, int n) {
  std::string out;
  out.reserve(s.size() * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

std::string expand(std::string text, const fs::path& dir) {
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"{dir}", dir.string()}, {"{src}", FSPM_SOURCE_DIR}}) {
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at)) {
      text.replace(at, key.size(), value);
      at += value.size();
    }
  }
  return text;
}

const std::string kExamples = "{src}/examples";
const std::string kTree = kExamples + "/trees/small.nwk";
const std::string kScene = kExamples + "/environment/wall_scene.json";
const std::string kPoints = kExamples + "/environment/points.csv";
const std::string kGrowth = kExamples + "/environment/tree_a.toml";
const std::string kPlant = kExamples + "/greenlab/gl1_plant.toml";
const std::string kGrammar = kExamples + "/lsystems/parametric_tree.l";
const std::string kFull = "No space left on device";
// 1e300 and nan as little-endian doubles, in printf's octal escapes.
const std::string kHugeDouble = "\\234\\165\\000\\210\\074\\344\\067\\176";
const std::string kNanDouble = "\\000\\000\\000\\000\\000\\000\\370\\177";
// An MTG header: plants P (scale 1) of internodes E (scale 2); the code starts on line 9.
constexpr const char* kMtgHeader =
    "CODE:\tFORM-A\nCLASSES:\nSYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION\n$"
    "\t0\tFREE\tFREE\tIMPLICIT\nP\t1\tFREE\tFREE\tIMPLICIT\nE\t2\tFREE\tFREE\tIMPLICIT\nMTG:"
    "\nENTITY-CODE\n";
const std::string kSynthetic = "[experiment]\nname = \"s\"\n[model]\nkind = \"synthetic\"\n";

std::vector<Case> output_cases() {
  return {
      {"ExportCsvToFullStdout",
       {{"e.toml", kSynthetic}},
       {"run {dir}/e.toml --out {dir}/out"},
       "results export {dir}/out --csv >/dev/full",
       1,
       "standard output: cannot write: " + kFull},
      {"DeriveStringToFullStdout",
       {},
       {},
       "lsystem derive " + kGrammar + " --string >/dev/full",
       1,
       "standard output: cannot write: " + kFull},
      {"TreeInfoJsonToFullStdout",
       {},
       {},
       "tree info " + kTree + " --json >/dev/full",
       1,
       "standard output: cannot write: " + kFull},
      {"LightToFullStdout",
       {},
       {},
       "light --scene " + kScene + " --points " + kPoints + " >/dev/full",
       1,
       "standard output: cannot write: " + kFull},
      {"TreeInfoToClosedStdout",
       {},
       {},
       "tree info " + kTree + " >&-",
       1,
       "standard output: cannot write: Bad file descriptor"},
      // The output file opened while stdout is closed must not take its descriptor, and a
      // command whose report fails keeps none of its files.
      {"SimulateJsonToClosedStdout",
       {},
       {},
       "greenlab simulate " + kPlant + " -o {dir}/p.ctree --json >&-",
       1,
       "standard output: cannot write: Bad file descriptor",
       {"p.ctree"}},
      {"GrowJsonToFullStdoutKeepsNoTree",
       {},
       {},
       "grow " + kGrowth + " --years 2 -o {dir}/t.tree --json >/dev/full",
       1,
       "standard output: cannot write: " + kFull,
       {"t.tree"}},
      {"EncodeJsonToFullStdoutKeepsNoOutput",
       {},
       {},
       "encode " + kExamples +
           "/trees/open_a12.treeb -o {dir}/c.clusters --skeleton {dir}/s.tree "
           "--json >/dev/full",
       1,
       "standard output: cannot write: " + kFull,
       {"c.clusters", "s.tree"}},
      {"HelpToFullStdout", {}, {}, "--help >/dev/full", 1, "standard output: cannot write"},
      // A device is written in place, never replaced by a renamed file; the link keeps the
      // device safe should that ever regress.
      {"CtreeToFullDevice",
       {},
       {},
       "greenlab simulate " + kPlant + " -o {dir}/full.ctree",
       1,
       "full.ctree: cannot write: " + kFull,
       {},
       "ln -s /dev/full {dir}/full.ctree; "},
      {"LightToFullDevice",
       {},
       {},
       "light --scene " + kScene + " --points " + kPoints + " -o {dir}/full.csv",
       1,
       "full.csv: cannot write: " + kFull,
       {},
       "ln -s /dev/full {dir}/full.csv; "},
      {"EncodeToFullDevice",
       {},
       {},
       "encode " + kExamples + "/trees/open_a12.treeb -o {dir}/full.clusters",
       1,
       "full.clusters: cannot write: " + kFull,
       {},
       "ln -s /dev/full {dir}/full.clusters; "},
      {"OutputIsADirectory",
       {},
       {},
       "greenlab simulate " + kPlant + " -o {dir}/d.ctree",
       1,
       "d.ctree: is a directory, expected a file",
       {},
       "mkdir {dir}/d.ctree; "},
      {"CrownOutputDirectoryIsAFile",
       {{"taken", "x"}},
       {},
       "crown " + kExamples + "/crown/tree_front.png -o {dir}/taken",
       1,
       "taken: cannot create the output directory",
       {"taken"}},
      // Several outputs: all or none. The last one written goes to a full device; the others,
      // already written to their temporaries, must not appear.
      {"MeshAndItsMtlOnAFullDisk",
       {},
       {},
       "mesh " + kExamples + "/trees/open_a12.treeb -o {dir}/m.obj",
       1,
       "m.obj: cannot write: " + kFull,
       {"m.mtl"},
       "ln -s /dev/full {dir}/m.obj; "},
      // The crown's cubemaps description (read by view --ray-cast) took the last of a key given
      // twice.
      {"CrownCubemapsKeyGivenTwice",
       {},
       {"crown " + kExamples + "/crown/tree_front.png -o {dir}/c"},
       "view {dir}/c/crown.glb --ray-cast --frames 1 --size 64x64 --screenshot {dir}/o.png",
       1,
       "crown_cubemaps.json:[0-9]+:[0-9]+: duplicate key 'cubemap_size'",
       {"o.png"},
       "sed -i 's/\"cubemap_size\": \\([0-9]*\\),/\"cubemap_size\": \\1, \"cubemap_size\": 8,/' "
       "{dir}/c/crown_cubemaps.json; "},
      {"InterpretedObjAndItsMtlOnAFullDisk",
       {},
       {},
       "lsystem interpret " + kGrammar + " -o {dir}/m.obj",
       1,
       "m.obj: cannot write: " + kFull,
       {"m.mtl"},
       "ln -s /dev/full {dir}/m.obj; "},
      {"CrownWithPreviewOnAFullDisk",
       {},
       {},
       "crown " + kExamples + "/crown/tree_front.png -o {dir}/out --preview {dir}/p.png",
       1,
       "p.png: cannot write: " + kFull,
       {"out", "out/crown.glb", "out/crown_color_cubemap.png", "out/crown_radius_cubemap.exr",
        "out/crown_cubemaps.json", "out/crown_relief.png", "out/crown_mask.png"},
       "ln -s /dev/full {dir}/p.png; "},
      {"CrownMeshFileOnAFullDisk",
       {},
       {},
       "crown " + kExamples + "/crown/tree_front.png -o {dir}/c.obj --side-mask {dir}/s.png",
       1,
       "s.png: cannot write: " + kFull,
       {"c.obj", "c.mtl", "c_color_cubemap.png", "c_radius_cubemap.exr", "c_relief.png",
        "c_mask.png"},
       "ln -s /dev/full {dir}/s.png; "},
      {"TreeFileOverTheSizeLimit",
       {},
       {},
       "tree convert " + kExamples + "/trees/open_a12.treeb {dir}/big.tree",
       1,
       "big.tree: cannot write: File too large",
       {"big.tree"},
       "ulimit -f 4; trap '' XFSZ; "},
  };
}

std::vector<Case> nesting_cases() {
  const std::string deep = repeat("[", 100000) + repeat("]", 100000);
  const std::string deep_tree = repeat("(", 1000001) + "1" + repeat(")", 1000001) + ";";
  return {
      {"DeepJsonSceneForLight",
       {{"deep.json", deep}},
       {},
       "light --scene {dir}/deep.json --points " + kPoints + " -o {dir}/light.csv",
       1,
       "deep.json:1:65: nesting deeper than the limit of 64 levels",
       {"light.csv"}},
      {"DeepJsonSceneForGrow",
       {{"deep.json", deep}},
       {},
       "grow " + kGrowth + " --years 1 --scene {dir}/deep.json -o {dir}/t.tree",
       1,
       "deep.json:1:65: nesting deeper than the limit of 64 levels",
       {"t.tree"}},
      {"HalfDeepJsonScene",
       {{"deep.json", repeat("[", 50000)}},
       {},
       "light --scene {dir}/deep.json --points " + kPoints,
       1,
       "nesting deeper than the limit"},
      {"DeepToml",
       {{"deep.toml", "years = " + deep}},
       {},
       "grow {dir}/deep.toml -o {dir}/t.tree",
       1,
       "deep.toml.*nested",
       {"t.tree"}},
      {"DeepNewick",
       {{"deep.nwk", deep_tree}},
       {},
       "tree convert {dir}/deep.nwk {dir}/t.tree",
       1,
       "deep.nwk:1:1000001: nesting deeper than the limit of 1000000 levels",
       {"t.tree"}},
      {"DeepBrackets",
       {{"deep.l", "Axiom: " + repeat("[", 1000001) + repeat("]", 1000001) + "\n"}},
       {},
       "lsystem derive {dir}/deep.l",
       1,
       "deep.l:1:1000008: nesting deeper than the limit of 1000000 levels"},
      {"LongLineInError",
       {{"long.l", "Axiom: F\nF --> F(" + repeat("1+", 100000) + "\n"}},
       {},
       "lsystem derive {dir}/long.l",
       1,
       "long.l:2"},
  };
}

std::vector<Case> wrong_input_cases() {
  const std::string grammar = "#define LEN 2\nAxiom: F(LEN)\nF(x) --> F(x*LEN)\n";
  const std::string sweep =
      "[experiment]\nname = \"d\"\n[model]\nkind = \"lsystem\"\nfile = \"g.l\"\n"
      "[sweep]\nsteps = [1]\n\"define.LNE\" = [1, 2]\n";
  return {
      {"MisspelledSweepDefine",
       {{"g.l", grammar}, {"e.toml", sweep}},
       {},
       "run {dir}/e.toml --out {dir}/out",
       1,
       "e.toml:8: define.LNE: cannot override .*never uses it \\(did you mean 'LEN'\\?\\)",
       {"out"}},
      {"MisspelledDefineOption",
       {{"g.l", grammar}},
       {},
       "lsystem derive {dir}/g.l --define zz=1",
       1,
       "g.l: cannot override the macro 'zz'"},
      {"NegativeProbability",
       {{"p.l", "Axiom: F\nF --> FF : -0.5\nF --> F : 1.5\n"}},
       {},
       "lsystem derive {dir}/p.l --steps 2",
       1,
       "p.l:2:1: a production probability must be a finite weight >= 0, got -0.5"},
      {"TruncatedGrammar",
       {{"t.l", "Axiom: F\nF --> F[+F[-F"}},
       {},
       "lsystem derive {dir}/t.l",
       1,
       "t.l:2:11: this '\\[' is never closed"},
      {"UnbalancedAxiom",
       {{"u.l", "Axiom: F]F\n"}},
       {},
       "lsystem derive {dir}/u.l",
       1,
       "u.l:1:9: '\\]' without a matching '\\['"},
      {"NegativeCycles",
       {},
       {},
       "greenlab simulate " + kPlant + " --cycles -3 -o {dir}/p.ctree",
       1,
       "--cycles: expected a number in \\[0, 10000\\], got '-3'",
       {"p.ctree"}},
      {"NanTimeLimit",
       {{"e.toml", kSynthetic}},
       {},
       "run {dir}/e.toml --out {dir}/out --time-limit nan",
       1,
       "--time-limit: expected a number in \\(0, 1000000000\\], got 'nan'",
       {"out"}},
      {"NegativeYears",
       {},
       {},
       "grow " + kGrowth + " --years -1 -o {dir}/t.tree",
       1,
       "--years: expected a number in \\[0, 1000\\]",
       {"t.tree"}},
      {"NegativeAge",
       {},
       {"greenlab simulate " + kPlant + " -o {dir}/p.ctree"},
       "greenlab reconstruct {dir}/p.ctree --age -2 -o {dir}/t.tree",
       1,
       "--age: expected a number in",
       {"t.tree"}},
      {"NanAge",
       {},
       {"greenlab simulate " + kPlant + " -o {dir}/p.ctree"},
       "greenlab reconstruct {dir}/p.ctree --age nan -o {dir}/t.tree",
       1,
       "--age: expected a number in .*got 'nan'",
       {"t.tree"}},
      {"NanMainSkeleton",
       {},
       {},
       "distance " + kTree + " " + kTree + " --main-skeleton nan",
       1,
       "--main-skeleton: expected a number in .*got 'nan'"},
      {"NegativeSkeletonRadius",
       {},
       {},
       "adapt " + kTree + " --scene " + kScene + " --skeleton-radius -1 -o {dir}/t.tree",
       1,
       "--skeleton-radius: expected a number in \\(0, 1000\\], got '-1'",
       {"t.tree"}},
      {"NanGrownBrightest",
       {},
       {},
       "adapt " + kTree + " --scene " + kScene + " --grown-brightest 0 1 nan -o {dir}/t.tree",
       1,
       "--grown-brightest: expected a number in .*got 'nan'",
       {"t.tree"}},
      // An unsigned option must not wrap -1 round to 2^64 - 1.
      {"NegativeScanSeed",
       {},
       {},
       "scan " + kTree + " --seed -1 -o {dir}/p.ply",
       1,
       "--seed: expected a number in \\[0, .*got '-1'",
       {"p.ply"}},
      {"HugeEncodeSeed",
       {},
       {},
       "encode " + kTree + " --seed 99999999999999999999 -o {dir}/c.clusters",
       1,
       "--seed: expected a number in \\[0, ",
       {"c.clusters"}},
      {"NegativeJobs",
       {{"e.toml", kSynthetic}},
       {},
       "run {dir}/e.toml -j -1 --out {dir}/out",
       1,
       "--jobs: expected a number in \\[0, 4096\\], got '-1'",
       {"out"}},
      {"NanGeometry",
       {{"n.tree", "fspm-tree 1\nnodes 1\n0 - internode 0 0 0 0 0 0 0 nan 0 0 1 1 0.1 0\n"}},
       {},
       "tree convert {dir}/n.tree {dir}/m.treeb",
       1,
       "n.tree:3:[0-9]+: expected a finite number for end, found 'nan'",
       {"m.treeb"}},
      {"NanGeometryFromGrammar",
       {{"n.l", "Axiom: F(sqrt(-1))\n"}},
       {},
       "lsystem interpret {dir}/n.l -o {dir}/t.tree",
       1,
       "t.tree: cannot write node 0: its (end|length) is nan or infinite",
       {"t.tree"}},
      {"OutputIsInput",
       {{"p.toml", "@" + kPlant}},
       {},
       "greenlab simulate {dir}/p.toml -o {dir}/./p.toml",
       1,
       "p.toml: the output would overwrite an input",
       {"p.toml"}},
      {"ExportOverItsDatabase",
       {{"e.toml", kSynthetic}},
       {"run {dir}/e.toml --out {dir}/out"},
       "results export {dir}/out --csv -o {dir}/out/results.sqlite",
       1,
       "results.sqlite: the output would overwrite an input",
       {"out/results.sqlite"}},
      {"HalfAnMtg",
       {{"h.mtg", "CODE:\tFORM-A\n\nCLASSES:\nSYMBOL\tSCALE\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:1: no 'MTG:' section",
       {"t.tree"}},
      {"MtgCutAfterItsHeader",
       {{"h.mtg", "CODE:\tFORM-A\nMTG:\nENTITY-CODE\t\tLength\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:3: the MTG: table has no entity after its ENTITY-CODE header",
       {"t.tree"}},
      // What OpenAlea's reader cannot make sense of either: file:line:column and the code.
      {"MtgCaretOpeningAColumn",
       {{"h.mtg", std::string(kMtgHeader) + "/P1/E1\n\t^<E2\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:10:2: entity code '\\^<E2': '\\^' continues an entity of its own column",
       {"t.tree"}},
      {"MtgUndeclaredSymbol",
       {{"h.mtg", std::string(kMtgHeader) + "/Q1/E1\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:9:1: entity code '/Q1/E1': symbol 'Q' is not declared in CLASSES",
       {"t.tree"}},
      {"MtgRangeCountingDown",
       {{"h.mtg", std::string(kMtgHeader) + "/P1/E5<<E3\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:9:7: entity code '/P1/E5<<E3': a range from E5 to E3 must count up",
       {"t.tree"}},
      {"MtgColumnMatchingNone",
       {{"h.mtg", std::string(kMtgHeader) + "/P1/E1\n\t\t+E2\n\t+E3\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:11:2: entity code '\\+E3' is in column 2, which matches no column",
       {"t.tree"}},
      // OpenAlea's reader reads no entity at all from this file.
      {"MtgBranchesInTheFirstColumn",
       {{"h.mtg", std::string(kMtgHeader) + "/P1/E1\n+E2\n+E3\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:11: a branch \\('\\+' in the first column\\) closes here that no line opened",
       {"t.tree"}},
      {"MtgStarWithALabel",
       {{"h.mtg", std::string(kMtgHeader) + "/P1/E1\n*E2\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:10:1: entity code '\\*E2': '\\*' repeats the entity above",
       {"t.tree"}},
      {"TreebWithTrailingGarbage",
       {},
       {"tree convert " + kTree + " {dir}/g.treeb"},
       "tree info {dir}/g.treeb",
       1,
       "g.treeb: unexpected data after the end of the tree",
       {},
       "printf 'junk' >> {dir}/g.treeb; "},
      // The final age is the double at byte 24 of a .ctree.
      {"CtreeWithHugeAge",
       {},
       {"greenlab simulate " + kPlant + " -o {dir}/p.ctree"},
       "greenlab reconstruct {dir}/p.ctree -o {dir}/t.tree",
       1,
       "p.ctree: the final age 1e\\+300 is out of range",
       {"t.tree"},
       "printf '" + kHugeDouble +
           "' | dd of={dir}/p.ctree bs=1 seek=24 conv=notrunc 2>/dev/null; "},
      {"CtreeWithNanAge",
       {},
       {"greenlab simulate " + kPlant + " -o {dir}/p.ctree"},
       "greenlab reconstruct {dir}/p.ctree -o {dir}/t.tree",
       1,
       "p.ctree: the final age nan is out of range",
       {"t.tree"},
       "printf '" + kNanDouble + "' | dd of={dir}/p.ctree bs=1 seek=24 conv=notrunc 2>/dev/null; "},
  };
}

std::vector<Case> message_cases() {
  return {
      {"DirectoryAsTree", {}, {}, "tree info {dir}", 1, "is a directory, expected a file"},
      {"DirectoryAsParameters",
       {},
       {},
       "grow {dir} -o {dir}/t.tree",
       1,
       "is a directory, expected a file",
       {"t.tree"}},
      {"MissingFile",
       {},
       {},
       "tree info {dir}/none.tree",
       1,
       "none.tree: cannot open for reading: No such file or directory"},
      {"HugeDerivationLength",
       {{"h.l", "derivation length: 2000000000\nAxiom: F\n"}},
       {},
       "lsystem derive {dir}/h.l",
       1,
       "h.l:1:19: derivation length must be an integer in \\[0, 1000000000\\]"},
      {"NegativeSteps",
       {},
       {},
       "lsystem derive " + kGrammar + " --steps -1",
       1,
       "--steps: expected a number in \\[0, 1000000000\\], got '-1'"},
      {"HugeValuesInTtest",
       {{"a.txt", "1e308\n-1e308\n1e308\n"}, {"b.txt", "1\n2\n3\n"}},
       {},
       "stats ttest {dir}/a.txt {dir}/b.txt",
       1,
       "too large"},
      // A text reader stops at the first NUL byte instead of reading a gigabyte.
      {"EndlessInput",
       {},
       {},
       "grow /dev/zero -o {dir}/t.tree",
       1,
       "/dev/zero: binary data \\(a NUL byte at byte 0\\), expected a text file",
       {"t.tree"}},
      {"EndlessNumbers",
       {},
       {},
       "stats describe /dev/zero",
       1,
       "/dev/zero: binary data \\(a NUL byte at byte 0\\), expected a text file"},
      {"BinaryViewFile",
       {{"b.v", std::string("angle factor: 8\n\0\1\2: 3\n", 23)}},
       {},
       "lsystem interpret " + kGrammar + " --view {dir}/b.v -o {dir}/t.tree",
       1,
       "b.v: binary data \\(a NUL byte at byte 16\\), expected a text file",
       {"t.tree"}},
      {"EmptyGrowthParameters",
       {{"empty.toml", "# nothing yet\n"}},
       {},
       "grow {dir}/empty.toml -o {dir}/t.tree",
       1,
       "empty.toml:1: no parameter in the file",
       {"t.tree"}},
  };
}

// The memory limit (--memory-limit) is checked before every large allocation, whether the size
// comes from a file or from an option; the message names the estimate and the limit.
std::vector<Case> memory_cases() {
  const std::string doubling = "Axiom: F\nF --> FF\n";
  // A star of 3000 leaves against itself keeps 3001 rows of 3001 doubles pending twice
  // (144 096 016 bytes) and matches the 3000 x 3000 children of the roots (72 000 000 bytes):
  // 206.1 MiB.
  const std::string star = "(" + repeat("1,", 2999) + "1);";
  const std::string limit = "above the memory limit of (1|100) MiB \\(--memory-limit\\)";
  // Twenty parameters per module, doubling at every step: the string outgrows any machine.
  const std::string wide = "A(" + repeat("1,", 19) + "1)";
  const std::string params = "A(a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,q,r,s,t)";
  return {
      // Under an address-space limit far below half the machine's memory the default budget
      // follows the limit: a clean error, not std::bad_alloc.
      {"DoublingModulesUnderAnAddressSpaceLimit",
       {{"w.l", "derivation length: 40\nAxiom: " + wide + "\n" + params + " --> " + params +
                    params + "\n"}},
       {},
       "lsystem derive {dir}/w.l --json",
       1,
       "above the memory limit of [0-9.]+ MiB \\(--memory-limit\\)",
       {},
       "ulimit -v 1500000; "},
      {"LsystemStringOverTheMemoryLimit",
       {{"g.l", "derivation length: 40\n" + doubling}},
       {},
       "--memory-limit 1M lsystem interpret {dir}/g.l -o {dir}/t.tree",
       1,
       "g.l: the L-system string at derivation step 19 needs about 1.5 MiB, " + limit,
       {"t.tree"}},
      {"LsystemStepsOptionOverTheMemoryLimit",
       {{"g.l", doubling}},
       {},
       "lsystem interpret {dir}/g.l --steps 40 -o {dir}/t.tree --memory-limit 1M",
       1,
       "g.l: the L-system string at derivation step 19 needs about 1.5 MiB, " + limit,
       {"t.tree"}},
      {"DistanceOverTheMemoryLimit",
       {{"a.nwk", star}},
       {},
       "--memory-limit 100M distance {dir}/a.nwk {dir}/a.nwk",
       1,
       "the edit distance of trees of 3001 and 3001 nodes needs about 206.1 MiB, " + limit,
       {},
       {},
       60},
      {"SweepAxisOverTheMemoryLimit",
       {{"e.toml", kSynthetic + "[sweep]\n\"x.a\" = { range = [0, 100000000] }\n"}},
       {},
       "--memory-limit 100M run {dir}/e.toml --out {dir}/out",
       1,
       "e.toml:6:[0-9]+: .*a sweep axis of 100000000 values needs about 3.7 GiB, " + limit,
       {"out"}},
      {"MeshOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 100K mesh " + kExamples + "/trees/open_a12.treeb -o {dir}/m.ply",
       1,
       "a mesh of [0-9]+ triangles needs about [0-9.]+ KiB, above the memory limit of 100 KiB",
       {"m.ply"}},
      {"ReconstructionOverTheMemoryLimit",
       {},
       {"greenlab simulate " + kPlant + " -o {dir}/p.ctree"},
       "--memory-limit 10K greenlab reconstruct {dir}/p.ctree -o {dir}/t.tree",
       1,
       "the explicit tree of [0-9]+ metamers needs about [0-9.]+ KiB, above the memory limit of "
       "10 KiB",
       {"t.tree"}},
      {"RunCountFromTheFile",
       {{"e.toml", kSynthetic + "[sweep]\n\"x.a\" = { range = [0, 100000] }\n" +
                       "[sampling]\nsamples = 100000\n[sampling.parameters]\n" +
                       "\"x.u\" = { uniform = [0, 1] }\n"}},
       {},
       "run {dir}/e.toml --out {dir}/out",
       1,
       "e.toml:1: the experiment has 10000000000 runs, more than the limit of 1000000000",
       {"out"}},
      {"RunCountFromTheReplicatesOption",
       {{"e.toml", kSynthetic + "[sweep]\n\"x.a\" = { range = [0, 100000] }\n"}},
       {},
       "run {dir}/e.toml --replicates 100000 --out {dir}/out",
       1,
       "e.toml: --replicates 100000: the experiment has 10000000000 runs, more than the limit of "
       "1000000000",
       {"out"}},
      // Binary readers keep what they read: a device (through a link named like the format)
      // is cut at the memory limit, not read up to the 1 GiB bound of inputs.
      {"TreebFromADeviceOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 1M tree info {dir}/z.treeb",
       1,
       "z.treeb: a pipe or device holding more than the memory limit of 1 MiB \\(--memory-limit\\)",
       {},
       "ln -s /dev/zero {dir}/z.treeb; "},
      {"CtreeFromADeviceOverTheMemoryLimit",
       {},
       {},
       "greenlab reconstruct {dir}/z.ctree -o {dir}/t.tree --memory-limit 1M",
       1,
       "z.ctree: a pipe or device holding more than the memory limit of 1 MiB \\(--memory-limit\\)",
       {"t.tree"},
       "ln -s /dev/zero {dir}/z.ctree; "},
      {"ClustersFromADeviceOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 1M decode {dir}/z.clusters -o {dir}/t.tree",
       1,
       "z.clusters: a pipe or device holding more than the memory limit of 1 MiB",
       {"t.tree"},
       "ln -s /dev/zero {dir}/z.clusters; "},
      {"BinaryPlyOverTheMemoryLimit",
       {{"big.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 200000\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n" +
             std::string(2400000, 'a')}},
       {},
       "--memory-limit 1M encode {dir}/big.ply -o {dir}/c.clusters",
       1,
       "big.ply: reading the whole file needs about 2.3 MiB, above the memory limit of 1 MiB",
       {"c.clusters"}},
      {"TruncatedLas",
       {{"cut.las", std::string("LASF\0\0", 6)}},
       {},
       "encode {dir}/cut.las -o {dir}/c.clusters",
       1,
       "cut.las: the file ends inside the file source id, global encoding and GUID \\(6 bytes\\) "
       "at byte 4",
       {"c.clusters"}},
      {"CompressedLasPointFormat",
       {{"laz.las", "LASF" + std::string(20, '\0') + "\x01\x02" + std::string(68, '\0') + "\xe3" +
                        std::string(1, '\0') + "\xe3" + std::string(7, '\0') + "\x83" +
                        std::string(200, '\0')}},
       {},
       "encode {dir}/laz.las -o {dir}/c.clusters",
       1,
       "laz.las: the point data is compressed \\(LAZ, point format byte 131\\); decompress it "
       "first",
       {"c.clusters"}},
      {"ZeroMemoryLimit",
       {},
       {},
       "--memory-limit 0 tree info " + kTree,
       1,
       "--memory-limit: expected a size such as 512M or 2G, got '0'"},
  };
}

// Options of the whole command line given where the command has none, and empty option values,
// which CLI11 would otherwise read as the option's default.
std::vector<Case> option_cases() {
  const std::string scan = "scan " + kTree + " -o {dir}/p.ply";
  return {
      // Without a display the render runs again under xvfb-run and reads its input a second
      // time: a FIFO, drained by the first read, blocked it for ever.
      {"RenderOfAFifoWithoutADisplay",
       {},
       {"scan " + kExamples + "/trees/open_a12.treeb -o {dir}/v.xyz --density 2000"},
       "render {dir}/p.xyz -o {dir}/o.png",
       1,
       "p.xyz: not a regular file \\(a pipe or device\\): without an X display the command runs "
       "again under xvfb-run",
       {"o.png"},
       "mkfifo {dir}/p.xyz; (timeout 20 sh -c 'cat {dir}/v.xyz > {dir}/p.xyz' >/dev/null 2>&1 &); "
       "timeout 60 env -u DISPLAY -u WAYLAND_DISPLAY "},
      // A joining distance of a denormal is raised to a millionth of the mesh's extent; the
      // linking of its parts then searched a grid of such cells for gaps a million times wider.
      {"StagesJoinDistanceOfADenormal",
       {},
       {},
       "stages " + kExamples + "/trees/y_tubes.obj --at 0.5 -o {dir}/o.tree --join-distance 1e-320",
       0,
       "",
       {},
       "timeout 60 "},
      {"GlobalJsonOnACommandWithout",
       {},
       {},
       "--json tree convert " + kTree + " {dir}/t.tree",
       1,
       "^fspm: error: --json: 'fspm tree convert' has no JSON output\n$",
       {"t.tree"}},
      {"GlobalJsonAfterACommandWithout",
       {},
       {},
       "tree convert " + kTree + " {dir}/t.tree --json",
       1,
       "^fspm: error: --json: 'fspm tree convert' has no JSON output\n$",
       {"t.tree"}},
      {"EmptySeed",
       {},
       {},
       scan + " --seed ''",
       1,
       "^fspm: error: --seed: expected a number in \\[0, [0-9]+\\], got '' \\(see fspm scan "
       "--help\\)\\n$",
       {"p.ply"}},
      {"EmptyTextOption",
       {},
       {},
       "tree info " + kTree + " --format ''",
       1,
       "^fspm: error: --format: expected a value, got an empty string \\(see fspm tree info "
       "--help\\)\\n$"},
      {"EmptyEnumOption",
       {},
       {},
       "distance " + kTree + " " + kTree + " --cost ''",
       1,
       "^fspm: error: --cost: '' is not a choice"},
      {"EmptyListElement",
       {},
       {},
       "adapt " + kTree + " --scene " + kScene + " --grown-brightest 0 '' 1 -o {dir}/t.tree",
       1,
       "^fspm: error: --grown-brightest: expected a number in .*got ''",
       {"t.tree"}},
      {"EmptyMemoryLimit",
       {},
       {},
       "--memory-limit '' tree info " + kTree,
       1,
       "^fspm: error: --memory-limit: expected a value, got an empty string"},
      {"EmptyPositional",
       {},
       {},
       "tree convert " + kTree + " ''",
       1,
       "^fspm: error: OUT: expected a value, got an empty string"},
      {"EmptyOptionOfAFullCommand",
       {{"e.toml", kSynthetic}},
       {},
       "run {dir}/e.toml --jobs '' --out {dir}/out",
       1,
       "^fspm: error: --jobs: expected a number in \\[0, 4096\\], got ''",
       {"out"}},
      // CLI11 reads "--steps=" as the option without its value.
      {"EmptyValueAfterEquals",
       {},
       {},
       "lsystem derive " + kGrammar + " --steps=",
       1,
       "^fspm: error: --steps: 1 required .* missing"},
  };
}

// CRC-32 of PNG chunks (ISO 3309, as in the PNG specification's annex D), bit by bit.
std::uint32_t png_crc(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (const char ch : bytes) {
    crc ^= static_cast<unsigned char>(ch);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

std::string big_endian(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}

std::string png_chunk(const std::string& type, const std::string& data) {
  return big_endian(static_cast<std::uint32_t>(data.size())) + type + data +
         big_endian(png_crc(type + data));
}

// A valid PNG of one RGB pixel whose header declares `width` x `height`: a few dozen bytes that
// promise gigabytes.
std::string lying_png(std::uint32_t width, std::uint32_t height) {
  const std::string ihdr =
      big_endian(width) + big_endian(height) + std::string("\x08\x02\0\0\0", 5);
  // zlib: one stored block of the row's filter byte and three samples, then its Adler-32.
  const std::string idat("\x78\x01\x01\x04\x00\xfb\xff\0\0\0\0\x00\x04\x00\x01", 15);
  return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", idat) +
         png_chunk("IEND", "");
}

const std::string kPlyHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n";

// Input that is wrong in a way a reader could miss: refused, with the file (and line, key) named.
std::vector<Case> named_input_cases() {
  return {
      {"LightWithZeroDirections",
       {},
       {},
       "light --scene " + kScene + " --points " + kPoints + " --directions 0",
       1,
       "--directions: expected a number in \\[1, 1048576\\], got '0'"},
      {"StagesSkeletonOverItsOutput",
       {},
       {},
       "stages " + kExamples +
           "/trees/open_a12.treeb --at 0.5 --skeleton {dir}/o.tree -o "
           "{dir}/./o.tree",
       1,
       "o.tree: --skeleton '.*o.tree' and -o name the same file",
       {"o.tree"}},
      {"JsonSceneWithAKeyTwice",
       {{"dup.json",
         "{\n  \"sky\": { \"directions\": 64 },\n  \"sky\": { \"directions\": 8 }\n}\n"}},
       {},
       "light --scene {dir}/dup.json --points " + kPoints,
       1,
       "dup.json:3:3: duplicate key 'sky' \\(first given on line 2\\)"},
      {"JsonKeyTwiceThroughAnEscape",
       {{"dup.json", "{\"sky\": {\"directions\": 64, \"direction\\u0073\": 8}}"}},
       {},
       "light --scene {dir}/dup.json --points " + kPoints,
       1,
       "dup.json:1:28: duplicate key 'directions'"},
      {"TomlWithAKeyTwice",
       {{"dup.toml", "years = 3\nyears = 4\n"}},
       {},
       "grow {dir}/dup.toml -o {dir}/t.tree",
       1,
       "dup.toml:2:[0-9]+: .*cannot redefine existing .*'years'",
       {"t.tree"}},
      // TOML forbids defining a key or table twice (TOML 1.0, "Keys"); every TOML input refuses it
      // with the file and line, through the one reader (fspm/toml_text.hpp).
      {"GreenlabParametersWithATableTwice",
       {{"dup.toml", "[functional]\nbiomass = 1\n[functional]\nbiomass = 2\n"}},
       {},
       "greenlab simulate {dir}/dup.toml -o {dir}/p.ctree",
       1,
       "dup.toml:3:[0-9]+: .*cannot redefine existing table 'functional'",
       {"p.ctree"}},
      {"ExperimentWithAKeyTwice",
       {{"dup.toml", kSynthetic + "[sweep]\n\"x.a\" = [1, 2]\n\"x.a\" = [3]\n"}},
       {},
       "run {dir}/dup.toml --out {dir}/out",
       1,
       "dup.toml:7:[0-9]+: .*cannot redefine existing array",
       {"out"}},
      {"GrowthParametersDottedKeyOverAValue",
       {{"dup.toml", "years = 3\nyears.max = 4\n"}},
       {},
       "grow {dir}/dup.toml -o {dir}/t.tree",
       1,
       "dup.toml:2:[0-9]+: .*cannot redefine existing integer as dotted key-value pair",
       {"t.tree"}},
      {"SkyFileWithAKeyTwice",
       {{"sky.toml", "[sky]\ndate = \"2024-06-21\"\ndate = \"2024-12-21\"\n"}},
       {},
       "adapt " + kExamples + "/trees/open_a12.treeb --scene " + kScene +
           " --sky {dir}/sky.toml -o {dir}/a.tree",
       1,
       "sky.toml:3:[0-9]+: .*cannot redefine existing .*'date'",
       {"a.tree"}},
      {"StrayBytesInABinaryPly",
       {{"s.ply", kPlyHeader + std::string(24, '\0') + "junk"}},
       {},
       "encode {dir}/s.ply -o {dir}/c.clusters",
       1,
       "s.ply: the header declares 2 vertex \\(24 bytes of data\\), the file holds 28 bytes after "
       "its header \\(to byte [0-9]+\\): a header count that does not match the data",
       {"c.clusters"}},
      // 2 x 10^18 records of 12 bytes pass 2^64 bytes: said so, not converted (found by fuzzing).
      {"BinaryPlyCountBeyondSixtyFourBits",
       {{"s.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000000000000\nproperty "
         "float x\nproperty float y\nproperty float z\nend_header\n" +
             std::string(24, '\0')}},
       {},
       "encode {dir}/s.ply -o {dir}/c.clusters",
       1,
       "s.ply: the header declares 2000000000000000000 vertex \\(more than 10\\^19 bytes of "
       "data\\), the file holds 24 bytes",
       {"c.clusters"}},
      {"BinaryPlyShorterThanItsHeader",
       {{"s.ply", kPlyHeader + std::string(20, '\0')}},
       {},
       "encode {dir}/s.ply -o {dir}/c.clusters",
       1,
       "s.ply: the header declares 2 vertex \\(24 bytes of data\\), the file holds 20 bytes",
       {"c.clusters"}},
      {"AsciiPlyLongerThanItsHeader",
       {{"a.ply",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n0 0 0\n1 1 1\n2 2 2\n"}},
       {},
       "encode {dir}/a.ply -o {dir}/c.clusters",
       1,
       "a.ply:9: more lines than the header declares \\(1 vertex\\)",
       {"c.clusters"}},
      // Bytes 8-11 of a GLB hold its total length, here 16 bytes short of the file's.
      {"GlbWhoseHeaderLengthLies",
       {},
       {"mesh " + kExamples + "/trees/growth_units.mtg -o {dir}/t.glb"},
       "encode {dir}/t.glb -o {dir}/c.clusters",
       1,
       "t.glb: the GLB header gives a length of [0-9]+ bytes, the file has [0-9]+",
       {"c.clusters"},
       "printf 0123456789abcdef >> {dir}/t.glb; "},
      {"EncodeToATextExtension",
       {},
       {},
       "encode " + kExamples + "/trees/open_a12.treeb -o {dir}/o.txt",
       1,
       "o.txt: -o: encode writes the cluster format, expected a .clusters file",
       {"o.txt"}},
      {"CrownObjLinkedToAText",
       {{"notes.txt", "just some notes\n"}},
       {},
       "mesh {dir}/c.obj -o {dir}/o.obj",
       1,
       "c.obj: no triangle in the OBJ file \\(0 vertices, no face of 3 or more\\)",
       {"o.obj"},
       "ln -s {dir}/notes.txt {dir}/c.obj; "},
      {"HeaderOnlyPointFile",
       {{"e.xyz", "x y z\n"}},
       {},
       "encode {dir}/e.xyz -o {dir}/c.clusters",
       1,
       "e.xyz: no point in the file",
       {"c.clusters"}},
      {"EmptyPlyPointFile",
       {{"e.ply",
         "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n"}},
       {},
       "encode {dir}/e.ply -o {dir}/c.clusters",
       1,
       "e.ply: no point in the file",
       {"c.clusters"}},
      // A link to itself: the system's refusal names the file, exit 1, not an internal error.
      {"InputIsALinkLoop",
       {},
       {},
       "mesh {dir}/loop.treeb -o {dir}/m.obj",
       1,
       "^fspm: error: .*loop.treeb: Too many levels of symbolic links\\n$",
       {"m.obj"},
       "ln -s loop.treeb {dir}/loop.treeb; "},
      // libpng prints its own complaint on stderr; it joins the one line of the error.
      {"TruncatedPngIsOneLine",
       {},
       {},
       "crown {dir}/cut.png -o {dir}/out",
       1,
       "^fspm: error: .*cut.png: cannot decode image: [^\\n]*hit end of file[^\\n]*\\n$",
       {"out"},
       "head -c 20000 " + kExamples + "/crown/tree_front.png > {dir}/cut.png; "},
      {"UnknownCommandIsNamed",
       {},
       {},
       "tree frobnicate",
       1,
       "^fspm: error: unknown command 'frobnicate' \\(see fspm tree --help\\)\\n$"},
      {"NegativeMtgScale",
       {},
       {},
       "--mtg-scale -1 tree info " + kExamples + "/trees/growth_units.mtg",
       1,
       "--mtg-scale: Value -1 not in range 0 to 1000"},
      {"EncodeOfThreePointsNamesTheFile",
       {{"t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}},
       {},
       "encode {dir}/t.obj -o {dir}/c.clusters",
       1,
       "t.obj: no trunk diameter could be fitted",
       {"c.clusters"}},
      {"MeshWithoutFaceForStages",
       {{"v.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"}},
       {},
       "stages {dir}/v.obj --at 0.5 -o {dir}/t.tree",
       1,
       "v.obj: no triangle in the mesh \\(3 vertices, no face\\)",
       {"t.tree"}},
      {"LatinOneSeparatorKeepsItsFirstPoint",
       {{"l.xyz",
         "1.0\xa0"
         "2.0\xa0"
         "3.0\n4 5 6\n"}},
       {},
       "encode {dir}/l.xyz -o {dir}/c.clusters",
       1,
       "l.xyz:1: expected at least 3 values \\(x y z\\), got 1",
       {"c.clusters"}},
  };
}

// Images are checked against a maximum size and the memory limit from their header, before a
// byte of pixels is allocated: a 1 x 1 PNG declaring 20 000 x 20 000 costs nothing.
std::vector<Case> image_cases() {
  const std::string limit = "above the memory limit of 1 GiB \\(--memory-limit\\)";
  return {
      {"CrownPhotoDeclaringTwentyThousandSquared",
       {{"big.png", lying_png(20000, 20000)}},
       {},
       "--memory-limit 1G crown {dir}/big.png -o {dir}/out",
       1,
       "big.png: the image header declares 20000 x 20000 pixels, more than the largest image "
       "read \\(268435456 pixels, 16384 x 16384\\)",
       {"out"},
       {},
       300},
      {"CrownPhotoDeclaringTenThousandSquared",
       {{"big.png", lying_png(10000, 10000)}},
       {},
       "--memory-limit 1G crown {dir}/big.png -o {dir}/out",
       1,
       "big.png: an image of 10000 x 10000 pixels and 3 channels needs about 1.4 GiB, " + limit,
       {"out"},
       {},
       300},
      {"CrownMaskDeclaringTenThousandSquared",
       {{"big.png", lying_png(10000, 10000)}},
       {},
       "--memory-limit 1G crown " + kExamples +
           "/crown/tree_front.png --mask {dir}/big.png -o "
           "{dir}/out",
       1,
       "big.png: an image of 10000 x 10000 pixels and 3 channels needs about 1.4 GiB, " + limit,
       {"out"},
       {},
       300},
      {"CrownMaskOfAnotherSize",
       {{"big.png", lying_png(4000, 3000)}},
       {},
       "crown " + kExamples + "/crown/tree_front.png --mask {dir}/big.png -o {dir}/out",
       1,
       "big.png: the mask is 4000 x 3000 pixels but the photograph 256 x 256: they must be the "
       "same size",
       {"out"},
       {},
       300},
      {"HeightfieldDeclaringTwelveThousandSquared",
       {{"h.png", lying_png(12000, 12000)},
        {"t.json",
         "{\"fspm_scene\": 2, \"terrain\": {\"heightfield\": \"{dir}/h.png\", "
         "\"metres_per_pixel\": 1}}"}},
       {},
       "--memory-limit 256M mesh {dir}/t.json -o {dir}/t.glb",
       1,
       "h.png: an image of 12000 x 12000 pixels and 1 channel needs about [0-9.]+ MiB, above the "
       "memory limit of 256 MiB \\(--memory-limit\\)",
       {"t.glb"},
       {},
       300},
      {"ImageBeyondTheLargestSize",
       {{"wide.png", lying_png(1000000, 1000)}},
       {},
       "crown {dir}/wide.png -o {dir}/out",
       1,
       "wide.png: the image header declares 1000000 x 1000 pixels, more than the largest image "
       "read \\(268435456 pixels, 16384 x 16384\\)",
       {"out"},
       {},
       300},
      {"CrownPhotoFromAFifo",
       {},
       {},
       "crown {dir}/photo.png -o {dir}/out",
       1,
       "photo.png: not a regular file \\(a pipe, device or folder\\), expected an image file",
       {"out"},
       "mkfifo {dir}/photo.png; timeout 60 "},
      // Nothing writes to the pipes: a reader that opened one would wait (here 60 s) for a writer.
      {"GlbFromAFifo",
       {},
       {},
       "encode {dir}/f.glb -o {dir}/c.clusters",
       1,
       "f.glb: not a regular file \\(a pipe or device\\), expected a glTF file on disk",
       {"c.clusters"},
       "mkfifo {dir}/f.glb; timeout 60 "},
      {"GltfFromAFifoForTreeConvert",
       {},
       {},
       "tree convert {dir}/f.gltf {dir}/t.tree",
       1,
       "f.gltf: not a regular file \\(a pipe or device\\), expected a glTF file on disk",
       {"t.tree"},
       "mkfifo {dir}/f.gltf; timeout 60 "},
  };
}

// The one memory budget on the paths that grow with their input, each under a small limit with
// the peak resident memory checked: the request is refused before its memory is taken.
std::vector<Case> budget_cases() {
  std::string cloud;
  for (int i = 0; i < 100000; ++i) {
    cloud += std::to_string(i % 317) + " " + std::to_string(i % 101) + " " +
             std::to_string(i % 53) + "\n";
  }
  const std::string landscape = kExamples + "/landscape";
  const std::string terrain = "{\"fspm_scene\": 2, \"terrain\": {\"heightfield\": \"" + landscape +
                              "/hills.png\", \"metres_per_pixel\": 6, \"height_scale_m\": 150}";
  return {
      // ABOP Fig. 1.24a derived a billion steps deep: the walk down takes a frame per step.
      {"CompressedDerivationBillionSteps",
       {},
       {},
       "--memory-limit 64M lsystem derive " + kExamples +
           "/lsystems/abop_1_24a.l --compressed --steps 1000000000",
       1,
       "abop_1_24a.l: the substructure derivation \\([0-9]+ substructures, [0-9]+ steps deep\\) "
       "needs about [0-9.]+ MiB, above the memory limit of 64 MiB \\(--memory-limit\\)",
       {},
       {},
       400},
      // Branching at every step, and parameters that never repeat, so no substructure is shared.
      {"DeepBranchingOverTheMemoryLimit",
       {{"b.l", "derivation length: 40\nAxiom: A\nA --> F[+A][-A]\n"}},
       {},
       "--memory-limit 16M lsystem interpret {dir}/b.l -o {dir}/t.tree",
       1,
       "b.l: the L-system string at derivation step [0-9]+ needs about [0-9.]+ MiB, above the "
       "memory limit of 16 MiB \\(--memory-limit\\)",
       {"t.tree"},
       {},
       300},
      {"UnsharedSubstructuresOverTheMemoryLimit",
       {{"p.l", "derivation length: 60\nAxiom: A(1)\nA(x) --> F(x)[+A(x+1)][-A(x*2)]\n"}},
       {},
       "--memory-limit 16M lsystem derive {dir}/p.l --compressed",
       1,
       "p.l: the substructure derivation \\([0-9]+ substructures, [0-9]+ steps deep\\) needs "
       "about [0-9.]+ MiB, above the memory limit of 16 MiB \\(--memory-limit\\)",
       {},
       {},
       300},
      {"PointCloudRenderOverTheMemoryLimit",
       {{"cloud.xyz", cloud}},
       {},
       "--memory-limit 64M render {dir}/cloud.xyz -o {dir}/cloud.png",
       1,
       "drawing 100000 points as spheres \\(the mesh and the renderer's copies and buffers\\) "
       "needs about "
       "[0-9.]+ MiB, above the memory limit of 64 MiB \\(--memory-limit\\)",
       {"cloud.png"},
       {},
       400},
      {"EncodeOverTheMemoryLimit",
       {{"cloud.xyz", cloud}},
       {},
       "--memory-limit 8M encode {dir}/cloud.xyz -o {dir}/c.clusters",
       1,
       "cloud.xyz: encoding 100000 points \\(recentred copy and voxel thinning\\) needs about "
       "[0-9.]+ MiB, above the memory limit of 8 MiB \\(--memory-limit\\)",
       {"c.clusters"},
       {},
       300},
      {"TerrainMeshOverTheMemoryLimit",
       {{"t.json", terrain + "}"}},
       {},
       "--memory-limit 512K mesh {dir}/t.json -o {dir}/t.glb",
       1,
       "the terrain mesh of 129 x 129 vertices \\(terrain.stride 1\\) needs about [0-9.]+ KiB, "
       "above the memory limit of 512 KiB \\(--memory-limit\\)",
       {"t.glb"},
       {},
       400},
      // The crown's working memory (photograph, masks, working images, cubemaps, preview) is
      // estimated from the photograph's header; these headers declare what their data lacks.
      {"CrownOfAPhoneSizedPhotoOverTheMemoryLimit",
       {{"big.png", lying_png(4000, 3000)}},
       {},
       "--memory-limit 256M crown {dir}/big.png -o {dir}/out",
       1,
       "big.png: the crown of a 4000 x 3000 photograph needs about [0-9.]+ MiB, above the memory "
       "limit of 256 MiB \\(--memory-limit\\)",
       {"out"},
       {},
       300},
      {"CrownPreviewOverTheMemoryLimit",
       {{"big.png", lying_png(2000, 1500)}},
       {},
       "--memory-limit 256M crown {dir}/big.png -o {dir}/out --preview {dir}/p.png",
       1,
       "big.png: the crown of a 2000 x 1500 photograph and its preview needs about [0-9.]+ MiB, "
       "above the memory limit of 256 MiB \\(--memory-limit\\)",
       {"out", "p.png"},
       {},
       300},
      {"CrownCubemapsOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 512M crown " + kExamples +
           "/crown/tree_front.png -o {dir}/out --cubemap-size 2048",
       1,
       "tree_front.png: the crown of a 256 x 256 photograph with cubemaps of 2048 texels needs "
       "about [0-9.]+ MiB, above the memory limit of 512 MiB \\(--memory-limit\\)",
       {"out"},
       {},
       300},
      // Copying a branch onto a node of its own branch doubles the model at each edit (Pirk
      // 5.4.1 edits are applied in turn): thirty copies would need 2^30 times the branch.
      {"StagesBranchCopiesOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 64M stages " + kExamples + "/trees/open_a12.treeb --at 1 -o {dir}/s.tree" +
           repeat(" --copy-branch 614:631", 30),
       1,
       "branch edit \\(copy\\) 614:631: a model of [0-9]+ nodes needs about [0-9.]+ MiB, above "
       "the memory limit of 64 MiB \\(--memory-limit\\)",
       {"s.tree"},
       {},
       200},
      // The points a simulated scan keeps are bounded before it starts (at most 1 / pi of the
      // candidates it draws): 10^8 per m2 would take minutes and gigabytes.
      {"ScanDensityOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 256M scan " + kExamples +
           "/trees/open_a12.treeb -o {dir}/s.xyz --density 100000000",
       1,
       "a simulated scan of about [0-9]+ points \\(density 100000000 per m2\\) needs about "
       "[0-9.]+ GiB, above the memory limit of 256 MiB \\(--memory-limit\\)",
       {"s.xyz"},
       {},
       100},
      // Two runs of about 70 MiB each (the turtle's tree of 2^19 internodes) under a limit of
      // 100 MiB: with --jobs 2 they share the limit, so the second waits for the first instead
      // of doubling the peak (each alone peaks near 150 MB with the program; both at once near
      // 250 MB), and both succeed as with --jobs 1.
      {"RunJobsShareTheMemoryLimit",
       {{"t.l", "derivation length: 19\nAxiom: A\nA --> F[+A][-A]\n"},
        {"e.toml",
         "[experiment]\nname = \"m\"\nreplicates = 2\n[model]\nkind = \"lsystem\"\nfile = "
         "\"t.l\"\n[outputs]\nmetrics = [\"nodes\"]\n"}},
       {},
       "--memory-limit 100M run {dir}/e.toml --out {dir}/out --jobs 2",
       0,
       "progress: 2/2 runs \\(100%\\), 0 failed",
       {},
       {},
       200},
      // 50 bytes of "+.+" notation nest 210 010 branches on branches; MTG indents each level by
      // a tab, so the code written back would take about 41 GiB.
      {"MtgCodeOverItsLimitNamesTheOutput",
       {{"deep.mtg", "MTG:\nENTITY-CODE\n/I2+.+nnnnnnnPn210011\n"}},
       {},
       "tree convert {dir}/deep.mtg {dir}/o.mtg",
       1,
       "o.mtg: the MTG code would take about [0-9.]+ GiB, expected at most 256 MiB: its "
       "branching nests 210010 levels deep",
       {"o.mtg"},
       {},
       300},
      // The viewer keeps the mesh of every stage: 200 stages of a 12-year tree took 430 MB under
      // a limit of 64 MiB before each stage's mesh was reserved before it was made (the viewer's
      // libraries and the developmental model take about 170 MB before the first mesh).
      {"ViewStagesOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 64M view " + kExamples +
           "/trees/open_a12.treeb --stages 200 --frames 1 --screenshot {dir}/v.png",
       1,
       "keeping the meshes of steps 1 to [0-9]+ of 200 for the viewer needs about [0-9.]+ MiB, "
       "above the memory limit of 64 MiB \\(--memory-limit\\)",
       {"v.png"},
       {},
       300},
      // The steps fit, but not beside their copies uploaded for drawing (about as large again).
      {"ViewStagesAndTheirUploadOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 90M view " + kExamples +
           "/trees/open_b12.treeb --stages 200 --frames 1 --screenshot {dir}/v.png",
       1,
       "drawing 200 steps \\(their meshes and the copies uploaded for drawing\\) needs about "
       "[0-9.]+ MiB, above the memory limit of 90 MiB \\(--memory-limit\\)",
       {"v.png"}},
      // A GLB chunk whose length lies (2 GiB declared, a kilobyte present) had the decoder
      // allocate the declared length: 2 GB of resident memory before it noticed.
      {"GlbChunkLengthLies",
       {},
       {"mesh " + kExamples + "/trees/growth_units.mtg -o {dir}/v.glb"},
       "--memory-limit 64M encode {dir}/bad.glb -o {dir}/o.clusters",
       1,
       "bad.glb: GLB chunk 0 declares 2147483647 bytes, but only [0-9]+ follow its header",
       {"o.clusters"},
       "{ head -c 12 {dir}/v.glb; printf '\\377\\377\\377\\177'; tail -c +17 {dir}/v.glb; } > "
       "{dir}/bad.glb; ",
       100},
      // Stages are made one at a time into one tree: a long sequence holds no more than one.
      {"ThousandStagesWithinASmallLimit",
       {},
       {},
       "--memory-limit 8M stages " + kExamples + "/trees/open_a12.treeb --steps 1000 -o {dir}/s",
       0,
       "",
       {},
       {},
       100},
      // Four million Latin-hypercube samples within the limit: the plan holds them in one block
      // (a vector per sample took 534 MB where the estimate said 240 MiB).
      {"SamplingWithinTheMemoryLimit",
       {{"e.toml",
         "[experiment]\nname = \"s\"\n[model]\nkind = \"synthetic\"\n[sampling]\n"
         "samples = 3956852\n[sampling.parameters]\n\"x.u\" = { uniform = [0, 1] }\n"}},
       {},
       "--memory-limit 256M run {dir}/e.toml --emit-slurm --slurm-file {dir}/s.slurm --out {dir}/r",
       0,
       "",
       {},
       {},
       300},
      {"PopulationDistanceTooSmallNamesItsKey",
       {{"p.json", terrain +
                       ", \"population\": {\"min_distance_m\": 0.0001, \"classes\": "
                       "[{\"value\": 255, \"density\": 1, \"plants\": [{\"file\": \"" +
                       kTree + "\", \"probability\": 1}]}]}}"}},
       {},
       "mesh {dir}/p.json -o {dir}/p.glb",
       1,
       "population.min_distance_m 0.000100 m over a terrain of 768.0+ x 768.0+ m: the minimum "
       "distance is too small for the area",
       {"p.glb"}},
  };
}

// Cases of a second hostile audit: counts in plant files far past any memory, job threads the
// system refuses, file names that hold control characters.
std::vector<Case> audit_cases() {
  // A 32 x 32 PNG of one green (RGB 40, 120, 40).
  static constexpr char kUniformPng[] =
      "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52"
      "\x00\x00\x00\x20\x00\x00\x00\x20\x08\x02\x00\x00\x00\xfc\x18\xed"
      "\xa3\x00\x00\x00\x29\x49\x44\x41\x54\x78\xda\xed\xcd\x31\x0d\x00"
      "\x00\x08\x03\xb0\xc9\x99\x44\xe4\xa3\x82\x83\xa4\x49\xff\xa6\xd3"
      "\x53\x11\x08\x04\x02\x81\x40\x20\x10\x08\x04\x5f\x82\x05\x28\x5d"
      "\x20\x2e\x55\xbc\xe6\x36\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42"
      "\x60\x82";
  // Plants P of internodes E with a length and a diameter; the code starts on line 13.
  const std::string kMtgWithFeatures =
      "CODE:\tFORM-A\nCLASSES:\nSYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION\n$"
      "\t0\tFREE\tFREE\tIMPLICIT\nP\t1\tFREE\tFREE\tIMPLICIT\nE\t2\tFREE\tFREE\tIMPLICIT\n"
      "FEATURES:\nNAME\tTYPE\nLength\tREAL\nDiameter\tREAL\nMTG:\nENTITY-CODE\t\tLength\t"
      "Diameter\n";
  const std::string plant = "[plant]\ncycles = 5\n[[age]]\nindex = 1\nduration = 5\nnext_age = 0\n";
  const std::string limit = "above the memory limit of 256 MiB \\(--memory-limit\\)";
  return {
      // 10^9 metamers in one growth unit: 56 GB of records before anything else saw them.
      {"GreenlabUnitCountOverTheMemoryLimit",
       {{"p.toml", plant + "units = [ { count = 1000000000 } ]\n"}},
       {},
       "--memory-limit 256M greenlab simulate {dir}/p.toml -o {dir}/p.ctree",
       1,
       "the compressed plant of 1000000000 records and 0 axillary references needs about "
       "[0-9.]+ GiB, " +
           limit,
       {"p.ctree"},
       {},
       100},
      // One metamer bearing 10^9 buds of its own age: as many axillary references.
      {"GreenlabBudCountOverTheMemoryLimit",
       {{"p.toml", plant + "branching_delay = 1\nunits = [ { count = 1, axillary = [ { age = 1, "
                           "count = 1000000000 } ] } ]\n"}},
       {},
       "--memory-limit 256M greenlab simulate {dir}/p.toml -o {dir}/p.ctree",
       1,
       "the compressed plant of 1 records and 1000000000 axillary references needs about "
       "[0-9.]+ GiB, " +
           limit,
       {"p.ctree"},
       {},
       100},
      // The beta law is tabulated over the whole expansion: 10^8 cycles took 800 MB, exit 0.
      {"GreenlabExpansionLongerThanAnySimulation",
       {{"p.toml", plant + "units = [ { count = 1 } ]\nleaf_expansion = 100000000\n"}},
       {},
       "--memory-limit 256M greenlab simulate {dir}/p.toml -o {dir}/p.ctree",
       1,
       "p.toml:8:[0-9]+: key 'age\\[0\\].leaf_expansion' is 100000000 cycles, expected at most "
       "10000",
       {"p.ctree"},
       {},
       100},
      // Under an address-space limit the system starts about a hundred of 4096 job threads;
      // the runs go on with those (a refused thread used to leave the started ones waiting for
      // ever, deaf to SIGTERM). The timeout turns a hang into a failure.
      {"JobThreadsRefusedBySystem",
       {{"e.toml", kSynthetic}},
       {},
       "run {dir}/e.toml --out {dir}/out --jobs 4096 --replicates 3000",
       0,
       "--jobs: the system started only [0-9]+ of 3000 job threads \\(.*\\): running with "
       "[0-9]+; "
       "give a lower --jobs(.|\\n)*progress: 3000/3000 runs \\(100%\\), 0 failed",
       {},
       "ulimit -s 8192; ulimit -v 1500000; timeout -s KILL 120 "},
      // "nan" reads as a number: a length of nan made the whole plant's geometry nan (tree info
      // printed it, exit 0; tree convert blamed the output file).
      {"MtgLengthNan",
       {{"h.mtg", kMtgWithFeatures + "/P1/E1\t\t10\t1\n^<E2\t\tnan\t1\n"}},
       {},
       "tree info {dir}/h.mtg",
       1,
       "h.mtg:14: feature Length: 'nan', expected a finite number >= 0"},
      {"MtgDiameterNegative",
       {{"h.mtg", kMtgWithFeatures + "/P1/E1\t\t10\t-1\n"}},
       {},
       "tree convert {dir}/h.mtg {dir}/t.tree",
       1,
       "h.mtg:13: feature Diameter: '-1', expected a finite number >= 0",
       {"t.tree"}},
      // Nothing to mesh: "wrote z.glb (0 vertices, 0 triangles)", exit 0, where a tree file of
      // the same drawing was refused.
      {"MeshOfZeroLengthInternodes",
       {{"z.l", "Axiom: F(0)\n"}},
       {},
       "mesh {dir}/z.l -o {dir}/z.glb",
       1,
       "z.glb: no triangle to write: the input draws no surface",
       {"z.glb"}},
      // An infinite length (1e308 squared) left out by the mesher: an empty OBJ and its MTL.
      {"InterpretInfiniteLengthToObj",
       {{"i.l", "derivation length: 1\nAxiom: F(1)\nF(x) --> F(x*1e308*1e308)\n"}},
       {},
       "lsystem interpret {dir}/i.l -o {dir}/i.obj",
       1,
       "cannot mesh node [0-9]+: its (end|length|direction) is nan or infinite",
       {"i.obj", "i.mtl"}},
      // A nan width: "mesh would have 18446744065119617028 vertices ...; raise the edge length".
      {"InterpretNanWidthToGlb",
       {{"w.l", "Axiom: !(sqrt(-1))F(1)\n"}},
       {},
       "lsystem interpret {dir}/w.l -o {dir}/w.glb",
       1,
       "cannot mesh node [0-9]+: its radius is nan or infinite",
       {"w.glb"}},
      // A scan that sees nothing wrote an empty file ("0 points", exit 0) that every point
      // reader refuses.
      {"ScanOfZeroLengthInternodes",
       {{"z.l", "Axiom: F(0)\n"}},
       {"lsystem interpret {dir}/z.l -o {dir}/z.tree"},
       "scan {dir}/z.tree -o {dir}/z.xyz",
       1,
       "z.xyz: no point to write: the point set is empty",
       {"z.xyz"}},
      // A photograph of one colour: the message named no file.
      {"CrownOfAUniformPhotoNamesIt",
       {{"g.png", std::string(kUniformPng, sizeof kUniformPng - 1)}},
       {},
       "crown {dir}/g.png -o {dir}/out",
       1,
       "g.png: no crown found: nothing differs from the sky and ground beside it",
       {"out"}},
      // A view file's numbers go through strtod, which reads 1e309 as inf and "nan" as nan: the
      // error came from the tree writer, naming the output, or an empty mesh was written.
      {"ViewFileAngleOverflowing",
       {{"t.v", "angle increment: 1e309\n"}},
       {},
       "lsystem interpret " + kExamples + "/lsystems/abop_1_24a.l --view {dir}/t.v -o {dir}/t.tree",
       1,
       "t.v:1:[0-9]+: expected a finite number, got '1e309'",
       {"t.tree"}},
      {"ViewFileLineWidthNan",
       {{"t.v", "initial line width: nan\n"}},
       {},
       "lsystem interpret " + kExamples + "/lsystems/abop_1_24a.l --view {dir}/t.v -o {dir}/t.glb",
       1,
       "t.v:1:[0-9]+: expected a line width",
       {"t.glb"}},
      // An experiment named "-rf" wrote "-rf.slurm" and printed "sbatch '-rf.slurm'", which
      // sbatch (or rm) reads as options however it is quoted.
      {"SlurmScriptOfANameWithALeadingDash",
       {{"e.toml", "[experiment]\nname = \"-rf\"\n[model]\nkind = \"synthetic\"\n"}},
       {},
       "run e.toml --out o --emit-slurm",
       0,
       "",
       {"-rf.slurm", "-rf-results"},
       "cd {dir} && "},
      // A render size within 16384 x 16384 but above the budget: 2.8 GB, exit 0.
      {"RenderSizeOverTheMemoryLimit",
       {},
       {},
       "--memory-limit 256M render " + kExamples + "/trees/open_a12.treeb -o {dir}/r.png --size " +
           "8192x8192",
       1,
       "a render of 8192x8192 needs about 2.5 GiB, " + limit,
       {"r.png"}},
      // Its pipe-model power overflowed: the tree writer refused an infinite radius, naming the
      // output.
      {"GrowthTipRadiusOverflowNamesItsKey",
       {{"g.toml", "years = 3\ntip_radius_m = 1e300\n"}},
       {},
       "grow {dir}/g.toml -o {dir}/t.tree",
       1,
       "g.toml:2:[0-9]+: tip_radius_m: expected a positive length up to 1 m",
       {"t.tree"}},
      // A newline in a file name stays inside the one line of the message.
      {"NewlineInAFileName",
       {},
       {},
       "tree info '{dir}/no\nsuch.nwk'",
       1,
       "^fspm: error: [^\\n]*/no\\\\nsuch\\.nwk: cannot open for reading: No such file or "
       "directory\\n$"},
      // An escape sequence in a file name is printed as text, never sent to the terminal.
      {"EscapeSequenceInAFileName",
       {{"e\x1b[2Jsc.nwk", "((a,b)c"}},
       {},
       "tree info '{dir}/e\x1b[2Jsc.nwk'",
       1,
       "^fspm: error: [^\\n\\x1b]*/e\\\\x1b\\[2Jsc\\.nwk:1:[0-9]+: [^\\n\\x1b]*\\n$"},
  };
}

// Test names in ctest and failure reports show the case's name, not its bytes.
void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

class Robustness : public ::testing::TestWithParam<Case> {};

TEST_P(Robustness, FailsCleanly) {
  const Case& c = GetParam();
  const fs::path dir = scratch_dir("robust_" + c.name);
  for (const auto& [name, text] : c.files) {
    if (text.starts_with("@")) {
      fs::copy_file(expand(text.substr(1), dir), dir / name);
    } else {
      write_text(dir / name, expand(text, dir));
    }
  }
  for (const std::string& setup : c.setup) {
    const CommandResult r = run_fspm(expand(setup, dir));
    ASSERT_EQ(r.exit_code, 0) << setup << "\n" << r.err;
  }
  std::map<std::string, std::string> before;
  for (const std::string& name : c.untouched) {
    before[name] = fs::exists(dir / name) ? read_text(dir / name) : "<absent>";
  }
  CommandResult r;
  if (c.max_rss_mib > 0) {
    const MeasuredRun m =
        run_measured(expand(c.shell_prefix, dir) + "exec " + FSPM_EXE + " " + expand(c.args, dir),
                     dir.string() + ".err");
    fs::remove(dir.string() + ".err");
    r.exit_code = m.exit_code;
    r.err = m.err;
    EXPECT_LT(m.peak_rss_kib, c.max_rss_mib * 1024) << "peak resident memory in KiB";
  } else {
    r = run_fspm(expand(c.args, dir), expand(c.shell_prefix, dir));
  }
  if (r.err.find("fspm was built without the viewer") != std::string::npos) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex(expand(c.message, dir)))) << r.err;
  // One line, short even when the input is huge.
  EXPECT_LT(r.err.size(), 600u) << r.err.substr(0, 600);
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  for (const std::string& name : c.untouched) {
    const std::string after = fs::exists(dir / name) ? read_text(dir / name) : "<absent>";
    EXPECT_EQ(after, before[name]) << name << " appeared or changed";
  }
  // No temporary file of an atomic write is left behind.
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  }
  fs::remove_all(dir);
}

// The options of the whole command line (-q, -v, --json) mean the same before the command and
// after it: both spellings succeed, print the same stdout, and their stdout and stderr show the
// option's effect.
struct Spelling {
  std::string name;
  std::string before;  // the option before the command
  std::string after;   // the option after the command
  std::string out;     // regex searched in stdout
  std::string err;     // regex searched in stderr
};

void PrintTo(const Spelling& s, std::ostream* out) { *out << s.name; }

std::vector<Spelling> spellings() {
  const std::string light = "light --scene " + kScene + " --points " + kPoints;
  const std::string ctree = "greenlab simulate " + kPlant + " -o {dir}/p.ctree";
  return {
      {"JsonTreeInfo", "--json tree info " + kTree, "tree info " + kTree + " --json",
       "^\\{\\n  \"attributes\": \\[", "^$"},
      // Between a command group and its command.
      {"JsonInsideGroup", "tree --json info " + kTree, "tree info " + kTree + " --json",
       "\"nodes\": 9,", "^$"},
      {"JsonLight", "--json " + light, light + " --json", "\"points\": 4,", "^$"},
      // Handed over to fspm-full with the whole command line.
      {"JsonReport", "--json report {dir}/out --no-figures", "report {dir}/out --no-figures --json",
       "\"runs\": 1", "^$"},
      // Without -q both commands write a line on stderr ("wrote ...").
      {"QuietConvert", "-q tree convert " + kTree + " {dir}/t.tree",
       "tree convert " + kTree + " {dir}/t.tree -q", "^$", "^$"},
      {"QuietSimulate", "-q " + ctree, ctree + " -q", "^$", "^$"},
      {"VerboseLight", "-v " + light, light + " -v", "^x,y,z,light,dx,dy,dz\\n",
       "\\[debug\\] light: 4 points in"},
  };
}

class GlobalOption : public ::testing::TestWithParam<Spelling> {};

TEST_P(GlobalOption, SameBeforeAndAfterTheCommand) {
  const Spelling& s = GetParam();
  const fs::path dir = scratch_dir("global_" + s.name);
  write_text(dir / "e.toml", kSynthetic);
  ASSERT_EQ(run_fspm(expand("run {dir}/e.toml --out {dir}/out -q", dir)).exit_code, 0);
  const CommandResult before = run_fspm(expand(s.before, dir));
  const CommandResult after = run_fspm(expand(s.after, dir));
  for (const CommandResult* r : {&before, &after}) {
    EXPECT_EQ(r->exit_code, 0) << r->err;
    EXPECT_TRUE(std::regex_search(r->out, std::regex(s.out))) << r->out.substr(0, 600);
    EXPECT_TRUE(std::regex_search(r->err, std::regex(s.err))) << r->err;
  }
  // Timings differ from run to run; the rest of the output must not.
  const std::regex seconds("\"seconds\": [0-9.e+-]+");
  EXPECT_EQ(std::regex_replace(before.out, seconds, ""),
            std::regex_replace(after.out, seconds, ""));
  fs::remove_all(dir);
}

// SIGTERM and SIGINT end a command as the signal does (a shell sees 143 and 130), and what it
// had not finished goes with it: no temporary of an atomic write, no output folder it created.
struct Stopped {
  bool by_signal = false;
  int signal = 0;
};

Stopped stop_after(const std::vector<std::string>& args, int signal, double seconds) {
  std::vector<std::string> words = {FSPM_EXE};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0), ::dup2(null, 1), ::dup2(null, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::usleep(static_cast<useconds_t>(seconds * 1e6));
  ::kill(child, signal);
  int status = 0;
  ::waitpid(child, &status, 0);
  return {WIFSIGNALED(status), WIFSIGNALED(status) ? WTERMSIG(status) : 0};
}

std::vector<std::string> temporaries_in(const fs::path& dir) {
  std::vector<std::string> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().filename().string().find(".tmp") != std::string::npos) out.push_back(e.path());
  }
  return out;
}

TEST(Signals, StagesStoppedLeaveNoTemporary) {
  for (const int signal : {SIGTERM, SIGINT}) {
    const fs::path dir = scratch_dir("signal_stages");
    const Stopped s = stop_after({"stages", expand(kExamples, {}) + "/trees/open_a12.treeb",
                                  "--steps", "100000", "-o", (dir / "out").string()},
                                 signal, 1.0);
    EXPECT_TRUE(s.by_signal && s.signal == signal) << "ended by signal " << s.signal;
    EXPECT_TRUE(fs::exists(dir / "out"));  // some stages were written, each whole
    EXPECT_EQ(temporaries_in(dir), std::vector<std::string>{});
    fs::remove_all(dir);
  }
}

TEST(Signals, CrownStoppedLeavesNoOutputFolder) {
  const fs::path dir = scratch_dir("signal_crown");
  const Stopped s = stop_after({"crown", expand(kExamples, {}) + "/crown/tree_front.png", "-o",
                                (dir / "out").string(), "--cubemap-size", "1024"},
                               SIGTERM, 1.0);
  EXPECT_TRUE(s.by_signal && s.signal == SIGTERM) << "ended by signal " << s.signal;
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_EQ(temporaries_in(dir), std::vector<std::string>{});
  fs::remove_all(dir);
}

// Counts that saturate at 2^64 - 1 (ABOP Fig. 1.24a derived 40 steps has about 10^28 modules)
// are written "more than 10^19" in text, logs and JSON, never as the saturated number itself.
TEST(SaturatedCounts, AreMoreThanTenToTheNineteen) {
  const std::string derive =
      "lsystem derive " + expand(kExamples, {}) + "/lsystems/abop_1_24a.l --compressed --steps 40";
  for (const std::string& args : {derive, derive + " --json", "-v " + derive}) {
    const CommandResult r = run_fspm(args);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    const std::string all = r.out + r.err;
    EXPECT_EQ(all.find("18446744073709551615"), std::string::npos) << args << "\n" << all;
    EXPECT_NE(all.find("more than 10^19"), std::string::npos) << args << "\n" << all;
  }
  const CommandResult json = run_fspm(derive + " --json");
  EXPECT_NE(json.out.find("\"modules\": \"more than 10^19\""), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"compression\": \"more than "), std::string::npos) << json.out;
  // Below the saturation the counts stay numbers. F --> F[+F]F[-F]F makes 5^n F and adds six
  // other modules per F rewritten: 5^n + 6 (5^n - 1) / 4 modules, 745058059692382811 at n = 25.
  const CommandResult exact = run_fspm("lsystem derive " + expand(kExamples, {}) +
                                       "/lsystems/abop_1_24a.l --compressed --steps 25 --json");
  EXPECT_NE(exact.out.find("\"modules\": 745058059692382811"), std::string::npos) << exact.out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }
std::string spelling_name(const ::testing::TestParamInfo<Spelling>& info) {
  return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(Output, Robustness, ::testing::ValuesIn(output_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Nesting, Robustness, ::testing::ValuesIn(nesting_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(WrongInput, Robustness, ::testing::ValuesIn(wrong_input_cases()),
                         case_name);
INSTANTIATE_TEST_SUITE_P(Messages, Robustness, ::testing::ValuesIn(message_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Memory, Robustness, ::testing::ValuesIn(memory_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Options, Robustness, ::testing::ValuesIn(option_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(NamedInput, Robustness, ::testing::ValuesIn(named_input_cases()),
                         case_name);
INSTANTIATE_TEST_SUITE_P(Images, Robustness, ::testing::ValuesIn(image_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Budget, Robustness, ::testing::ValuesIn(budget_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Audit, Robustness, ::testing::ValuesIn(audit_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Options, GlobalOption, ::testing::ValuesIn(spellings()), spelling_name);

}  // namespace
}  // namespace fspm::testing
