// Programmer mistakes stop at their line with their values (after pbrt-v4's util/check.h):
// CHECK(c) and CHECK_EQ(a, b) (NE, LT, LE, GT, GE) print "file:line: check failed: a == b
// (3 vs 4)" and a note saying what broke, then abort, so that a broken invariant is found where
// it broke instead of unwinding as "internal error". DCHECK is CHECK in debug builds and
// nothing in release builds. Bad input is never a CHECK: it is an InputError (error.h).
#pragma once

#include <sstream>
#include <string>

namespace curdle::detail {

[[noreturn]] void check_failed(const char* file, int line, const char* condition,
                               const std::string& values, const std::string& note);

template <class A, class B>
std::string check_values(const A& a, const B& b) {
  std::ostringstream s;
  s << a << " vs " << b;
  return s.str();
}

}  // namespace curdle::detail

// CHECK(condition) or CHECK(condition, note): the note (a string) says what it means. The
// CURDLE_ names are the ones the installed headers use; the short ones are for curdle's own
// code, and are left alone where a program that includes curdle has its own.
#define CURDLE_CHECK(...) \
  CURDLE_CHECK_PICK(__VA_ARGS__, CURDLE_CHECK_NOTE, CURDLE_CHECK_BARE)(__VA_ARGS__)
#define CURDLE_CHECK_PICK(a, b, name, ...) name
#define CURDLE_CHECK_BARE(condition) CURDLE_CHECK_NOTE(condition, "")
#define CURDLE_CHECK_NOTE(condition, note) \
  ((condition) ? (void)0 : ::curdle::detail::check_failed(__FILE__, __LINE__, #condition, {}, note))

#define CURDLE_CHECK_OP(a, b, op)                                              \
  do {                                                                         \
    const auto& curdle_check_a = (a);                                          \
    const auto& curdle_check_b = (b);                                          \
    if (!(curdle_check_a op curdle_check_b))                                   \
      ::curdle::detail::check_failed(                                          \
          __FILE__, __LINE__, #a " " #op " " #b,                               \
          ::curdle::detail::check_values(curdle_check_a, curdle_check_b), ""); \
  } while (false)

#ifdef NDEBUG
#define CURDLE_DCHECK(...) ((void)0)
#else
#define CURDLE_DCHECK(...) CURDLE_CHECK(__VA_ARGS__)
#endif

#ifndef CHECK
#define CHECK(...) CURDLE_CHECK(__VA_ARGS__)
#define CHECK_EQ(a, b) CURDLE_CHECK_OP(a, b, ==)
#define CHECK_NE(a, b) CURDLE_CHECK_OP(a, b, !=)
#define CHECK_LT(a, b) CURDLE_CHECK_OP(a, b, <)
#define CHECK_LE(a, b) CURDLE_CHECK_OP(a, b, <=)
#define CHECK_GT(a, b) CURDLE_CHECK_OP(a, b, >)
#define CHECK_GE(a, b) CURDLE_CHECK_OP(a, b, >=)
#define DCHECK(...) CURDLE_DCHECK(__VA_ARGS__)
#endif
