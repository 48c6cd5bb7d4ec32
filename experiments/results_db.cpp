#include "experiments/results_db.hpp"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "fspm/error.hpp"
#include "fspm/name_table.hpp"

namespace fspm::experiments {
namespace {

constexpr NameTable<RunStatus, 3> kRunStatusNames{
    "run status",
    {{RunStatus::kOk, "ok", "the run finished"},
     {RunStatus::kError, "error", "the model threw"},
     {RunStatus::kTimeout, "timeout", "the run outlasted its time limit"}}};

}  // namespace

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string quoted_identifier(const std::string& name) {
  std::string out = "\"";
  for (char c : name) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string json_path(const std::string& key) {
  std::string out = "$.\"";
  for (char c : key) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

json parameters_json(const ParameterSet& p) {
  json j = json::object();
  for (const auto& [name, value] : p) {
    std::visit([&](const auto& v) { j[name] = v; }, value);
  }
  return j;
}

ParameterSet parameters_from_json(const json& j) {
  ParameterSet p;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it->is_number_integer()) {
      p[it.key()] = it->get<std::int64_t>();
    } else if (it->is_number()) {
      p[it.key()] = it->get<double>();
    } else if (it->is_string()) {
      p[it.key()] = it->get<std::string>();
    }
  }
  return p;
}

}  // namespace

std::string_view run_status_name(RunStatus status) { return kRunStatusNames.name(status); }

RunStatus run_status_from_name(std::string_view name) { return kRunStatusNames.from_name(name); }

struct ResultsDb::Statements {
  sqlite3_stmt* insert = nullptr;
  ~Statements() { sqlite3_finalize(insert); }
};

namespace {

// Turns a failed SQLite call into an IoError that says what happened to which file.
[[noreturn]] void fail(sqlite3* db, int rc, const std::string& path, const std::string& doing) {
  std::string what = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
  const int primary = rc & 0xff;
  if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED) {
    what = "the database is locked by another process (" + what + ")";
  } else if (primary == SQLITE_CORRUPT || primary == SQLITE_NOTADB) {
    what =
        "the database is corrupted or not a result database (" + what + "); it was left untouched";
  }
  throw IoError(doing + ": " + what, path);
}

void exec(sqlite3* db, const std::string& sql, const std::string& path, const std::string& doing) {
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
  if (rc != SQLITE_OK) fail(db, rc, path, doing);
}

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql, const std::string& path) : db_(db), path_(path) {
    const int rc = sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr);
    if (rc != SQLITE_OK) fail(db, rc, path, "reading the database");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  // true while there is a row.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    fail(db_, rc, path_, "reading the database");
  }
  std::string text(int column) const {
    const auto* t = sqlite3_column_text(stmt_, column);
    return t == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(t));
  }
  std::int64_t integer(int column) const { return sqlite3_column_int64(stmt_, column); }
  double real(int column) const { return sqlite3_column_double(stmt_, column); }

 private:
  sqlite3* db_;
  std::string path_;
  sqlite3_stmt* stmt_ = nullptr;
};

}  // namespace

ResultsDb::ResultsDb(const std::string& dir, Mode mode, const ExperimentInfo& info)
    : path_((fs::path(dir) / kDatabaseFile).string()), statements_(std::make_unique<Statements>()) {
  std::error_code ec;
  const bool exists = fs::exists(path_, ec);
  if (mode == Mode::kRead && !exists) throw IoError("no result database here", path_);
  if (mode == Mode::kCreate && exists) {
    throw IoError(
        "the output directory already holds a result database; use --resume to continue "
        "it or choose another --out (it is never overwritten)",
        path_);
  }
  if (!exists) {
    fs::create_directories(dir, ec);
    if (ec) throw IoError("cannot create the output directory: " + ec.message(), dir);
  }
  if (mode != Mode::kRead) {
    acquire_lock(dir);
    if (!exists) create_database_file(info);
  }
  const int flags =
      mode == Mode::kRead ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  int rc = sqlite3_open_v2(path_.c_str(), &db_, flags | SQLITE_OPEN_FULLMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    const std::string message = db_ != nullptr ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    release_lock();
    throw IoError("cannot open the result database: " + message, path_);
  }
  try {
    sqlite3_busy_timeout(db_, 5000);
    bool fresh = false;
    if (mode == Mode::kResume) {
      // A run killed while creating the database leaves a file without tables: nothing to keep.
      Statement tables(db_, "SELECT count(*) FROM sqlite_master", path_);
      fresh = tables.step() && tables.integer(0) == 0;
    }
    if (!fresh) {
      // Catches files that are not databases and damaged pages before anything is written.
      Statement check(db_, "PRAGMA quick_check", path_);
      if (!check.step() || check.text(0) != "ok") {
        throw IoError("the database is corrupted (" + check.text(0) + "); it was left untouched",
                      path_);
      }
      load_info();
      if (mode == Mode::kResume && info_.experiment_text != info.experiment_text) {
        throw IoError("the database belongs to another experiment file (or an edited one: '" +
                          info_.experiment_path +
                          "'); resume with the same file or choose another --out",
                      path_);
      }
    }
    if (mode != Mode::kRead) {
      exec(db_, "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL", path_,
           "opening the database");
      if (fresh) create_schema(info);
      rc = sqlite3_prepare_v2(db_,
                              "INSERT INTO runs(run, point, replicate, seed, status, seconds, "
                              "parameters, metrics, error, files, finished_at) "
                              "VALUES (?,?,?,?,?,?,?,?,?,?,?)",
                              -1, &statements_->insert, nullptr);
      if (rc != SQLITE_OK) fail(db_, rc, path_, "opening the database");
    }
  } catch (...) {
    statements_.reset();
    sqlite3_close(db_);
    db_ = nullptr;
    release_lock();
    throw;
  }
}

