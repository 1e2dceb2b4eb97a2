// `dyop pairs`: the CSV contract, line by line, with good and bad lines mixed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "dyop/batch.hpp"
#include "program/pair_csv.hpp"
#include "program/pairs_command.hpp"

namespace dyop::cli {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

PairMethod method(const std::string& name) {
  for (const PairMethod& b : pairs_methods()) {
    if (b.name == name) return b;
  }
  ADD_FAILURE() << "no method " << name;
  return {};
}

TEST(PairCsv, ParsesTwelveNumbersWithSpacesSignsAndWindowsLineEnds) {
  const PairLine l = parse_pair_line(" 0, +1.5 ,-2e3,3,4,5,6,7,8,9,10,11\r");
  ASSERT_EQ(l.kind, PairLine::Kind::Data);
  EXPECT_EQ(l.values[1], 1.5);
  EXPECT_EQ(l.values[2], -2000);
  EXPECT_EQ(l.values[11], 11);
}

TEST(PairCsv, BlankAndCommentLinesAreSkipped) {
  EXPECT_EQ(parse_pair_line("").kind, PairLine::Kind::Skip);
  EXPECT_EQ(parse_pair_line("   \t").kind, PairLine::Kind::Skip);
  EXPECT_EQ(parse_pair_line("# ax,ay,...").kind, PairLine::Kind::Skip);
}

TEST(PairCsv, EveryMalformedLineNamesWhatIsWrong) {
  const struct {
    const char* line;
    const char* says;
  } cases[] = {
      {"1,2,3", "expected 12 comma-separated fields, got 3"},
      {"1,2,3,4,5,6,7,8,9,10,11,12,13", "got 13"},
      {"1,2,3,4,5,x,7,8,9,10,11,12", "field 6 (cy) is not a number: 'x'"},
      {"1,2,3,4,5,6,7,8,9,10,11,", "field 12 (ry) is not a number: ''"},
      {"1,2,3,4,5,6,nan,8,9,10,11,12", "field 7 (px) is not finite"},
      {"1,2,3,4,5,6,7,8,inf,10,11,12", "field 9 (qx) is not finite"},
      {"1,2,3,4,5,6,7,8,9,1e999,11,12", "field 10 (qy) is out of range of double"},
  };
  for (const auto& c : cases) {
    const PairLine l = parse_pair_line(c.line);
    EXPECT_EQ(l.kind, PairLine::Kind::Error) << c.line;
    EXPECT_NE(l.message.find(c.says), std::string::npos) << c.line << " -> " << l.message;
  }
}

TEST(PairCsv, DegenerateAndFloatOverflowingTrianglesAreErrorsNamingTheTriangle) {
  const std::array<double, pair_fields> collinear{0, 0, 1, 1, 2, 2, 0, 0, 1, 0, 0, 1};
  EXPECT_NE(make_pair_triangles<double>(collinear).message.find("triangle ABC"), std::string::npos);
  const std::array<double, pair_fields> repeated{0, 0, 1, 0, 0, 1, 5, 5, 5, 5, 6, 6};
  EXPECT_NE(make_pair_triangles<double>(repeated).message.find("triangle PQR"), std::string::npos);
  const std::array<double, pair_fields> huge{0, 0, 1e300, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  EXPECT_NE(make_pair_triangles<double>(huge).message.find("too large"), std::string::npos);
  const std::array<double, pair_fields> beyond_float{0, 0, 1e39, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  EXPECT_NE(make_pair_triangles<float>(beyond_float).message.find("field 3 (bx)"),
            std::string::npos);
}

TEST(PairsCommand, EveryInputLineIsAccountedForInOrderWithItsLineNumber) {
  const std::string input =
      "# header comment\n"
      "0,0, 4,0, 2,4,  2,0.5, 1,-2, 3,-2\n"  // line 2: penetrating by 0.5
      "\n"
      "0,0,1,0,0,1\n"                        // line 4: too few fields
      "0,0, 1,0, 0,1,  2,0, 3,0, 2,1\n"      // line 5: apart by 1
      "0,0, 1,1, 2,2,  2,0, 3,0, 2,1\n"      // line 6: degenerate
      "0,0, 1,0, 0,1,  2,0, 3,0, 2,oops\n";  // line 7: not a number
  std::istringstream in(input);
  std::ostringstream out;
  const PairsSummary s = run_pairs({{method("sat")}, false, false}, in, out);
  EXPECT_EQ(s.rows, 5);
  EXPECT_EQ(s.ok, 2);
  EXPECT_EQ(s.errors, 3);
  const auto lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "row,status,overlap,depth,separation,nx,ny,message");
  EXPECT_EQ(lines[1], "2,ok,1,0.5,-0.5,0,-1,");
  EXPECT_EQ(lines[2].rfind("4,error,,,,,,\"expected 12", 0), 0u) << lines[2];
  EXPECT_EQ(lines[3], "5,ok,0,0,1,1,0,");
  EXPECT_EQ(lines[4].rfind("6,error,,,,,,\"triangle ABC", 0), 0u) << lines[4];
  EXPECT_EQ(lines[5].rfind("7,error,,,,,,\"field 12 (ry)", 0), 0u) << lines[5];
}

// A user of distances wants the direction that separates a pair, as for penetrating pairs: the
// exact methods give the unit vector from A to B for pairs apart and touching too.
TEST(PairsCommand, ExactMethodsGiveApartAndTouchingPairsTheUnitDirectionFromAToB) {
  const std::string input =
      "0,0, 1,0, 0,1,  2,0, 3,0, 2,1\n"    // line 1: B apart by 1 along +x
      "0,0, 2,0, 1,1,  0,0, 1,-1, 2,0\n";  // line 2: B touching A's lower edge from below
  for (const char* name : {"dyop", "sat", "batch"}) {
    std::istringstream in(input);
    std::ostringstream out;
    run_pairs({{method(name)}, false, false}, in, out);
    const auto lines = lines_of(out.str());
    ASSERT_EQ(lines.size(), 3u) << name;
    EXPECT_EQ(lines[1], "1,ok,0,0,1,1,0,") << name;
    EXPECT_EQ(lines[2], "2,ok,1,0,0,0,-1,") << name;
  }
}

TEST(PairsCommand, NumbersHaveSeventeenSignificantDigits) {
  std::istringstream in("0,0, 3,0, 0,3,  0.9,0.9, 3,3, 1,4\n");
  std::ostringstream out;
  run_pairs({{method("dyop")}, false, false}, in, out);
  const auto lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 2u);
  // Depth along the hypotenuse: (3 - 0.9 - 0.9) / sqrt(2), printed "0.84852813742385..." in full.
  const std::string depth = lines[1].substr(7, lines[1].find(',', 7) - 7);
  EXPECT_EQ(depth.size(), 19u) << depth;  // "0." and 17 digits
  EXPECT_NEAR(std::stod(depth), 1.2 / std::sqrt(2.0), 1e-15);
}

TEST(PairsCommand, FloatPrecisionRunsTheFloatInstantiation) {
  std::istringstream in("0,0, 3,0, 0,3,  0.9,0.9, 3,3, 1,4\n");
  std::ostringstream out;
  run_pairs({{method("sat")}, true, false}, in, out);
  const auto lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 2u);
  const std::string depth = lines[1].substr(7, lines[1].find(',', 7) - 7);
  EXPECT_EQ(static_cast<double>(static_cast<float>(std::stod(depth))), std::stod(depth))
      << "a float result, widened: " << depth;
  EXPECT_NEAR(std::stod(depth), 1.2 / std::sqrt(2.0), 1e-6);
}

