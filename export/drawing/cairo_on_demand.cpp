#include "export/drawing/cairo_on_demand.h"

#include <dlfcn.h>

#include <future>
#include <mutex>
#include <stdexcept>

// The forwarders below are the only definitions of these names in curdle, and stay inside it: a
// program or the Python module that maps the real cairo as well keeps calling its own.
#define cairo_public __attribute__((visibility("hidden")))
#include <cairo-pdf.h>
#include <cairo.h>

namespace curdle {
namespace {

constexpr const char* kLibrary = "libcairo.so.2";

struct Loaded {
  void* handle = nullptr;
  std::string why;
};

Loaded load() {
  Loaded out;
  out.handle = ::dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (!out.handle) {
    const char* error = ::dlerror();
    out.why = std::string("drawings (layout.pdf, layout.png) need cairo, and ") + kLibrary +
              " will not load (" + (error ? error : "no reason given") +
              "); on Debian it comes with libcairo2, which setup.sh installs";
  }
  return out;
}

std::mutex loading_mutex;

std::shared_future<Loaded> start_loading() {
  static std::shared_future<Loaded> loading;
  std::lock_guard lock(loading_mutex);
  if (!loading.valid()) loading = std::async(std::launch::async, load).share();
  return loading;
}

// The library's own definition of `name`; throws std::runtime_error when cairo will not load.
void* real(const char* name) {
  const Loaded& loaded = start_loading().get();
  if (!loaded.handle) throw std::runtime_error(loaded.why);
  void* symbol = ::dlsym(loaded.handle, name);
  if (!symbol) throw std::runtime_error(std::string(kLibrary) + " lacks " + name);
  return symbol;
}

}  // namespace

bool cairo_installed(std::string* why) {
  const std::shared_future<Loaded> loading = start_loading();
  // Answered without waiting unless the answer is already known to be no.
  if (loading.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return true;
  if (loading.get().handle) return true;
  if (why) *why = loading.get().why;
  return false;
}

}  // namespace curdle

// Each forwarder looks its function up once.
#define CURDLE_CAIRO(result, name, parameters, arguments)                                \
  extern "C" result name parameters {                                                    \
    static const auto function = reinterpret_cast<decltype(&name)>(curdle::real(#name)); \
    return function arguments;                                                           \
  }

CURDLE_CAIRO(void, cairo_arc,
             (cairo_t * cr, double xc, double yc, double radius, double angle1, double angle2),
             (cr, xc, yc, radius, angle1, angle2))
CURDLE_CAIRO(void, cairo_clip, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_close_path, (cairo_t * cr), (cr))
CURDLE_CAIRO(cairo_t*, cairo_create, (cairo_surface_t * target), (target))
CURDLE_CAIRO(void, cairo_destroy, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_fill, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_fill_preserve, (cairo_t * cr), (cr))
CURDLE_CAIRO(cairo_font_options_t*, cairo_font_options_create, (), ())
CURDLE_CAIRO(void, cairo_font_options_set_antialias,
             (cairo_font_options_t * options, cairo_antialias_t antialias), (options, antialias))
CURDLE_CAIRO(void, cairo_font_options_set_hint_metrics,
             (cairo_font_options_t * options, cairo_hint_metrics_t hint_metrics),
             (options, hint_metrics))
CURDLE_CAIRO(void, cairo_font_options_set_hint_style,
             (cairo_font_options_t * options, cairo_hint_style_t hint_style), (options, hint_style))
CURDLE_CAIRO(int, cairo_format_stride_for_width, (cairo_format_t format, int width),
             (format, width))
CURDLE_CAIRO(void, cairo_get_current_point, (cairo_t * cr, double* x, double* y), (cr, x, y))
CURDLE_CAIRO(cairo_pattern_t*, cairo_get_source, (cairo_t * cr), (cr))
CURDLE_CAIRO(cairo_surface_t*, cairo_image_surface_create,
             (cairo_format_t format, int width, int height), (format, width, height))
CURDLE_CAIRO(cairo_surface_t*, cairo_image_surface_create_for_data,
             (unsigned char* data, cairo_format_t format, int width, int height, int stride),
             (data, format, width, height, stride))
CURDLE_CAIRO(unsigned char*, cairo_image_surface_get_data, (cairo_surface_t * surface), (surface))
CURDLE_CAIRO(int, cairo_image_surface_get_stride, (cairo_surface_t * surface), (surface))
CURDLE_CAIRO(void, cairo_line_to, (cairo_t * cr, double x, double y), (cr, x, y))
CURDLE_CAIRO(void, cairo_move_to, (cairo_t * cr, double x, double y), (cr, x, y))
CURDLE_CAIRO(void, cairo_new_path, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_new_sub_path, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_paint, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_paint_with_alpha, (cairo_t * cr, double alpha), (cr, alpha))
CURDLE_CAIRO(void, cairo_pattern_set_filter, (cairo_pattern_t * pattern, cairo_filter_t filter),
             (pattern, filter))
CURDLE_CAIRO(void, cairo_pop_group_to_source, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_push_group, (cairo_t * cr), (cr))
CURDLE_CAIRO(cairo_surface_t*, cairo_pdf_surface_create_for_stream,
             (cairo_write_func_t write_func, void* closure, double width_in_points,
              double height_in_points),
             (write_func, closure, width_in_points, height_in_points))
CURDLE_CAIRO(void, cairo_pdf_surface_set_metadata,
             (cairo_surface_t * surface, cairo_pdf_metadata_t metadata, const char* utf8),
             (surface, metadata, utf8))
CURDLE_CAIRO(void, cairo_pdf_surface_set_size,
             (cairo_surface_t * surface, double width_in_points, double height_in_points),
             (surface, width_in_points, height_in_points))
CURDLE_CAIRO(void, cairo_rectangle, (cairo_t * cr, double x, double y, double width, double height),
             (cr, x, y, width, height))
CURDLE_CAIRO(void, cairo_restore, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_rotate, (cairo_t * cr, double angle), (cr, angle))
CURDLE_CAIRO(void, cairo_save, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_scale, (cairo_t * cr, double sx, double sy), (cr, sx, sy))
CURDLE_CAIRO(void, cairo_select_font_face,
             (cairo_t * cr, const char* family, cairo_font_slant_t slant,
              cairo_font_weight_t weight),
             (cr, family, slant, weight))
CURDLE_CAIRO(void, cairo_set_dash,
             (cairo_t * cr, const double* dashes, int num_dashes, double offset),
             (cr, dashes, num_dashes, offset))
CURDLE_CAIRO(void, cairo_set_fill_rule, (cairo_t * cr, cairo_fill_rule_t fill_rule),
             (cr, fill_rule))
CURDLE_CAIRO(void, cairo_set_font_options, (cairo_t * cr, const cairo_font_options_t* options),
             (cr, options))
CURDLE_CAIRO(void, cairo_set_font_size, (cairo_t * cr, double size), (cr, size))
CURDLE_CAIRO(void, cairo_set_line_cap, (cairo_t * cr, cairo_line_cap_t line_cap), (cr, line_cap))
CURDLE_CAIRO(void, cairo_set_line_width, (cairo_t * cr, double width), (cr, width))
CURDLE_CAIRO(void, cairo_set_source_rgba,
             (cairo_t * cr, double red, double green, double blue, double alpha),
             (cr, red, green, blue, alpha))
CURDLE_CAIRO(void, cairo_set_source_surface,
             (cairo_t * cr, cairo_surface_t* surface, double x, double y), (cr, surface, x, y))
CURDLE_CAIRO(void, cairo_show_page, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_show_text, (cairo_t * cr, const char* utf8), (cr, utf8))
CURDLE_CAIRO(const char*, cairo_status_to_string, (cairo_status_t status), (status))
CURDLE_CAIRO(void, cairo_stroke, (cairo_t * cr), (cr))
CURDLE_CAIRO(void, cairo_surface_destroy, (cairo_surface_t * surface), (surface))
CURDLE_CAIRO(void, cairo_surface_finish, (cairo_surface_t * surface), (surface))
CURDLE_CAIRO(void, cairo_surface_flush, (cairo_surface_t * surface), (surface))
CURDLE_CAIRO(cairo_status_t, cairo_surface_status, (cairo_surface_t * surface), (surface))
CURDLE_CAIRO(void, cairo_text_extents,
             (cairo_t * cr, const char* utf8, cairo_text_extents_t* extents), (cr, utf8, extents))
CURDLE_CAIRO(void, cairo_translate, (cairo_t * cr, double tx, double ty), (cr, tx, ty))

#undef CURDLE_CAIRO
