#pragma once
// A sum of doubles that does not depend on the order of its terms (docs/parallel.md, "Sums over many domains").
//
// Floating-point addition is not associative: the same terms added in another order give another last bit. A
// sum whose terms come from several domains (the kinetic energy over the nodes, a rigid body's resultant over its
// nodes, the work of the contact forces...) would then depend on the partition. ExactSum keeps the sum exactly, as
// a fixed-point number wide enough for every double (2^-1088 to 2^1056), in 32-bit digits held in 64-bit words:
// each term is split over the three digits its 53-bit mantissa covers, so adding is a few integer additions and
// the order of the terms changes nothing. value() rounds the exact sum to the nearest double once. Two sums of
// different domains combine by adding their digits (ExactSum::add, or a reduction of digits()).
#include <array>
#include <cstdint>

namespace crumple {

class ExactSum {
 public:
  static constexpr int kDigits = 67;  // 32-bit digits, the lowest of weight 2^-1088

  void add(double term);
  void add(const ExactSum& other);
  // The exact sum rounded to the nearest double; a non-finite term makes the sum the IEEE sum of those terms.
  double value() const;
  void clear();

  // The digits as integers, for a reduction over domains (slot-wise integer sums, then set_digits); the
  // non-finite part travels as its own double.
  std::array<std::int64_t, kDigits>& digits() { return digits_; }
  double& non_finite() { return non_finite_; }
  // Carries between digits: every digit but the top one in [0, 2^32), the sign in the top one. The sum of the
  // normalised digits of up to 2^31 domains cannot overflow.
  void normalise();

 private:

  std::array<std::int64_t, kDigits> digits_{};
  double non_finite_ = 0.0;  // the IEEE sum of the infinite and NaN terms
  std::int32_t since_normalised_ = 0;
};

}  // namespace crumple
