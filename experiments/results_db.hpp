#pragma once
// The result database of an experiment: DIR/results.sqlite, SQLite in WAL mode, one row per run
// (table `runs`), the experiment it belongs to in table `meta`, and a view `results` with one
// column per parameter and metric for notebooks. An existing database is never overwritten: it
// is resumed when it belongs to the same experiment, otherwise the open fails. A file that is not
// a result database, a corrupted one or one locked by another process is reported as IoError.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "experiments/run_record.hpp"

struct sqlite3;

namespace fspm::experiments {

inline constexpr const char* kDatabaseFile = "results.sqlite";
inline constexpr int kDatabaseFormat = 1;

// What a database records about its experiment.
struct ExperimentInfo {
  std::string name;
  std::string experiment_path;
  std::string experiment_text;  // a resumed or merged database must match it exactly
  std::size_t total_runs = 0;
  std::vector<std::string> swept;    // swept parameter names, CSV column order
  std::vector<std::string> metrics;  // recorded metrics, CSV column order
};

class ResultsDb {
 public:
  enum class Mode {
    kCreate,  // a new database; fails when DIR already holds one
    kResume,  // the existing database of the same experiment, or a new one
    kRead,    // an existing database, read only
  };

  // `info` is needed for kCreate and kResume, ignored for kRead.
  ResultsDb(const std::string& dir, Mode mode, const ExperimentInfo& info = {});
  ~ResultsDb();
  ResultsDb(const ResultsDb&) = delete;
  ResultsDb& operator=(const ResultsDb&) = delete;

  const ExperimentInfo& info() const { return info_; }
  const std::string& path() const { return path_; }

  // done[i] != 0 when run i has a row.
  std::vector<char> recorded_runs() const;
  std::size_t row_count() const;
  // All rows in run order.
  std::vector<RunRecord> read_all() const;
  // Inserts the records in one transaction. A run that already has a row is an IoError (never
  // two rows for one run).
  void insert(const std::vector<RunRecord>& records);

 private:
  void acquire_lock(const std::string& dir);
  void create_database_file(const ExperimentInfo& info);
  void create_schema(const ExperimentInfo& info);
  void load_info();
  void release_lock();
  std::string path_;
  sqlite3* db_ = nullptr;
  int lock_fd_ = -1;  // flock held by the writer of the directory
  ExperimentInfo info_;
  struct Statements;
  std::unique_ptr<Statements> statements_;
};

}  // namespace fspm::experiments
