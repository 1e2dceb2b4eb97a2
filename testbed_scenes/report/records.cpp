#include "report/records.hpp"

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "report/format.hpp"

namespace dyop::report {

Value Value::text(std::string s) {
  Value v;
  v.kind_ = Kind::Text;
  v.text_ = std::move(s);
  return v;
}

Value Value::count(std::int64_t n) {
  Value v;
  v.kind_ = Kind::Count;
  v.count_ = n;
  return v;
}

Value Value::number(double x, const char* display) {
  Value v;
  v.kind_ = Kind::Number;
  v.number_ = x;
  v.display_ = display;
  return v;
}

Value Value::metres(double x) {
  Value v = number(x, "%.2e");
  v.kind_ = Kind::Metres;
  return v;
}

std::string Value::displayed() const {
  switch (kind_) {
    case Kind::Text:
      return text_;
    case Kind::Count:
      return std::to_string(count_);
    case Kind::Number:
      return fmt(display_, number_);
    case Kind::Metres:
      return report::metres(number_);
  }
  return {};
}

std::string Value::csv() const {
  if (kind_ == Kind::Number || kind_ == Kind::Metres) return csv_number(number_);
  if (kind_ == Kind::Count || text_.find_first_of(",\"\n") == std::string::npos) {
    return displayed();  // text and counts read the same everywhere
  }
  // A comma, quote or line break: quoted, quotes doubled (RFC 4180).
  std::string quoted = "\"";
  for (char c : text_) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

Json Value::json() const {
  switch (kind_) {
    case Kind::Text:
      return Json(text_);
    case Kind::Count:
      return Json(count_);
    case Kind::Number:
    case Kind::Metres:
      return json_number(number_);
  }
  return Json(nullptr);
}

Records::Records(std::vector<Column> columns) : columns_(std::move(columns)) {}

void Records::add(std::vector<Value> row) {
  if (row.size() != columns_.size()) {
    throw std::logic_error("Records::add: " + std::to_string(row.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns");
  }
  rows_.push_back(std::move(row));
}

namespace {

// `s` padded to `width` characters (negative: on the right, as printf's "%-Ns").
std::string padded(const std::string& s, int width) {
  const std::size_t w = static_cast<std::size_t>(std::abs(width));
  const std::string pad = s.size() < w ? std::string(w - s.size(), ' ') : std::string();
  return width < 0 ? s + pad : pad + s;
}

}  // namespace

template <class Cell>
void Records::write_lines(std::ostream& out, const Layout& layout, Cell cell) const {
  auto line = [&](const std::vector<Value>* row) {
    out << layout.open;
    bool first = true;
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (!(columns_[c].where & layout.where)) continue;
      if (!first) out << layout.separator;
      first = false;
      out << cell(columns_[c], row != nullptr ? &(*row)[c] : nullptr);
    }
    out << layout.close << '\n';
  };
  line(nullptr);
  if (layout.rule) {
    out << '|';
    for (const Column& column : columns_) {  // text left-aligned, figures right-aligned
      if (column.where & layout.where) out << (column.width < 0 ? "---|" : "--:|");
    }
    out << '\n';
  }
  for (const auto& row : rows_) line(&row);
}

void Records::write_table(std::ostream& out) const {
  write_lines(out, {where::table, "", " ", "", false}, [](const Column& c, const Value* v) {
    const std::string& heading = c.abbreviation.empty() ? c.key : c.abbreviation;
    return padded(v != nullptr ? v->displayed() : heading, c.width);
  });
}

void Records::write_csv(std::ostream& out) const {
  write_lines(out, {where::csv, "", ",", "", false},
              [](const Column& c, const Value* v) { return v != nullptr ? v->csv() : c.key; });
}

void Records::write_markdown(std::ostream& out) const {
  write_lines(out, {where::markdown, "| ", " | ", " |", true}, [](const Column& c, const Value* v) {
    return v != nullptr ? v->displayed() : c.heading;
  });
}

Json Records::json() const {
  Json list = Json::array();
  for (const auto& row : rows_) {
    Json object = Json::object();
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (columns_[c].where & where::json) object[columns_[c].key] = row[c].json();
    }
    list.push_back(std::move(object));
  }
  return list;
}

}  // namespace dyop::report
