// cairo, loaded the first time a drawing is made (layout.pdf, layout.png) instead of at every
// start: with the sixteen libraries it maps (X11, xcb, fontconfig, freetype, pixman, ...) it was
// half of the page faults of a `curdle --help`. The cairo_* functions the exporters call are
// defined in cairo_on_demand.cpp and forward to the library's own, so the drawing code calls
// cairo as usual.
#pragma once

#include <string>

namespace curdle {

// Whether cairo loads; when not, `why` says what is missing and what to install. When it does,
// it starts loading on a thread of its own, so that it is there by the time a drawing is made.
bool cairo_installed(std::string* why);

}  // namespace curdle
