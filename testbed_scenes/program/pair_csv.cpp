#include "program/pair_csv.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace dyop::cli {
namespace {

constexpr const char* kFieldNames[pair_fields] = {"ax", "ay", "bx", "by", "cx", "cy",
                                                  "px", "py", "qx", "qy", "rx", "ry"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

std::string field_label(int i) {
  return "field " + std::to_string(i + 1) + " (" + kFieldNames[i] + ")";
}

std::string number(double x) {
  if (x == 0) x = 0;  // no "-0" in the output
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// Messages go into a CSV field: quote it, doubling inner quotes.
std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    if (c != '\n' && c != '\r') out += c;
  }
  return out + '"';
}

}  // namespace

PairLine parse_pair_line(std::string_view line) {
  PairLine out;
  line = trim(line);
  if (line.empty() || line.front() == '#') return out;
  out.kind = PairLine::Kind::Error;
  int count = 1;
  for (char c : line) count += c == ',';
  if (count != pair_fields) {
    out.message = "expected " + std::to_string(pair_fields) + " comma-separated fields, got " +
                  std::to_string(count);
    return out;
  }
  for (int i = 0; i < pair_fields; ++i) {
    const std::size_t comma = line.find(',');
    const std::string_view field = trim(line.substr(0, comma));
    line = comma == std::string_view::npos ? std::string_view() : line.substr(comma + 1);
    double value = 0;
    const char* end = field.data() + field.size();
    // from_chars rejects a leading '+'; accept it as people write it.
    const char* begin = !field.empty() && field.front() == '+' ? field.data() + 1 : field.data();
    const auto parsed = std::from_chars(begin, end, value);
    if (parsed.ec == std::errc::result_out_of_range && parsed.ptr == end) {
      out.message = field_label(i) + " is out of range of double: '" + std::string(field) + "'";
      return out;
    }
    if (field.empty() || parsed.ec != std::errc() || parsed.ptr != end) {
      out.message = field_label(i) + " is not a number: '" + std::string(field) + "'";
      return out;
    }
    if (!std::isfinite(value)) {
      out.message = field_label(i) + " is not finite: '" + std::string(field) + "'";
      return out;
    }
    out.values[i] = value;
  }
  out.kind = PairLine::Kind::Data;
  return out;
}

template <class T>
PairTriangles<T> make_pair_triangles(const std::array<double, pair_fields>& v) {
  PairTriangles<T> out;
  for (int i = 0; i < pair_fields; ++i) {
    if (std::abs(v[i]) > static_cast<double>(std::numeric_limits<T>::max())) {
      out.message = field_label(i) + " = " + number(v[i]) + " is out of range of the precision";
      return out;
    }
  }
  auto at = [&](int k) { return Vec2<T>(static_cast<T>(v[k]), static_cast<T>(v[k + 1])); };
  out.a = Triangle<T>::make(at(0), at(2), at(4));
  out.b = Triangle<T>::make(at(6), at(8), at(10));
  if (!out.a.ok()) {
    out.message = std::string("triangle ABC (fields 1-6): ") + describe(out.a.error);
  } else if (!out.b.ok()) {
    out.message = std::string("triangle PQR (fields 7-12): ") + describe(out.b.error);
  }
  return out;
}

const char* pair_csv_header() { return "row,status,overlap,depth,separation,nx,ny,message"; }

std::string format_result_line(int row, const Result<double>& r) {
  if (r.status == Status::Invalid) {
    return format_error_line(row, r.reason != InvalidReason::None
                                      ? describe(r.reason)
                                      : "no answer: the method gave a non-finite value");
  }
  const bool overlap = r.status != Status::Separated;
  // The method's normal whatever the status: a user of distances wants the direction that
  // separates a pair apart or touching as much as the one that separates a penetrating pair.
  return std::to_string(row) + ",ok," + (overlap ? "1," : "0,") + number(r.depth) + "," +
         number(r.separation) + "," + number(r.normal.x()) + "," + number(r.normal.y()) + ",";
}

std::string format_error_line(int row, std::string_view message) {
  return std::to_string(row) + ",error,,,,,," + quoted(message);
}

template PairTriangles<float> make_pair_triangles(const std::array<double, pair_fields>&);
template PairTriangles<double> make_pair_triangles(const std::array<double, pair_fields>&);

}  // namespace dyop::cli
