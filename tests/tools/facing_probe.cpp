// Bench tool: which way drawings face as the engine reads them (issue 35), to check the facing
// rules (eye_cue.h, shape_facing.h) on a corpus against the facing a reader sees.
//   facing_probe CLASS X.svg ...   (CLASS: a figure class the lexicon names, "quadruped", "wheeled")
// One line per drawing: its file, how many head or tail limbs the eye cue places by their base
// (their base and tip at opposite ends: eye_cue.h), the eye's side, the outline's side for CLASS, the facing the
// plan uses (limb_qualifiers.h, with CLASS), each end's top and thickness, and the reading's why.
// The rig is built from the file as drawn (build_rig with no grouper), the eye read in its colours.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "procedural/body_facing.h"
#include "procedural/eye_cue.h"
#include "procedural/limb_qualifiers.h"
#include "procedural/shape_facing.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: facing_probe CLASS X.svg ...\n");
    return 2;
  }
  FigureClass cls = FigureClass::None;
  for (FigureClass c : {FigureClass::Biped, FigureClass::Quadruped, FigureClass::Bird, FigureClass::FishOrSnake, FigureClass::Insect,
                        FigureClass::Wheeled, FigureClass::Object})
    if (std::string(figure_class_name(c)) == argv[1]) cls = c;
  if (cls == FigureClass::None) {
    std::fprintf(stderr, "facing_probe: no figure class '%s'\n", argv[1]);
    return 2;
  }
  auto side = [](int s) { return s < 0 ? "L" : s > 0 ? "R" : "-"; };
  for (int a = 2; a < argc; ++a) {
    try {
      const Scene s = read_svg_file(argv[a]);
      Rig rig = build_rig(s, read_source_names(argv[a]));
      apply_eye_cue(rig, s, s);
      std::string shape_why, why;
      const int shape = shape_facing(rig, cls, &shape_why);
      const int facing = facing_side(rig, cls, &why);
      const int body = body_facing(rig, cls, nullptr);
      const SideProfile p = side_profile(rig);
      const BodyEnds e = body_ends(rig);
      // Head and tail limbs whose base and tip lie at opposite ends (eye_cue.h: placed by the base).
      int by_base = 0;
      const double mid = rig.figure.centre().x, off = kEyeOffCentre * rig.figure.w();
      for (const ArmLobe& l : rig.limbs)
        if (rig.eye_side != 0 && (l.kind == LobeKind::Head || l.kind == LobeKind::Tail) && std::fabs(l.pivot.x - mid) > off &&
            std::fabs(l.tip.x - mid) > off && (l.pivot.x - mid) * (l.tip.x - mid) < 0)
          ++by_base;
      std::printf("%s\tby base %d\teye %s\tshape %s\tfacing %s\tleft top %.2f thick %.2f\tright top %.2f thick %.2f\tbody %s over %.3f %.3f fill %.3f %.3f\t%s\n", argv[a], by_base,
                  side(rig.eye_side), side(shape), side(facing), p.left.top, p.left.thick, p.right.top, p.right.thick, side(body), e.overhang_left,
                  e.overhang_right, e.fill_left, e.fill_right, why.c_str());
    } catch (const std::exception& e) {
      std::printf("%s\terror\t%s\n", argv[a], e.what());
    }
  }
  return 0;
}
