#include "curdle/probability.h"

#include <charconv>
#include <cmath>
#include <numeric>

namespace curdle {
namespace {

std::optional<uint64_t> parse_uint(std::string_view s) {
  if (s.empty() || s.size() > 18) return std::nullopt;
  uint64_t v = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

Probability Probability::fraction(uint64_t numerator, uint64_t denominator) {
  Probability p;
  uint64_t g = std::gcd(numerator, denominator);
  p.numerator_ = numerator / g;
  p.denominator_ = denominator / g;
  p.value_ = static_cast<double>(p.numerator_) / static_cast<double>(p.denominator_);
  p.text_ = p.denominator_ == 1
                ? std::to_string(p.numerator_)
                : std::to_string(p.numerator_) + "/" + std::to_string(p.denominator_);
  p.set_threshold();
  return p;
}

std::optional<Probability> Probability::parse(const std::string& text) {
  std::string_view s = trim(text);
  if (auto slash = s.find('/'); slash != std::string_view::npos) {
    auto num = parse_uint(trim(s.substr(0, slash)));
    auto den = parse_uint(trim(s.substr(slash + 1)));
    if (!num || !den || *den == 0 || *num > *den) return std::nullopt;
    Probability p = fraction(*num, *den);
    p.text_ = std::string(s);
    return p;
  }
  // A decimal: digits, optionally '.', digits. Kept exact as a fraction over 10^k.
  auto dot = s.find('.');
  std::string_view whole = s.substr(0, dot);
  std::string_view frac = dot == std::string_view::npos ? std::string_view{} : s.substr(dot + 1);
  if (whole.empty() && frac.empty()) return std::nullopt;
  if (frac.size() > 17) return std::nullopt;
  uint64_t w = 0, f = 0, den = 1;
  if (!whole.empty()) {
    auto v = parse_uint(whole);
    if (!v) return std::nullopt;
    w = *v;
  }
  if (!frac.empty()) {
    auto v = parse_uint(frac);
    if (!v) return std::nullopt;
    f = *v;
    for (size_t i = 0; i < frac.size(); ++i) den *= 10;
  }
  if (w > 1 || (w == 1 && f != 0)) return std::nullopt;
  Probability p = fraction(w * den + f, den);
  p.text_ = std::string(s);
  return p;
}

std::optional<Probability> Probability::from_double(double value) {
  if (!(value >= 0.0 && value <= 1.0)) return std::nullopt;
  Probability p;
  p.value_ = value;
  char buf[32];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
  p.text_ = std::string(buf, ptr);
  // Prefer the exact decimal the user typed when it round-trips (0.7 means 7/10).
  if (auto exact = parse(p.text_); exact && exact->value_ == value) return exact;
  p.set_threshold();
  return p;
}

void Probability::set_threshold() {
  certain_ = false;
  if (denominator_ != 0) {
    if (numerator_ == denominator_) {
      certain_ = true;
      threshold_ = UINT64_MAX;
      return;
    }
    unsigned __int128 scaled = static_cast<unsigned __int128>(numerator_) << 64;
    threshold_ = static_cast<uint64_t>(scaled / denominator_);
    return;
  }
  if (value_ >= 1.0) {
    certain_ = true;
    threshold_ = UINT64_MAX;
    return;
  }
  threshold_ = static_cast<uint64_t>(std::ldexp(value_, 64));  // exact: a double has 53 bits
}

bool Probability::times_is_whole(uint64_t n) const {
  if (denominator_ != 0)
    return (static_cast<unsigned __int128>(numerator_) * n) % denominator_ == 0;
  double x = value_ * static_cast<double>(n);
  return std::fabs(x - std::round(x)) < 1e-9;
}

uint64_t Probability::round_times(uint64_t n) const {
  if (denominator_ != 0) {
    unsigned __int128 twice = static_cast<unsigned __int128>(numerator_) * n * 2 + denominator_;
    return static_cast<uint64_t>(twice / (2 * static_cast<unsigned __int128>(denominator_)));
  }
  return static_cast<uint64_t>(std::floor(value_ * static_cast<double>(n) + 0.5));
}

std::optional<std::pair<uint64_t, uint64_t>> exact_sum(const std::vector<Probability>& terms,
                                                       size_t n) {
  unsigned __int128 num = 0, den = 1;
  for (size_t i = 0; i < n; ++i) {
    if (!terms[i].is_rational()) return std::nullopt;
    num = num * terms[i].denominator() + static_cast<unsigned __int128>(terms[i].numerator()) * den;
    den *= terms[i].denominator();
    const uint64_t g = std::gcd(static_cast<uint64_t>(num % den), static_cast<uint64_t>(den));
    if (g > 1) num /= g, den /= g;
    if (den >> 62 || num >> 62) return std::nullopt;
  }
  return std::pair{static_cast<uint64_t>(num), static_cast<uint64_t>(den)};
}

}  // namespace curdle
