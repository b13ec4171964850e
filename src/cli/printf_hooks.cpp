// The programs refuse printf hooks. GDAL maps libgfortran, which maps libquadmath, whose
// constructor registers handlers for %f, %e, %g and %a with glibc; from then on glibc sends
// every printf of the process, cairo's numbers in layout.pdf included, down its slow general
// path (printf_positional). The pavilion's whole run spent 3.4 % of its instructions there.
// Defined here and exported from the program (CMakeLists.txt), these come before glibc's for
// every library the process loads; libquadmath, told no, registers nothing, and its own
// quadmath_snprintf, which no curdle code calls, works without them.
#include <printf.h>

#include <cerrno>

extern "C" {

__attribute__((visibility("default"))) int register_printf_specifier(
    int /*spec*/, printf_function* /*handler*/,
    printf_arginfo_size_function* /*arginfo*/) noexcept {
  errno = ENOSYS;
  return -1;
}

__attribute__((visibility("default"))) int register_printf_modifier(
    const wchar_t* /*text*/) noexcept {
  errno = ENOSYS;
  return -1;
}

__attribute__((visibility("default"))) int register_printf_type(
    printf_va_arg_function* /*fetch*/) noexcept {
  errno = ENOSYS;
  return -1;
}

}  // extern "C"
