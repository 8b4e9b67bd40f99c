// CSV: quoting, numbers, and no "nan" or "inf" cells; numbers as text.
#include <cmath>

#include <gtest/gtest.h>

#include "grainlab/studies/paper/csv_table.hpp"
#include "grainlab/studies/paper/number_text.hpp"

namespace grainlab::report {
namespace {

TEST(CsvTable, QuotesTextAndLeavesMissingNumbersEmpty) {
  CsvTable t({"assembly", "a_c", "note"});
  t.addRow({"circular", 0.25, "a, \"b\""});
  t.addRow({"random", NAN, INFINITY});
  EXPECT_EQ(t.text(), "assembly,a_c,note\ncircular,0.25,\"a, \"\"b\"\"\"\nrandom,,\n");
  EXPECT_EQ(t.rows(), 2u);
  EXPECT_THROW(t.addRow({"too", "few"}), std::invalid_argument);
}

TEST(NumberText, FormatsWithoutMinusZeroOrNan) {
  EXPECT_EQ(fixed(-0.001, 2), "0.00");
  EXPECT_EQ(fixed(NAN, 2), "-");
  EXPECT_EQ(general(1.0 / 3.0, 3), "0.333");
  EXPECT_EQ(general(NAN), "");
}

}  // namespace
}  // namespace grainlab::report
