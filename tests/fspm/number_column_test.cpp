#include "fspm/number_column.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fspm/error.hpp"

namespace fspm {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() /
                 ("fspm_number_column_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p) << text;
  return p.string();
}

TEST(NumberColumn, OneNumberPerLineSkipsBlanksAndComments) {
  const auto p = write_temp("plain", "# header comment\n1.5\n\n  -2e3 \r\n7\n");
  EXPECT_EQ(read_number_column(p), (std::vector<double>{1.5, -2000.0, 7.0}));
}

TEST(NumberColumn, OneColumnCsvHeaderIsSkippedOnlyOnTheFirstLine) {
  EXPECT_EQ(read_number_column(write_temp("header", "height_m\n1.5\n2\n")),
            (std::vector<double>{1.5, 2.0}));
  EXPECT_EQ(read_number_column(write_temp("quoted", "# comment\n\"h\"\n3\n")),
            (std::vector<double>{3.0}));
  // Only the first line may be a name, and "nan" is a number (refused), not a name.
  EXPECT_THROW(read_number_column(write_temp("late", "1\nheight\n")), ParseError);
  EXPECT_THROW(read_number_column(write_temp("two", "a\nb\n1\n")), ParseError);
  EXPECT_THROW(read_number_column(write_temp("nanfirst", "nan\n1\n")), ParseError);
  EXPECT_THROW(read_number_column(write_temp("only", "height\n")), ParseError);
}

TEST(NumberColumn, CsvColumnByName) {
  const auto p = write_temp("csv", "a, \"b\" ,c\n1,2,3\n4, 5 ,6\n");
  EXPECT_EQ(read_number_column(p, "b"), (std::vector<double>{2.0, 5.0}));
  EXPECT_THROW(read_number_column(p, "d"), ValueError);
}

TEST(NumberColumn, ErrorsCarryFileLineAndColumn) {
  const auto bad = write_temp("bad", "1\n2\n  x1\n");
  try {
    read_number_column(bad);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), bad);
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 3);
  }
  EXPECT_THROW(read_number_column(write_temp("empty", "")), ParseError);
  EXPECT_THROW(read_number_column(write_temp("nan", "1\nnan\n")), ParseError);
  EXPECT_THROW(read_number_column(write_temp("csvrow", "a,b\n1,2\n3\n"), "b"), ParseError);
  EXPECT_THROW(read_number_column(write_temp("commas", "1,2\n")), ParseError);
  EXPECT_THROW(read_number_column("/nonexistent/x.txt"), IoError);
}

}  // namespace
}  // namespace fspm
