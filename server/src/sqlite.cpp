#include "sqlite.hpp"

#include <sqlite3.h>

namespace grainlab::server {
namespace {

[[noreturn]] void fail(sqlite3* db, const std::string& what) {
  throw SqliteError(what + ": " + (db ? sqlite3_errmsg(db) : "out of memory"));
}

}  // namespace

Database::Database(const std::string& path, bool create) {
  const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0) |
                    SQLITE_OPEN_NOMUTEX;
  if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw SqliteError("cannot open " + path + ": " + message);
  }
  // The writer's checkpoints briefly lock the file; readers wait rather than fail.
  sqlite3_busy_timeout(db_, 5000);
  sqlite3_extended_result_codes(db_, 1);
}

Database::~Database() { sqlite3_close(db_); }

void Database::exec(const char* sql) {
  char* message = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    std::string text = message ? message : sqlite3_errmsg(db_);
    sqlite3_free(message);
    throw SqliteError(std::string("exec failed: ") + text);
  }
}

std::int64_t Database::userVersion() {
  Statement s(*this, "PRAGMA user_version");
  auto use = s.use();
  return use.step() ? use.int64At(0) : 0;
}

std::int64_t Database::changes() const { return sqlite3_changes64(db_); }

std::int64_t Database::lastInsertId() const { return sqlite3_last_insert_rowid(db_); }

Statement::Statement(Database& db, const char* sql) : sql_(sql) {
  if (sqlite3_prepare_v3(db.handle(), sql, -1, SQLITE_PREPARE_PERSISTENT, &stmt_, nullptr) !=
      SQLITE_OK)
    fail(db.handle(), std::string("cannot prepare ") + sql);
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

StatementUse Statement::use() { return StatementUse(*this); }

StatementUse::~StatementUse() {
  sqlite3_reset(s_->stmt_);
  sqlite3_clear_bindings(s_->stmt_);
}

int StatementUse::index(const char* name) const {
  const int i = sqlite3_bind_parameter_index(s_->stmt_, name);
  if (i == 0) throw SqliteError(std::string("no parameter ") + name + " in " + s_->sql_);
  return i;
}

StatementUse& StatementUse::bind(const char* name, std::int64_t value) {
  if (sqlite3_bind_int64(s_->stmt_, index(name), value) != SQLITE_OK)
    fail(sqlite3_db_handle(s_->stmt_), name);
  return *this;
}

StatementUse& StatementUse::bind(const char* name, double value) {
  if (sqlite3_bind_double(s_->stmt_, index(name), value) != SQLITE_OK)
    fail(sqlite3_db_handle(s_->stmt_), name);
  return *this;
}

StatementUse& StatementUse::bindText(const char* name, std::string_view value) {
  if (sqlite3_bind_text64(s_->stmt_, index(name), value.data(), value.size(), SQLITE_TRANSIENT,
                          SQLITE_UTF8) != SQLITE_OK)
    fail(sqlite3_db_handle(s_->stmt_), name);
  return *this;
}

StatementUse& StatementUse::bindBlob(const char* name, std::string_view bytes) {
  if (sqlite3_bind_blob64(s_->stmt_, index(name), bytes.data(), bytes.size(),
                          SQLITE_TRANSIENT) != SQLITE_OK)
    fail(sqlite3_db_handle(s_->stmt_), name);
  return *this;
}

StatementUse& StatementUse::bindNull(const char* name) {
  if (sqlite3_bind_null(s_->stmt_, index(name)) != SQLITE_OK)
    fail(sqlite3_db_handle(s_->stmt_), name);
  return *this;
}

bool StatementUse::step() {
  const int rc = sqlite3_step(s_->stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(sqlite3_db_handle(s_->stmt_), std::string("step failed in ") + s_->sql_);
}

void StatementUse::run() {
  if (step()) throw SqliteError(std::string("unexpected row from ") + s_->sql_);
}

bool StatementUse::isNull(int column) const {
  return sqlite3_column_type(s_->stmt_, column) == SQLITE_NULL;
}

std::int64_t StatementUse::int64At(int column) const {
  return sqlite3_column_int64(s_->stmt_, column);
}

double StatementUse::doubleAt(int column) const {
  return sqlite3_column_double(s_->stmt_, column);
}

std::string StatementUse::textAt(int column) const {
  const auto* text = sqlite3_column_text(s_->stmt_, column);
  const int size = sqlite3_column_bytes(s_->stmt_, column);
  return text ? std::string(reinterpret_cast<const char*>(text), static_cast<size_t>(size))
              : std::string();
}

std::string StatementUse::blobAt(int column) const {
  const void* blob = sqlite3_column_blob(s_->stmt_, column);
  const int size = sqlite3_column_bytes(s_->stmt_, column);
  return blob ? std::string(static_cast<const char*>(blob), static_cast<size_t>(size))
              : std::string();
}

}  // namespace grainlab::server
