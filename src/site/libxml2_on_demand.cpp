// libxml2, loaded the first time an SVG drawing is read instead of at every start: with ICU and
// liblzma it maps four libraries and a fifth of the page faults a `curdle --help` took. The
// libxml2 functions svg_reader.cpp calls are defined here and forward to the library's own, so
// the reader calls libxml2 as usual.
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stdexcept>
#include <string>

// These definitions stay inside curdle: a program or the Python module that maps the real
// libxml2 as well keeps calling its own.
#pragma GCC visibility push(hidden)
#include <libxml/parser.h>
#include <libxml/tree.h>

namespace {

constexpr const char* kLibrary = "libxml2.so.2";

void* library() {
  static void* const handle = [] {
    void* loaded = ::dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
    if (!loaded) {
      const char* error = ::dlerror();
      throw std::runtime_error(std::string("SVG drawings are read with libxml2, and ") + kLibrary +
                               " will not load (" + (error ? error : "no reason given") +
                               "); on Debian it comes with libxml2, which setup.sh installs");
    }
    return loaded;
  }();
  return handle;
}

// The library's own definition of `name`.
void* real(const char* name) {
  void* symbol = ::dlsym(library(), name);
  if (!symbol) throw std::runtime_error(std::string(kLibrary) + " lacks " + name);
  return symbol;
}

// libxml2 hands out attribute values from its own allocator, whatever that is set to.
void free_with_libxml2(void* memory) {
  static const auto free_function = *reinterpret_cast<xmlFreeFunc*>(real("xmlFree"));
  free_function(memory);
}

}  // namespace

xmlFreeFunc xmlFree = free_with_libxml2;

// Each forwarder looks its function up once.
#define CURDLE_LIBXML2(result, name, parameters, arguments)                      \
  result name parameters {                                                       \
    static const auto function = reinterpret_cast<decltype(&name)>(real(#name)); \
    return function arguments;                                                   \
  }

extern "C" {
CURDLE_LIBXML2(xmlNodePtr, xmlDocGetRootElement, (const xmlDoc* doc), (doc))
CURDLE_LIBXML2(void, xmlFreeDoc, (xmlDocPtr cur), (cur))
CURDLE_LIBXML2(xmlErrorPtr, xmlGetLastError, (), ())
CURDLE_LIBXML2(long, xmlGetLineNo, (const xmlNode* node), (node))
CURDLE_LIBXML2(xmlChar*, xmlGetNoNsProp, (const xmlNode* node, const xmlChar* name), (node, name))
CURDLE_LIBXML2(xmlChar*, xmlGetNsProp,
               (const xmlNode* node, const xmlChar* name, const xmlChar* nameSpace),
               (node, name, nameSpace))
CURDLE_LIBXML2(xmlDocPtr, xmlReadMemory,
               (const char* buffer, int size, const char* URL, const char* encoding, int options),
               (buffer, size, URL, encoding, options))
CURDLE_LIBXML2(int, xmlStrEqual, (const xmlChar* str1, const xmlChar* str2), (str1, str2))
}

#undef CURDLE_LIBXML2
#pragma GCC visibility pop
