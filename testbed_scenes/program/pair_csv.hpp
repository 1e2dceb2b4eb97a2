#pragma once
/// \file
/// The pair CSV contract of `dyop pairs`.
///
/// Input: one pair a line, 12 numbers `ax,ay,bx,by,cx,cy,px,py,qx,qy,rx,ry` (triangle ABC then
/// PQR, world coordinates, any winding). Blank lines and lines starting with `#` are skipped.
/// Output: the header `row,status,overlap,depth,separation,nx,ny,message`, one line per data line
/// in input order; `row` is the 1-based input line number, `status` is `ok` or `error`, numbers
/// have 17 significant digits, `nx,ny` is the method's normal (`Result::normal`: unit, A to B,
/// for pairs apart and touching too; docs/testbed.md says what each method gives), and an error
/// line says in `message` what is wrong with that line.

#include <array>
#include <string>
#include <string_view>

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop::cli {

/// Number of fields of a data line.
constexpr int pair_fields = 12;

/// One input line, classified.
struct PairLine {
  enum class Kind { Skip, Data, Error };
  Kind kind = Kind::Skip;                    ///< Skip: blank or comment
  std::array<double, pair_fields> values{};  ///< Data only: the 12 coordinates, all finite
  std::string message;                       ///< Error only: what is wrong, naming the field
};

/// Parses one line (without its end-of-line; a trailing '\r' is ignored).
PairLine parse_pair_line(std::string_view line);

/// The two triangles of a data line in precision T, or a message naming what is wrong.
template <class T>
struct PairTriangles {
  std::string message;  ///< empty when both triangles are valid
  TriangleOrError<T> a;
  TriangleOrError<T> b;
};
template <class T>
PairTriangles<T> make_pair_triangles(const std::array<double, pair_fields>& v);

/// The output header line, without end-of-line.
const char* pair_csv_header();

/// One output line for a result (status `ok`, or `error` when the method returned Invalid).
std::string format_result_line(int row, const Result<double>& r);
/// One output line for an input error.
std::string format_error_line(int row, std::string_view message);

}  // namespace dyop::cli
