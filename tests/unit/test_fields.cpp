#include <gtest/gtest.h>

#include "crumple/deck/fields.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_fields {

using crumple::parse_fortran_real;
using crumple::parse_integer;

TEST(Fields, FortranRealsOfRealDecks) {
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1.5"), 1.5);
  EXPECT_DOUBLE_EQ(*parse_fortran_real(".3"), 0.3);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("-.3"), -0.3);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1E-6"), 1e-6);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1.D-3"), 1e-3);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1.d+3"), 1e3);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("205"), 205.0);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("   -8"), -8.0);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1.00000002E20"), 1.00000002e20);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("+2.5e1"), 25.0);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("7."), 7.0);
}

TEST(Fields, MalformedRealsAreRejected) {
  for (const char* bad : {"", "abc", "1.2.3", "1e", "e5", ".", "-", "1,5", "1E+", "1.5x", "--1", "1e400", "nan",
                          "inf", "0x10", "1 2"})
    EXPECT_FALSE(parse_fortran_real(bad).has_value()) << "'" << bad << "'";
}

TEST(Fields, Integers) {
  EXPECT_EQ(*parse_integer("        42"), 42);
  EXPECT_EQ(*parse_integer("-7"), -7);
  EXPECT_EQ(*parse_integer("+7"), 7);
  for (const char* bad : {"", "1.0", "1e3", "x", "12 3", "99999999999999999999"})
    EXPECT_FALSE(parse_integer(bad).has_value()) << "'" << bad << "'";
}

}  // namespace test_fields
