// The one writer of records (testbed_scenes/report/records.hpp): a record described once reads the
// same in the aligned table, CSV, Markdown and JSON.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "report/records.hpp"

namespace dyop::report {
namespace {

Records two_rows() {
  Records r({{"name", "name", "", -6},
             {"time_ms", "time (ms)", "ms", 7},
             {"count", "count", "", 5, where::files},
             {"error_m", "error (m)", "err", 9}});
  r.add({Value::text("dyop"), Value::number(1.23456789, "%.2f"), Value::count(42),
         Value::metres(0.000125)});
  r.add({Value::text("a, \"b\""), Value::number(NAN, "%.2f"), Value::count(-1), Value::metres(0)});
  return r;
}

template <class Write>
std::string written(Write write) {
  std::ostringstream out;
  write(out);
  return out.str();
}

TEST(Records, CsvHasEveryFileColumnWithSixDigitsAndQuotesTextWithCommas) {
  const std::string csv = written([](std::ostream& o) { two_rows().write_csv(o); });
  EXPECT_EQ(csv,
            "name,time_ms,count,error_m\n"
            "dyop,1.23457,42,0.000125\n"
            "\"a, \"\"b\"\"\",n/a,-1,0\n");
}

TEST(Records, TableAlignsItsColumnsAndLeavesOutTheFilesOnlyOnes) {
  const std::string table = written([](std::ostream& o) { two_rows().write_table(o); });
  EXPECT_EQ(table,
            "name        ms       err\n"
            "dyop      1.23  1.25e-04\n"
            "a, \"b\"     n/a         0\n");
}

TEST(Records, MarkdownHasHeadingsARuleThatAlignsFiguresRightAndTheDisplayedFigures) {
  const std::string md = written([](std::ostream& o) { two_rows().write_markdown(o); });
  EXPECT_EQ(md,
            "| name | time (ms) | error (m) |\n"
            "|---|--:|--:|\n"
            "| dyop | 1.23 | 1.25e-04 |\n"
            "| a, \"b\" | n/a | 0 |\n");
}

TEST(Records, JsonKeepsFullPrecisionAndWritesNonFiniteFiguresAsNull) {
  const Json list = two_rows().json();
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["time_ms"].get<double>(), 1.23456789);
  EXPECT_EQ(list[0]["count"].get<int>(), 42);
  EXPECT_TRUE(list[1]["time_ms"].is_null());
  EXPECT_EQ(list[1]["name"], "a, \"b\"");
}

TEST(Records, ARowWithTheWrongNumberOfValuesIsRefused) {
  Records r({{"a", "a", "", 3}, {"b", "b", "", 3}});
  EXPECT_THROW(r.add({Value::count(1)}), std::logic_error);
  EXPECT_EQ(r.size(), 0u);
}

}  // namespace
}  // namespace dyop::report
