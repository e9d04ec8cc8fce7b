// A minimal CSS style sheet for SVG <style> elements, as editors such as Illustrator write
// them (".st0{fill:#E30613;}"): rules whose selectors are compound simple selectors (`*`,
// `tag`, `.class`, `#id` and combinations such as `path.st0`), matched with CSS specificity
// and source order. Rules with other selectors (descendant or child combinators, attribute
// selectors, pseudo-classes) and at-rules (@media, @font-face, ...) are skipped and counted so
// the reader can warn once. `!important` is accepted and ignored.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace svgm::svg {

struct CssDeclaration {
  std::string name, value;
};

class StyleSheet {
 public:
  // Adds the rules of one <style> element's text. Returns how many selectors were skipped.
  int add(std::string_view css);
  bool empty() const { return rules_.empty(); }

  // The declarations that apply to an element, lowest precedence first (ascending
  // specificity, then source order), so applying them in turn gives the cascaded value.
  void match(std::string_view tag, std::string_view id, std::string_view class_attr,
             std::vector<const CssDeclaration*>& out) const;

 private:
  struct Rule {
    std::string tag;  // empty or "*": any element
    std::string id;
    std::vector<std::string> classes;
    int specificity = 0;
    int order = 0;
    size_t block = 0;  // index into blocks_
  };
  std::vector<Rule> rules_;
  std::vector<std::vector<CssDeclaration>> blocks_;
};

// The declarations of a `style` attribute or rule block: "a: b; c: d" (comments removed,
// names trimmed, values trimmed and without `!important`).
std::vector<CssDeclaration> parse_declarations(std::string_view block);

}  // namespace svgm::svg
