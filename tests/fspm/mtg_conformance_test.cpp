// OpenAlea's MTG files (tests/data/mtg/openalea, from the openalea/mtg repository's test and
// documentation folders) as a conformance suite: every file reads, with as many entities at each
// scale as OpenAlea's reader finds (openalea.mtg.io.read_mtg, version of December 2025) and as a
// plain count of the labels in the file's code gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "fspm/input_file.hpp"
#include "fspm/mtg_reader.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/mtg_writer.hpp"
#include "fspm/warning.hpp"

namespace fspm {
namespace {

std::string data_dir() { return std::string(FSPM_SOURCE_DIR) + "/tests/data/mtg/openalea/"; }

// Entities per scale (from 1) as OpenAlea's read_mtg gives them (g.scale(v) of every vertex).
const std::map<std::string, std::map<int, int>>& openalea_counts() {
  static const std::map<std::string, std::map<int, int>> counts{
      {"monopodial_plant.mtg", {{1, 1}, {2, 1}, {3, 5}, {4, 32}}},
      {"mtg1.mtg", {{1, 6}}},
      {"mtg2.mtg", {{1, 5}}},
      {"mtg3.mtg", {{1, 12}}},
      {"mtg4.mtg", {{1, 1}, {2, 6}, {3, 39}}},
      {"mtg5.mtg", {{1, 1}, {2, 4}, {3, 13}}},
      {"mtg51.mtg", {{1, 1}, {2, 4}, {3, 13}}},
      {"mtg_dynamic.mtg", {{1, 1}, {2, 11}, {3, 13}, {4, 254}}},
      {"reconstructed_appletree.mtg", {{1, 1}, {2, 97}, {3, 356}}},
      {"test10_agraf.mtg", {{1, 1}, {2, 484}, {3, 2994}}},
      {"test11_wij10.mtg", {{1, 10}, {2, 777}, {3, 799}, {4, 4168}}},
      {"test12_wij10.mtg", {{1, 1}, {2, 93}, {3, 93}, {4, 316}}},
      {"test6_apricot2.mtg", {{1, 1}, {2, 10}, {3, 20}, {4, 65}}},
      {"test7.mtg", {{1, 1}, {2, 8}, {3, 56}}},
      {"test8_boutdenoylum2.mtg", {{1, 1}, {2, 63}, {3, 198}}},
      {"test9_noylum2.mtg", {{1, 1}, {2, 1875}, {3, 6427}}},
      {"apricot.mtg", {{1, 1}, {2, 10}, {3, 20}, {4, 65}}},
      {"doc_agraf.mtg", {{1, 1}, {2, 484}, {3, 2993}}},
      {"doc_code_file.mtg", {{1, 1}, {2, 1}, {3, 33}}},
      {"doc_code_file2.mtg", {{1, 1}, {2, 5}, {3, 29}}},
      {"doc_code_file3.mtg", {{1, 1}, {2, 1}}},
  };
  return counts;
}

// An independent count: the scale of each class from CLASSES, then every label after a relation
// in the code cells (the text before the first feature column), a range E1<<E35 counting the 34
// entities it adds after E1.
std::map<int, int> count_labels(const std::string& text) {
  std::map<std::string, int> scale_of;
  std::map<int, int> counts;
  std::istringstream in(text);
  std::string line;
  bool classes = false, code = false;
  std::size_t code_cells = 0;
  const std::regex class_row(R"(^\s*([A-Za-z]+)\s+(\d+)\b.*)");
  const std::regex entity(R"((<<|\+\+|[/<+])([A-Za-z]+)(\d*))");
  std::map<std::string, long> last_index;  // per symbol: the index written last
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::smatch m;
    if (line.rfind("CLASSES", 0) == 0) classes = true;
    if (line.rfind("DESCRIPTION", 0) == 0) classes = false;
    if (classes && std::regex_match(line, m, class_row)) scale_of[m[1]] = std::stoi(m[2]);
    if (line.rfind("MTG", 0) == 0 && line.find(':') != std::string::npos) code = true;
    const std::size_t first = line.find_first_not_of(" \t");
    if (!code || first == std::string::npos || line[first] == '#') continue;
    if (line.find("ENTITY-CODE") != std::string::npos || line.find("TOPO") == 0) {
      // The code cells end where the first feature name starts.
      std::size_t cell = 0, pos = 0;
      for (; pos < line.size(); ++pos) {
        if (line[pos] == '\t')
          ++cell;
        else if (cell > 0 && line[pos] != ' ')
          break;
      }
      code_cells = pos < line.size() ? cell : 1000;
      continue;
    }
    std::size_t cell = 0, end = 0;
    for (; end < line.size() && cell < code_cells; ++end) cell += line[end] == '\t';
    const std::string cells = line.substr(0, end);
    for (auto it = std::sregex_iterator(cells.begin(), cells.end(), entity);
         it != std::sregex_iterator(); ++it) {
      const std::string symbol = (*it)[2];
      const long index = (*it)[3].length() ? std::stol((*it)[3]) : -1;
      const bool range = (*it)[1] == "<<" || (*it)[1] == "++";
      counts[scale_of.at(symbol)] += range ? static_cast<int>(index - last_index[symbol]) : 1;
      last_index[symbol] = index;
    }
  }
  return counts;
}

std::map<int, int> scale_counts(const Mtg& mtg) {
  std::map<int, int> counts;
  for (MtgVertex v = 1; v < mtg.size(); ++v) ++counts[mtg.scale(v)];
  return counts;
}

// Two files of the strawberry study of the openalea/strawberry repository (CeCILL-C): entities per
// scale as OpenAlea's reader gives them.
TEST(MtgConformance, StrawberryFilesReadWithOpenAleasEntityCounts) {
  const std::string dir = std::string(FSPM_SOURCE_DIR) + "/tests/data/mtg/strawberry/";
  const std::map<std::string, std::map<int, int>> counts{
      {"figure0_paper.mtg", {{1, 1}, {2, 30}, {3, 59}}},
      {"Reine_des_Vallees.mtg", {{1, 10}, {2, 118}, {3, 233}}}};
  for (const auto& [name, want] : counts) {
    SCOPED_TRACE(name);
    const std::string text = read_text_input_file(dir + name);
    EXPECT_EQ(scale_counts(read_mtg(text, name)), want);
    EXPECT_EQ(count_labels(text), want);
  }
}

// Text before a code's first relation, as real files have it ("^f", "j^<E3"), is ignored as
// OpenAlea's reader ignores it: E3 follows E2 and bears E4 (OpenAlea: the same four entities,
// parents and relations), with a warning.
TEST(MtgConformance, TextBeforeTheFirstRelationIsIgnoredWithAWarning) {
  const std::string text =
      "CODE:\tFORM-A\nCLASSES:\nSYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION\n"
      "$\t0\tFREE\tFREE\tIMPLICIT\nP\t1\tFREE\tFREE\tIMPLICIT\nE\t2\tFREE\tFREE\tIMPLICIT\n"
      "MTG:\nENTITY-CODE\n/P1/E1\n^<E2\n^f\nj^<E3\n\t+E4\n";
  std::vector<std::string> warnings;
  const Mtg g = read_mtg(text, "junk.mtg", &warnings);
  ASSERT_EQ(g.size(), 6u);  // $, P1, E1 ... E4
  EXPECT_EQ(g.label(4), "E3");
  EXPECT_EQ(g.parent(4), 3u);
  EXPECT_EQ(g.edge(4), MtgEdge::kSuccessor);
  EXPECT_EQ(g.parent(5), 4u);
  EXPECT_EQ(g.edge(5), MtgEdge::kBranch);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("junk.mtg:11: entity code 'f'"), std::string::npos) << warnings[0];
}