ResultsDb::~ResultsDb() {
  statements_.reset();
  sqlite3_close(db_);
  release_lock();
}

void ResultsDb::acquire_lock(const std::string& dir) {
  // One writer per directory: a second `fspm run` on the same output fails instead of
  // interleaving its runs with the first one's.
  const std::string lock = (fs::path(dir) / ".results.lock").string();
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) throw IoError("cannot create the lock file", lock);
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw IoError("the result database is locked: another fspm run is writing it", path_);
  }
}

void ResultsDb::create_database_file(const ExperimentInfo& info) {
  // Built under another name and renamed into place: a run killed while creating the database
  // leaves no database or a complete one, never a file without tables.
  const std::string partial = path_ + ".partial";
  std::error_code ec;
  fs::remove(partial, ec);
  fs::remove(partial + "-journal", ec);
  try {
    const int rc =
        sqlite3_open_v2(partial.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
    if (rc != SQLITE_OK) fail(db_, rc, partial, "creating the database");
    create_schema(info);
    const int closed = sqlite3_close(db_);
    db_ = nullptr;
    if (closed != SQLITE_OK) throw IoError("cannot close the new database", partial);
    fs::rename(partial, path_, ec);
    if (ec) throw IoError("cannot move the new database into place: " + ec.message(), path_);
  } catch (...) {
    sqlite3_close(db_);
    db_ = nullptr;
    fs::remove(partial, ec);
    release_lock();
    throw;
  }
}

void ResultsDb::release_lock() {
  if (lock_fd_ >= 0) ::close(lock_fd_);
  lock_fd_ = -1;
}

void ResultsDb::create_schema(const ExperimentInfo& info) {
  info_ = info;
  std::string sql =
      "BEGIN IMMEDIATE;"
      "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
      "CREATE TABLE runs(run INTEGER PRIMARY KEY, point INTEGER NOT NULL, replicate INTEGER NOT "
      "NULL, seed INTEGER NOT NULL, status TEXT NOT NULL CHECK (status IN "
      "('ok','error','timeout')), seconds REAL NOT NULL, parameters TEXT NOT NULL, metrics TEXT "
      "NOT NULL, error TEXT, files TEXT NOT NULL, finished_at TEXT NOT NULL);";
  // One column per swept parameter and metric, named as in the experiment file.
  std::string view = "CREATE VIEW results AS SELECT run, seed, status, seconds";
  for (const std::string& name : info.swept) {
    view += ", json_extract(parameters, '" + json_path(name) + "') AS " + quoted_identifier(name);
  }
  for (const std::string& name : info.metrics) {
    view += ", json_extract(metrics, '" + json_path(name) + "') AS " + quoted_identifier(name);
  }
  sql += view + ", error FROM runs;";
  exec(db_, sql, path_, "creating the database");
  sqlite3_stmt* stmt = nullptr;
  sqlite3_prepare_v2(db_, "INSERT INTO meta(key, value) VALUES (?, ?)", -1, &stmt, nullptr);
  const std::pair<std::string, std::string> rows[] = {
      {"format", std::to_string(kDatabaseFormat)},     {"name", info.name},
      {"experiment_path", info.experiment_path},       {"experiment_text", info.experiment_text},
      {"total_runs", std::to_string(info.total_runs)}, {"swept", json(info.swept).dump()},
      {"metrics", json(info.metrics).dump()},
  };
  for (const auto& [key, value] : rows) {
    sqlite3_bind_text(stmt, 1, key.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(stmt, 2, value.c_str(), -1, SQLITE_TRANSIENT);
    const int rc = sqlite3_step(stmt);
    sqlite3_reset(stmt);
    if (rc != SQLITE_DONE) {
      sqlite3_finalize(stmt);
      fail(db_, rc, path_, "creating the database");
    }
  }
  sqlite3_finalize(stmt);
  exec(db_, "COMMIT", path_, "creating the database");
}

void ResultsDb::load_info() {
  std::map<std::string, std::string> meta;
  {
    Statement s(db_,
                "SELECT name FROM sqlite_master WHERE type='table' AND name IN ('meta','runs')",
                path_);
    int tables = 0;
    while (s.step()) ++tables;
    if (tables != 2) {
      throw IoError("not an fspm result database (no meta and runs tables); it was left untouched",
                    path_);
    }
  }
  Statement s(db_, "SELECT key, value FROM meta", path_);
  while (s.step()) meta[s.text(0)] = s.text(1);
  if (meta["format"] != std::to_string(kDatabaseFormat)) {
    throw IoError("unsupported result database format '" + meta["format"] + "'", path_);
  }
  try {
    info_.name = meta["name"];
    info_.experiment_path = meta["experiment_path"];
    info_.experiment_text = meta["experiment_text"];
    info_.total_runs = std::stoull(meta["total_runs"]);
    info_.swept = json::parse(meta["swept"]).get<std::vector<std::string>>();
    info_.metrics = json::parse(meta["metrics"]).get<std::vector<std::string>>();
  } catch (const std::exception& e) {
    throw IoError(std::string("the database's meta table is damaged: ") + e.what(), path_);
  }
}

std::vector<char> ResultsDb::recorded_runs() const {
  std::vector<char> done(info_.total_runs, 0);
  Statement s(db_, "SELECT run FROM runs", path_);
  while (s.step()) {
    const auto run = static_cast<std::size_t>(s.integer(0));
    if (run < done.size()) done[run] = 1;
  }
  return done;
}

std::size_t ResultsDb::row_count() const {
  Statement s(db_, "SELECT count(*) FROM runs", path_);
  s.step();
  return static_cast<std::size_t>(s.integer(0));
}

std::vector<RunRecord> ResultsDb::read_all() const {
  std::vector<RunRecord> out;
  Statement s(db_,
              "SELECT run, point, replicate, seed, status, seconds, parameters, metrics, error, "
              "files, finished_at FROM runs ORDER BY run",
              path_);
  while (s.step()) {
    RunRecord r;
    r.run = static_cast<std::size_t>(s.integer(0));
    r.point = static_cast<std::size_t>(s.integer(1));
    r.replicate = static_cast<std::size_t>(s.integer(2));
    r.seed = static_cast<std::uint64_t>(s.integer(3));
    r.seconds = s.real(5);
    try {
      r.status = run_status_from_name(s.text(4));
      const json parameters = json::parse(s.text(6));
      r.parameters = parameters_from_json(parameters);
      const json metrics = json::parse(s.text(7));
      for (auto it = metrics.begin(); it != metrics.end(); ++it) {
        r.metrics[it.key()] = it->is_number() ? it->get<double>() : std::nan("");
      }
      r.files = json::parse(s.text(9)).get<std::vector<std::string>>();
    } catch (const std::exception& e) {
      throw IoError("run " + std::to_string(r.run) + " has a damaged row: " + e.what(), path_);
    }
    r.error = s.text(8);
    r.finished_at = s.text(10);
    out.push_back(std::move(r));
  }
  return out;
}

void ResultsDb::insert(const std::vector<RunRecord>& records) {
  if (records.empty()) return;
  exec(db_, "BEGIN IMMEDIATE", path_, "writing results");
  sqlite3_stmt* st = statements_->insert;
  try {
    for (const RunRecord& r : records) {
      json metrics = json::object();
      for (const auto& [name, v] : r.metrics) {
        metrics[name] = std::isfinite(v) ? json(v) : json(nullptr);
      }
      const std::string params = parameters_json(r.parameters).dump();
      const std::string metrics_text = metrics.dump();
      const std::string files = json(r.files).dump();
      const std::string_view status = run_status_name(r.status);
      sqlite3_bind_int64(st, 1, static_cast<sqlite3_int64>(r.run));
      sqlite3_bind_int64(st, 2, static_cast<sqlite3_int64>(r.point));
      sqlite3_bind_int64(st, 3, static_cast<sqlite3_int64>(r.replicate));
      sqlite3_bind_int64(st, 4, static_cast<sqlite3_int64>(r.seed));
      sqlite3_bind_text(st, 5, status.data(), static_cast<int>(status.size()), SQLITE_STATIC);
      sqlite3_bind_double(st, 6, r.seconds);
      sqlite3_bind_text(st, 7, params.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(st, 8, metrics_text.c_str(), -1, SQLITE_TRANSIENT);
      if (r.error.empty()) {
        sqlite3_bind_null(st, 9);
      } else {
        sqlite3_bind_text(st, 9, r.error.c_str(), -1, SQLITE_TRANSIENT);
      }
      sqlite3_bind_text(st, 10, files.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(st, 11, r.finished_at.c_str(), -1, SQLITE_TRANSIENT);
      const int rc = sqlite3_step(st);
      sqlite3_reset(st);
      if (rc != SQLITE_DONE) {
        if ((rc & 0xff) == SQLITE_CONSTRAINT) {
          throw IoError("run " + std::to_string(r.run) + " already has a row", path_);
        }
        fail(db_, rc, path_, "writing results");
      }
    }
    exec(db_, "COMMIT", path_, "writing results");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

}  // namespace fspm::experiments
