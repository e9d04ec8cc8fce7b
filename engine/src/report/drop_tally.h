// What the report's sanitiser left out of the user's animation, counted by kind in order of
// first occurrence, for the one warning line that names it ("2 <script>, 1 <foreignObject>,
// 3 on* attributes"). Shared by the document filter (inline_svg.cpp) and the CSS filter
// (safe_css.cpp).
#pragma once

#include <string>
#include <vector>

namespace svgm {

class DropTally {
 public:
  // One more of a kind, named as it is counted: ("on* attribute", "on* attributes").
  void add(const std::string& singular, const std::string& plural) {
    for (Kind& k : kinds_)
      if (k.singular == singular) {
        ++k.count;
        return;
      }
    kinds_.push_back({singular, plural, 1});
  }
  // Element names ("<script>") read the same in the singular and the plural.
  void add(const std::string& name) { add(name, name); }
  bool empty() const { return kinds_.empty(); }
  std::string summary() const {
    std::string s;
    for (const Kind& k : kinds_)
      s += (s.empty() ? "" : ", ") + std::to_string(k.count) + " " + (k.count == 1 ? k.singular : k.plural);
    return s;
  }

 private:
  struct Kind {
    std::string singular, plural;
    int count = 0;
  };
  std::vector<Kind> kinds_;
};

}  // namespace svgm
