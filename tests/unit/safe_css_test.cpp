// The CSS allow-list of report.html (report/safe_css.h): values that could fetch or run are
// refused whatever their spelling, safe ones kept as written, style sheets scoped to the
// animation's box, and every drop counted by kind.
#include <doctest/doctest.h>

#include "report/safe_css.h"

using namespace svgm;

TEST_SUITE("report") {
  TEST_CASE("a CSS value is kept only when it can neither fetch nor run") {
    for (const char* v : {"red", "#fff", "none", "url(#g)", "url( '#g' ) red", "url(\"#a.b:c\")", "rgb(1, 2, 3)",
                          "rotate(10deg) translate(1px,2px)", "10px", "\"Noto Sans\", serif", "0.5"})
      CHECK_MESSAGE(safe_css_value(v), v);
    for (const char* v : {"url(http://h/x)", "url(x.svg#a)", "url(//h/x)", "url(data:image/png;base64,AA)", "url(#a b)",
                          "url(#xpointer(id('a')))", "u\\72l(http://h/x)", "URL(file:///etc/hostname)", "expression(alert(1))",
                          "image-set(\"x.png\" 1x)", "var(--x)", "red;background:url(http://h/x)", "/*x*/red", "red}a{b:c",
                          "url(#a", "(#a)", "\"</style><script>\""})
      CHECK_MESSAGE(!safe_css_value(v), v);
    CHECK(local_reference("#a-b_c.d:e"));
    CHECK(!local_reference("#"));
    CHECK(!local_reference("a.svg#b"));
    CHECK(!local_reference("#svgView(viewBox(0,0,1,1))"));
  }

  TEST_CASE("a style attribute keeps its safe declarations and counts the others") {
    DropTally dropped;
    CHECK(safe_style_declarations("fill: red; background: url(http://h/x); stroke:url(#g) !important; FILL-OPACITY: .5;"
                                  " clip-path: url(http://h/c#c); behavior: url(x.htc); nonsense",
                                  dropped) == "fill:red;stroke:url(#g)!important;fill-opacity:.5");
    CHECK(dropped.summary() ==
          "1 background declaration, 1 clip-path declaration with an unsafe value, 1 behavior declaration, "
          "1 malformed CSS declaration");
  }

  TEST_CASE("a style sheet keeps simple rules, scoped, and drops at-rules and other selectors") {
    DropTally dropped;
    const std::string css =
        "@import url(http://h/a.css); /* a comment */ .a, #b > path { fill: red; cursor: url(x.cur) }\n"
        "a:hover { fill: red } @media print { path { fill: blue } } @font-face { src: url(http://h/f.woff) }\n"
        "path { fill: url(http://h/p.svg#g) } * { opacity: 0.5 } @charset \"utf-8\";";
    CHECK(safe_style_sheet(css, "#s ", dropped) == "#s .a,#s #b > path{fill:red}#s *{opacity:0.5}");
    CHECK(dropped.summary() ==
          "1 @import rule, 1 cursor declaration, 1 CSS rule with an unsupported selector, 1 @media rule, "
          "1 @font-face rule, 1 fill declaration with an unsafe value, 1 @charset rule");
    DropTally open;
    CHECK(safe_style_sheet("path { fill: red", "#s ", open) == "#s path{fill:red}");  // the sheet ends the rule
    CHECK(open.empty());
  }
}
