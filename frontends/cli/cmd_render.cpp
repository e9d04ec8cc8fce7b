// `svgmotion render`: rasterise an SVG to a PNG through the OpenCL renderer.
//
// The output format follows the extension: .png is written; any other (.svg, .jpg, none) is
// refused before anything is read, and the output may never be the input file itself (the
// same file under another name or through a link included).
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"

namespace svgm::cli {

int cmd_render(const std::vector<std::string>& argv) {
  const Args a = parse_args("render", argv,
                            {"-o", "--output", "--size", "--background", "--device", "--time"},
                            {"--strict"});
  if (a.positional.size() != 1)
    throw Error("render: expected one input SVG (svgmotion render IN.svg -o OUT.png)");
  const std::string input = a.positional[0];
  const auto out = a.get("-o") ? a.get("-o") : a.get("--output");
  if (!out || out->empty()) throw Error("render: missing -o OUT.png");
  {
    std::error_code ec;
    if (std::filesystem::equivalent(input, *out, ec))
      throw Error(*out + ": is the input file; choose another output name");
    std::string ext = std::filesystem::path(*out).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".png")
      throw Error(*out + ": render writes PNG images only; name the output with a .png extension" +
                  (ext.empty() ? std::string() : " (not " + ext + ")"));
  }
  const std::string bg = a.get("--background").value_or("white");
  if (bg != "white" && bg != "transparent")
    throw Error("render: --background must be white or transparent, got '" + bg + "'");
  const int width = a.get_int("--size", 0, 1, 16384);

  SvgReadLimits read_options;
  read_options.animation_time = a.get_double("--time", -1);
  if (a.has("--time") && !(read_options.animation_time >= 0))
    throw Error("render: --time wants a number of seconds >= 0");
  Scene scene = read_svg_file(input, read_options);
  for (const auto& w : scene.warnings) std::fprintf(stderr, "svgmotion: warning: %s\n", w.c_str());
  if (a.has("--strict") && !scene.warnings.empty())
    throw Error(input + ": warnings are errors under --strict");
  const RenderSize size = render_size(scene, width);
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);

  ClRuntime rt(a.get("--device").value_or("auto"));
  ClRaster raster(rt, plan, 1);
  raster.set_rest_pose();
  const std::array<float, 4> white{1, 1, 1, 1}, clear{0, 0, 0, 0};
  raster.forward(ClRaster::Output::Rgba8, bg == "white" ? white : clear);
  RgbaImage img{size.width, size.height, raster.read_rgba8()};
  write_png(*out, img);
  std::fprintf(stderr, "svgmotion: wrote %s (%dx%d)\n", out->c_str(), size.width, size.height);
  return 0;
}

}  // namespace svgm::cli