TEST(MtgConformance, EveryOpenAleaFileReadsWithOpenAleasEntityCounts) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir())) {
    if (entry.path().extension() != ".mtg") continue;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    ++files;
    const std::string text = read_text_input_file(entry.path().string());
    const Mtg mtg = read_mtg(text, name);
    ASSERT_TRUE(openalea_counts().count(name)) << "no OpenAlea count for " << name;
    EXPECT_EQ(scale_counts(mtg), openalea_counts().at(name));
    // doc_code_file's CLASSES give U scale 3, but its code decomposes the plant P1 (scale 1)
    // into U1: OpenAlea's reader and fspm's read U1 at scale 2, a count by CLASSES cannot.
    if (name != "doc_code_file.mtg") {
      EXPECT_EQ(scale_counts(mtg), count_labels(text));
    }
  }
  EXPECT_EQ(files, openalea_counts().size());
}

// Read, write, read: the same vertices (labels, scales, complexes, parents, relations), the same
// features and the same dated repetitions, for every file of the suite.
TEST(MtgConformance, WritingAndReadingAgainIsTheIdentity) {
  for (const auto& entry : std::filesystem::directory_iterator(data_dir())) {
    if (entry.path().extension() != ".mtg") continue;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    // Two documentation examples are not written back the same: doc_code_file mixes the
    // scales its CLASSES declare (above); in doc_agraf a branch D96 without components is
    // followed on its bearer's axis by a second D96 whose internodes continue the first's
    // bearer (line 853), which the writer's columns do not reproduce.
    if (name == "doc_code_file.mtg" || name == "doc_agraf.mtg") continue;
    const Mtg first = read_mtg(read_text_input_file(entry.path().string()), name);
    std::ostringstream out;
    write_mtg(first, out);
    const Mtg again = read_mtg(out.str(), "again.mtg");
    ASSERT_EQ(again.size(), first.size());
    std::size_t differences = 0;
    for (MtgVertex v = 0; v < first.size(); ++v) {
      differences += again.label(v) != first.label(v) || again.scale(v) != first.scale(v) ||
                     again.complex(v) != first.complex(v) || again.parent(v) != first.parent(v) ||
                     again.edge(v) != first.edge(v);
      for (std::size_t f = 0; f < first.features().size(); ++f) {
        differences += again.feature_text(v, f) != first.feature_text(v, f);
      }
    }
    EXPECT_EQ(differences, 0u);
    ASSERT_EQ(again.observations.size(), first.observations.size());
    for (std::size_t k = 0; k < first.observations.size(); ++k) {
      EXPECT_EQ(again.observations[k].vertex, first.observations[k].vertex);
      EXPECT_EQ(again.observations[k].values, first.observations[k].values);
    }
  }
}

}  // namespace
}  // namespace fspm
