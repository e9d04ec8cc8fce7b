// Bench tool: what the part locator (procedural/part_locator.h) finds on drawings for one kind of
// part, to check a locator rule on a corpus (issue 35: every emoji with smoke, fire or steam).
//   part_probe KIND X.svg ...   (KIND: a noun the locator knows, "smoke", "flames", "propeller")
// One line per drawing: its file, the lobes found, the paths that move and the locator's why.
// The rig is built from the file as drawn (build_rig with no grouper): a run's grouped.svg may
// group it otherwise. PART_PROBE_ELEMENTS=1 lists the figure's elements under each line.
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "procedural/part_locator.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: part_probe KIND X.svg ...\n");
    return 2;
  }
  const PartShape shape = part_shape_of(argv[1], FigureClass::None);
  if (shape == PartShape::None) {
    std::fprintf(stderr, "part_probe: the locator knows no part '%s'\n", argv[1]);
    return 2;
  }
  for (int a = 2; a < argc; ++a) {
    try {
      const Scene s = read_svg_file(argv[a]);
      const Rig rig = build_rig(s, read_source_names(argv[a]));
      const LocatedPart p = locate_part(rig, shape);
      std::string paths;
      for (int i : p.paths) paths += (paths.empty() ? "" : "+") + std::to_string(i + 1);
      std::printf("%s\t%zu\t%s\t%s\n", argv[a], p.lobes.size(), paths.empty() ? "-" : paths.c_str(), p.why.c_str());
      if (std::getenv("PART_PROBE_ELEMENTS"))  // the elements the locator chose from
        for (const RigElement& e : rig.elements)
          std::printf("  path %d.%d\tbox %s\tarea %.3g\n", e.path + 1, e.subpath, fmt_box(rig, e.box).c_str(), e.area);
    } catch (const std::exception& e) {
      std::printf("%s\terror\t%s\n", argv[a], e.what());
    }
  }
  return 0;
}
