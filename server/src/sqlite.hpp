#pragma once
// Thin RAII over the SQLite C API: a connection, prepared statements, and a scoped use of a
// statement that always resets it. An un-reset statement keeps its read transaction open and
// makes a later COMMIT fail, so nothing here hands out a raw step without a reset behind it.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace grainlab::server {

/// Any SQLite failure, with SQLite's own message.
class SqliteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One connection. Not thread-safe: one thread uses it at a time.
class Database {
 public:
  /// Opens (creating if asked) with a busy timeout, so a reader waits for the writer's
  /// checkpoint instead of failing.
  Database(const std::string& path, bool create);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  /// Runs one or more statements that return no rows.
  void exec(const char* sql);
  std::int64_t userVersion();
  std::int64_t changes() const;
  std::int64_t lastInsertId() const;
  sqlite3* handle() const { return db_; }

 private:
  sqlite3* db_ = nullptr;
};

class StatementUse;

/// A prepared statement; use it through use().
class Statement {
 public:
  Statement(Database& db, const char* sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  /// A scoped use: bind, step, read; resets and clears the bindings when it ends.
  StatementUse use();
  const char* sql() const { return sql_; }

 private:
  friend class StatementUse;
  sqlite3_stmt* stmt_ = nullptr;
  const char* sql_;
};

class StatementUse {
 public:
  explicit StatementUse(Statement& statement) : s_(&statement) {}
  ~StatementUse();
  StatementUse(const StatementUse&) = delete;
  StatementUse& operator=(const StatementUse&) = delete;

  /// Binds a named parameter such as ":id"; an unknown name is a programming error and throws.
  StatementUse& bind(const char* name, std::int64_t value);
  StatementUse& bind(const char* name, int value) { return bind(name, std::int64_t{value}); }
  StatementUse& bind(const char* name, double value);
  StatementUse& bindText(const char* name, std::string_view value);
  StatementUse& bindBlob(const char* name, std::string_view bytes);
  StatementUse& bindNull(const char* name);

  /// Steps once: true while there is a row to read.
  bool step();
  /// Steps a statement that returns no rows.
  void run();

  bool isNull(int column) const;
  std::int64_t int64At(int column) const;
  double doubleAt(int column) const;
  std::string textAt(int column) const;
  std::string blobAt(int column) const;

 private:
  int index(const char* name) const;
  Statement* s_;
};

}  // namespace grainlab::server
