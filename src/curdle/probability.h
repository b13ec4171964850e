// A stage probability, kept exact where the user wrote it exactly ("3/4", "0.7" as text),
// with a 64-bit fixed-point threshold so that a Bernoulli draw is an integer comparison.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace curdle {

class Probability {
 public:
  Probability() = default;

  // Parses "3/4", "0.75", "1", "0". Returns nullopt for anything else or a value outside
  // [0, 1]; the caller reports the error with its location.
  static std::optional<Probability> parse(const std::string& text);
  static std::optional<Probability> from_double(double value);
  static Probability fraction(uint64_t numerator, uint64_t denominator);

  double value() const { return value_; }
  const std::string& text() const { return text_; }
  bool is_rational() const { return denominator_ != 0; }
  uint64_t numerator() const { return numerator_; }
  uint64_t denominator() const { return denominator_; }

  // P(survive) = threshold / 2^64 exactly, except that certain() means probability 1.
  uint64_t threshold() const { return threshold_; }
  bool certain() const { return certain_; }

  // True when p * n is a whole number (exact mode needs p * b^E whole).
  bool times_is_whole(uint64_t n) const;
  // round(p * n), halves rounded up, exact for rationals.
  uint64_t round_times(uint64_t n) const;

 private:
  void set_threshold();

  double value_ = 0.0;
  std::string text_;
  uint64_t numerator_ = 0;
  uint64_t denominator_ = 0;  // 0: not rational, use value_
  uint64_t threshold_ = 0;
  bool certain_ = false;
};

// p_1 + ... + p_n as numerator and denominator in lowest terms, exact while both stay below
// 2^62; nothing when a term is not a fraction or the sum outgrows that.
std::optional<std::pair<uint64_t, uint64_t>> exact_sum(const std::vector<Probability>& terms,
                                                       size_t n);

}  // namespace curdle