TEST(PairsCommand, SeveralMethodsAddAMethodColumnAndOneLinePerMethod) {
  std::istringstream in("0,0, 1,0, 0,1,  2,0, 3,0, 2,1\n");
  std::ostringstream out;
  const PairsSummary s = run_pairs({pairs_methods(), false, false}, in, out);
  const auto lines = lines_of(out.str());
  EXPECT_EQ(lines[0].rfind("method,row,status", 0), 0u);
  EXPECT_EQ(lines.size(), pairs_methods().size() + 1);
  EXPECT_EQ(s.rows, static_cast<int>(pairs_methods().size()));
}

TEST(PairsCommand, MethodThatCannotHandleAPairReportsAnErrorLineWithItsReason) {
  std::istringstream in("0,0, 0,2, -2,1,  -0.2,1, 2,0.5, 2,1.5\n");  // pivot edge x = 0
  std::ostringstream out;
  const PairsSummary s = run_pairs({{method("dyop-paper")}, false, false}, in, out);
  EXPECT_EQ(s.errors, 1);
  EXPECT_NE(out.str().find("1,error"), std::string::npos) << out.str();
}

// Seeded pairs of unit-sized triangles, overlapping or apart, as CSV lines to 17 digits, with a
// bad line and a degenerate pair among them.
std::string random_pairs_csv(int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::string csv = "0,0,1,0,0,1\n0,0, 1,1, 2,2,  2,0, 3,0, 2,1\n";
  for (int k = 0; k < count; ++k) {
    const double dx = 1.5 * coordinate(rng), dy = 1.5 * coordinate(rng);
    for (int v = 0; v < 6; ++v) {
      char field[64];
      std::snprintf(field, sizeof field, "%.17g,%.17g%s", coordinate(rng) + (v >= 3 ? dx : 0),
                    coordinate(rng) + (v >= 3 ? dy : 0), v == 5 ? "\n" : ",");
      csv += field;
    }
  }
  return csv;
}

