// A sum of doubles independent of the order of its terms (core/exact_sum.hpp).
#include "crumple/core/exact_sum.hpp"

#include <bit>
#include <cmath>

namespace crumple {
namespace {

constexpr int kLowestExponent = -1088;                    // weight of digit 0's lowest bit: 2^-1088
constexpr std::int64_t kDigitBase = std::int64_t{1} << 32;
constexpr std::int32_t kAddsBeforeCarry = 1 << 30;       // each add moves a digit by less than 2^32
__extension__ typedef unsigned __int128 Wide;             // GCC's 128-bit integer: a mantissa placed in 3 digits

}  // namespace

void ExactSum::add(double term) {
  if (term == 0.0) return;
  if (!std::isfinite(term)) {
    non_finite_ += term;
    return;
  }
  // term = +-M 2^(e - 1075) for a normal double (M with its hidden bit), +-M 2^-1074 for a subnormal one.
  const auto bits = std::bit_cast<std::uint64_t>(term);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased != 0) mantissa |= std::uint64_t{1} << 52;
  const int position = (biased == 0 ? 1 : biased) - 1075 - kLowestExponent;  // of the mantissa's lowest bit
  const int digit = position / 32, shift = position % 32;
  const Wide placed = static_cast<Wide>(mantissa) << shift;
  const auto low = static_cast<std::int64_t>(static_cast<std::uint64_t>(placed) & 0xffffffffu);
  const auto middle = static_cast<std::int64_t>(static_cast<std::uint64_t>(placed >> 32) & 0xffffffffu);
  const auto high = static_cast<std::int64_t>(static_cast<std::uint64_t>(placed >> 64));
  const std::int64_t sign = term < 0.0 ? -1 : 1;
  auto* d = digits_.data() + digit;
  d[0] += sign * low, d[1] += sign * middle, d[2] += sign * high;
  if (++since_normalised_ >= kAddsBeforeCarry) normalise();
}

void ExactSum::add(const ExactSum& other) {
  for (int i = 0; i < kDigits; ++i) digits_[static_cast<std::size_t>(i)] += other.digits_[static_cast<std::size_t>(i)];
  non_finite_ += other.non_finite_;
  since_normalised_ += other.since_normalised_ + 1;
  if (since_normalised_ >= kAddsBeforeCarry) normalise();
}

void ExactSum::normalise() {
  for (std::size_t i = 0; i + 1 < digits_.size(); ++i) {
    const std::int64_t carry = digits_[i] >> 32;  // floor division by 2^32
    digits_[i] -= carry * kDigitBase;
    digits_[i + 1] += carry;
  }
  since_normalised_ = 0;
}

void ExactSum::clear() {
  digits_.fill(0);
  non_finite_ = 0.0;
  since_normalised_ = 0;
}

double ExactSum::value() const {
  if (non_finite_ != 0.0 || std::isnan(non_finite_)) return non_finite_;
  ExactSum s = *this;
  s.normalise();  // digits in [0, 2^32), the sign in the top digit
  const bool negative = s.digits_.back() < 0;
  if (negative) {
    for (auto& d : s.digits_) d = -d;
    s.normalise();
  }
  int top = kDigits - 1;
  while (top >= 0 && s.digits_[static_cast<std::size_t>(top)] == 0) --top;
  if (top < 0) return 0.0;
  auto digit = [&](int i) { return i >= 0 ? static_cast<std::uint64_t>(s.digits_[static_cast<std::size_t>(i)]) : 0u; };
  // The three highest digits in a 96-bit window, its leading bit brought to bit 63 of `mantissa`; what falls off
  // below, and every lower digit, is the sticky bit that makes the conversion round as the exact sum would.
  const Wide window =
      (static_cast<Wide>(digit(top)) << 64) | (static_cast<Wide>(digit(top - 1)) << 32) |
      digit(top - 2);
  bool sticky = false;
  for (int i = top - 3; i >= 0 && !sticky; --i) sticky = digit(i) != 0;
  // The top digit is not zero, so the leading bit is in the window's top 32 bits (64 .. 95).
  const int leading = 127 - std::countl_zero(static_cast<std::uint64_t>(window >> 64));
  const int lowest_bit = leading - 63;  // position in the window of bit 0 of `mantissa` (1 .. 32)
  sticky = sticky || (window & ((static_cast<Wide>(1) << lowest_bit) - 1)) != 0;
  const auto mantissa = static_cast<std::uint64_t>(window >> lowest_bit);
  const double rounded = static_cast<double>(mantissa | (sticky ? 1u : 0u));
  const int exponent = 32 * (top - 2) + kLowestExponent + lowest_bit;
  const double magnitude = std::ldexp(rounded, exponent);
  return negative ? -magnitude : magnitude;
}

}  // namespace crumple
