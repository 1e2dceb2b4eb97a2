#pragma once
/// \file
/// The one writer of records: a list of records is described once, column by column, and written
/// every way a report writes it — an aligned table on standard output, CSV, Markdown and JSON —
/// so that a table, its CSV and its JSON can never disagree on a column's name or a figure's
/// value, and a new experiment's report is its columns, not four writers.
///
/// Numbers read the same everywhere (`format.hpp`): a figure is written in the table and in
/// Markdown with its column's printf conversion, in CSV with six significant digits
/// (`csv_number`), and in JSON as a number; a non-finite figure is "n/a" in the table, Markdown
/// and CSV, and null in JSON (JSON has no NaN).

#include <cstdint>
#include <initializer_list>
#include <iosfwd>
#include <string>
#include <vector>

#include "report/json.hpp"

namespace dyop::report {

/// Where a column is written, as bits of `Column::where`.
namespace where {
inline constexpr unsigned table = 1u << 0;     ///< the aligned table on standard output
inline constexpr unsigned csv = 1u << 1;       ///< the CSV file
inline constexpr unsigned markdown = 1u << 2;  ///< the report's Markdown table
inline constexpr unsigned json = 1u << 3;      ///< the JSON list
inline constexpr unsigned files = csv | json;  ///< the machine-readable files only
inline constexpr unsigned everywhere = table | csv | markdown | json;
}  // namespace where

/// One value of a record: text, a whole number, or a figure with the printf conversion it is
/// displayed with in the table and in Markdown.
class Value {
 public:
  /// Text, written as it is (in CSV quoted when it has a comma, a quote or a line break).
  static Value text(std::string s);
  /// A whole number.
  static Value count(std::int64_t n);
  /// A figure; `display` is one printf conversion (e.g. "%.3f", "%.2e", "%.1f%%").
  static Value number(double v, const char* display);
  /// A length or an error in metres: `metres()` in the table and Markdown.
  static Value metres(double v);

  std::string displayed() const;  ///< as the table and Markdown show it
  std::string csv() const;        ///< as the CSV has it
  Json json() const;              ///< as the JSON has it

 private:
  enum class Kind : std::uint8_t { Text, Count, Number, Metres };
  Kind kind_ = Kind::Text;
  std::string text_;
  std::int64_t count_ = 0;
  double number_ = 0;
  const char* display_ = "";
};

/// One column: its names where it is written and its place in the aligned table.
struct Column {
  /// The CSV header and JSON key: snake_case, units in the name where it has one (`_ms`, `_m`).
  std::string key;
  /// The Markdown heading (plain words, units in brackets).
  std::string heading;
  /// The aligned table's heading (short, no spaces); empty: `key`.
  std::string abbreviation;
  /// The aligned table's width in characters; negative: left-aligned (text), as printf's `%-Ns`;
  /// Markdown aligns the column the same way.
  int width = 10;
  /// `where` bits: every output by default.
  unsigned where = where::everywhere;
};

/// A list of records described column by column. Rows are added in the order they are written.
class Records {
 public:
  explicit Records(std::vector<Column> columns);

  /// Adds a record: one value per column, in column order (throws std::logic_error otherwise:
  /// a report that does not describe its record is a programming error).
  void add(std::vector<Value> row);

  /// The aligned table: a header line, then one line per record.
  void write_table(std::ostream& out) const;
  /// The CSV: the header (`Column::key`s) and one line per record.
  void write_csv(std::ostream& out) const;
  /// The Markdown table (`Column::heading`s), no heading of its own.
  void write_markdown(std::ostream& out) const;
  /// A JSON list: one object per record, keys in column order.
  Json json() const;

  std::size_t size() const { return rows_.size(); }  ///< the number of records

 private:
  // How one output lays a line out: the columns it writes (a `where` bit), what opens, separates
  // and closes the cells, and whether a rule line follows the header (Markdown).
  struct Layout {
    unsigned where;
    const char* open;
    const char* separator;
    const char* close;
    bool rule;
  };
  // The header, the rule if any, then one line per record; `cell(column, value)` spells a cell
  // (value nullptr: the header's).
  template <class Cell>
  void write_lines(std::ostream& out, const Layout& layout, Cell cell) const;

  std::vector<Column> columns_;
  std::vector<std::vector<Value>> rows_;
};

}  // namespace dyop::report
