// librsvg's render time through dlopen (see bench_librsvg.h). The few entry points are declared
// here by their documented C signatures; handles and surfaces are opaque pointers.
#include "cli/bench_librsvg.h"

#include <dlfcn.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "cli/bench_util.h"

namespace svgm::cli {

namespace {

struct RsvgRect {
  double x, y, width, height;  // RsvgRectangle
};

struct Librsvg {
  void* (*new_from_file)(const char*, void**) = nullptr;                  // rsvg_handle_new_from_file
  int (*intrinsic_px)(void*, double*, double*) = nullptr;                // rsvg_handle_get_intrinsic_size_in_pixels
  int (*render_document)(void*, void*, const RsvgRect*, void**) = nullptr;  // rsvg_handle_render_document
  void (*unref)(void*) = nullptr;                                         // g_object_unref
  void* (*surface_create)(int, int, int) = nullptr;                       // cairo_image_surface_create
  void* (*create)(void*) = nullptr;                                       // cairo_create
  void (*set_source_rgb)(void*, double, double, double) = nullptr;        // cairo_set_source_rgb
  void (*paint)(void*) = nullptr;                                         // cairo_paint
  void (*surface_flush)(void*) = nullptr;                                 // cairo_surface_flush
  void (*destroy)(void*) = nullptr;                                       // cairo_destroy
  void (*surface_destroy)(void*) = nullptr;                               // cairo_surface_destroy
  bool ok = false;
};

template <class F>
bool bind(void* lib, const char* name, F& f) {
  f = lib ? reinterpret_cast<F>(dlsym(lib, name)) : nullptr;
  return f != nullptr;
}

const Librsvg& librsvg() {
  static const Librsvg l = [] {
    Librsvg r;
    void* rsvg = dlopen("librsvg-2.so.2", RTLD_NOW | RTLD_LOCAL);
    void* cairo = dlopen("libcairo.so.2", RTLD_NOW | RTLD_LOCAL);
    void* gobject = dlopen("libgobject-2.0.so.0", RTLD_NOW | RTLD_LOCAL);
    r.ok = bind(rsvg, "rsvg_handle_new_from_file", r.new_from_file) &&
           bind(rsvg, "rsvg_handle_get_intrinsic_size_in_pixels", r.intrinsic_px) &&
           bind(rsvg, "rsvg_handle_render_document", r.render_document) &&
           bind(gobject, "g_object_unref", r.unref) &&
           bind(cairo, "cairo_image_surface_create", r.surface_create) && bind(cairo, "cairo_create", r.create) &&
           bind(cairo, "cairo_set_source_rgb", r.set_source_rgb) && bind(cairo, "cairo_paint", r.paint) &&
           bind(cairo, "cairo_surface_flush", r.surface_flush) && bind(cairo, "cairo_destroy", r.destroy) &&
           bind(cairo, "cairo_surface_destroy", r.surface_destroy);
    return r;
  }();
  return l;
}

}  // namespace

std::optional<LibrsvgTimes> librsvg_ms_per_frame(const std::string& svg, int width, int frames, int repeat) {
  const Librsvg& l = librsvg();
  if (!l.ok) return std::nullopt;
  void* handle = l.new_from_file(svg.c_str(), nullptr);  // a null GError**: errors are not reported
  if (!handle) return std::nullopt;
  double w = 0, h = 0;
  if (!l.intrinsic_px(handle, &w, &h) || w <= 0) w = h = 1;
  const int height = std::max(1, static_cast<int>(std::lround(width * h / w)));
  const RsvgRect viewport{0, 0, double(width), double(height)};
  constexpr int kArgb32 = 0;  // CAIRO_FORMAT_ARGB32
  std::vector<double> ms, cpu_ms;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    for (int k = 0; k < frames; ++k) {
      void* surface = l.surface_create(kArgb32, width, height);
      void* cr = l.create(surface);
      l.set_source_rgb(cr, 1, 1, 1);
      l.paint(cr);
      l.render_document(handle, cr, &viewport, nullptr);
      l.surface_flush(surface);
      l.destroy(cr);
      l.surface_destroy(surface);
    }
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / frames);
    cpu_ms.push_back((cpu_seconds() - c0) * 1e3 / frames);
  }
  l.unref(handle);
  return LibrsvgTimes{median(ms), median(cpu_ms)};
}

}  // namespace svgm::cli