std::string run_to_text(const PairsOptions& options, const std::string& csv) {
  std::istringstream in(csv);
  std::ostringstream out;
  run_pairs(options, in, out);
  return out.str();
}

// The batch kernel answers the whole input in one call: every kernel this CPU runs writes the
// same lines, and they are `sat`'s answers (same status, separations within rounding).
TEST(PairsCommand, BatchGivesEveryKernelsSameLinesAndSatsAnswers) {
  const std::string csv = random_pairs_csv(500);
  for (const bool use_float : {false, true}) {
    const std::string portable =
        run_to_text({{method("batch")}, use_float, false, BatchKernel::Portable}, csv);
    for (const BatchKernel k : {BatchKernel::Auto, BatchKernel::Avx2, BatchKernel::Avx512}) {
      if (!batch_kernel_available(k)) continue;
      EXPECT_EQ(run_to_text({{method("batch")}, use_float, false, k}, csv), portable)
          << name(k) << (use_float ? ", float" : ", double");
    }
    const auto batch = lines_of(portable);
    const auto sat = lines_of(run_to_text({{method("sat")}, use_float, false}, csv));
    ASSERT_EQ(batch.size(), sat.size());
    const double rounding = use_float ? 1e-5 : 1e-12;  // the pairs are about 1 m across
    int compared = 0;
    for (std::size_t i = 1; i < batch.size(); ++i) {
      std::vector<std::string> x, y;
      for (auto* cells : {&x, &y}) {
        std::istringstream line(cells == &x ? batch[i] : sat[i]);
        for (std::string cell; std::getline(line, cell, ',');) cells->push_back(cell);
      }
      ASSERT_GE(x.size(), 3u);
      EXPECT_EQ(x[0] + x[1] + x[2], y[0] + y[1] + y[2]) << batch[i] << " | " << sat[i];
      if (x[1] != "ok" || y.size() < 5) continue;
      EXPECT_NEAR(std::stod(x[4]), std::stod(y[4]), rounding) << batch[i] << " | " << sat[i];
      ++compared;
    }
    EXPECT_GT(compared, 400);
  }
}

}  // namespace
}  // namespace dyop::cli
