// The animation as report.html inlines it (report/inline_svg.h): every file of the hostile
// corpus (tests/data/hostile, see its README) loses what could run or fetch, the warning names
// it, and the drawing and its animation stay; a benign document using everything the allow-list
// keeps comes out whole, written the way HTML and XML both read it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>

#include "report/inline_svg.h"
#include "temp_dir.h"
#include "test_paths.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The animated square every hostile file carries, as it must come out.
constexpr const char* kSquare =
    "<path id=\"p\" d=\"M10 10H90V90H10Z\" fill=\"#c33\"><animate attributeName=\"d\" dur=\"1s\" repeatCount=\"indefinite\" "
    "values=\"M10 10H90V90H10Z;M20 20H80V80H20Z;M10 10H90V90H10Z\"></animate></path>";

InlinedSvg inline_text(const std::string& text) {
  test::TempDir dir("svgm_inline_svg");
  std::ofstream(dir.path / "a.svg") << text;
  return inline_svg(dir.path / "a.svg");
}

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("every hostile file loses what could run or fetch, named, and keeps its animation") {
    struct Case {
      const char* file;
      const char* dropped;
    };
    const Case cases[] = {
        {"script_comment_breakout", "1 comment holding markup"},
        {"script_uppercase", "1 <SCRIPT>"},
        {"script_cdata_foreignobject", "1 <foreignObject>"},
        {"script_iframe_javascript", "1 <foreignObject>"},
        {"script_iframe_srcdoc", "1 <foreignObject>"},
        {"script_javascript_url_tab", "1 href outside the drawing"},
        {"script_a_javascript", "1 href outside the drawing"},
        {"script_set_href", "1 href on <a>, 1 <set> of href"},
        {"script_animate_href", "1 href on <a>, 1 <animate> of xlink:href"},
        {"script_onload", "2 on* attributes"},
        {"fetch_css_import", "1 @import rule"},
        {"fetch_css_url", "1 background-image declaration, 1 cursor declaration, 1 @font-face rule, "
                          "1 fill declaration with an unsafe value"},
        {"fetch_style_attribute", "1 background declaration, 1 clip-path declaration with an unsafe value"},
        {"fetch_clip_path", "1 clip-path attribute with an unsafe value, 1 mask attribute with an unsafe value, "
                            "1 fill attribute with an unsafe value"},
        {"fetch_image_href", "2 <image>"},
        {"fetch_feimage", "1 <filter>, 1 filter attribute"},
        {"fetch_foreignobject_embeds", "1 <foreignObject>"},
        {"fetch_use_external", "2 <use> with hrefs outside the drawing"},
        {"fetch_meta_refresh", "1 <meta>"},
        {"fetch_xml_stylesheet", "1 <?xml-stylesheet?>"},
        {"fetch_doctype_entities", "1 DOCTYPE with declarations (entities)"},
        {"overlay_transform", ""},  // kept: report.html's box clips it (report_hostile_test.sh)
    };
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(fs::path(svgm::test::data_path("hostile")))) files += e.path().extension() == ".svg";
    CHECK(files == std::size(cases));  // a new file gets its line here
    for (const Case& c : cases) {
      CAPTURE(c.file);
      const InlinedSvg s = inline_svg(fs::path(svgm::test::data_path("hostile")) / (std::string(c.file) + ".svg"));
      CHECK(s.dropped == c.dropped);
      CHECK(s.markup.find(kSquare) != std::string::npos);
      const std::string m = lower(s.markup);
      for (const char* gone : {"server", "javascript", "svgm-xss", "file:", "<!", "<?", "cdata", "script", "iframe", "srcdoc",
                               "foreignobject", "<image", "<meta", "<filter", "<use", "@import", "@font-face", "url(h",
                               " onload", " onbegin", " onerror", "xmlns:xlink"})
        CHECK_MESSAGE(m.find(gone) == std::string::npos, gone);
    }
  }

  TEST_CASE("a benign document keeps its drawing, references, styles and animation") {
    const InlinedSvg s = inline_text(
        "<?xml version=\"1.0\"?>\n<!-- drawn by hand -->\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" viewBox=\"0 0 100 100\" "
        "width=\"100\" height=\"100\">\n"
        "  <title>a &lt;b&gt; &amp; c</title>\n"
        "  <style>.a { fill: url(#g); stroke: #000 } #arm > path, rect { opacity: 0.5 }</style>\n"
        "  <defs>\n"
        "    <linearGradient id=\"g\" gradientUnits=\"userSpaceOnUse\" x1=\"0\" x2=\"1\"><stop offset=\"0\" stop-color=\"#f00\"/>"
        "<stop offset=\"1\" style=\"stop-color: blue\"/></linearGradient>\n"
        "    <linearGradient id=\"h\" xlink:href=\"#g\"/>\n"
        "    <clipPath id=\"c\" clipPathUnits=\"userSpaceOnUse\"><rect width=\"50\" height=\"50\"/></clipPath>\n"
        "    <mask id=\"m\"><circle cx=\"5\" cy=\"5\" r=\"5\" fill=\"#fff\"/></mask>\n"
        "  </defs>\n"
        "  <g id=\"arm\" data-group=\"arm\" clip-path=\"url(#c)\" mask=\"url('#m')\" transform=\"translate(1 2)\">\n"
        "    <path id=\"p\" class=\"a\" d=\"M0 0H10V10Z\"><animate attributeName=\"d\" dur=\"2s\" repeatCount=\"indefinite\" "
        "keyTimes=\"0;1\" values=\"M0 0H10V10Z;M0 0H20V20Z\"/></path>\n"
        "    <animateTransform attributeName=\"transform\" type=\"rotate\" additive=\"sum\" values=\"0;10\" dur=\"2s\"/>\n"
        "    <set attributeName=\"fill\" to=\"url(#h)\" begin=\"1s\"/>\n"
        "  </g>\n"
        "  <use xlink:href=\"#p\" x=\"5\"/>\n"
        "  <text x=\"1\" y=\"2\">hi &amp; <tspan>there</tspan></text>\n"
        "</svg>\n");
    CHECK(s.dropped == "");
    CHECK(s.markup ==
          "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100%\" height=\"100%\" viewBox=\"0 0 100 100\">"
          "<title>a &lt;b&gt; &amp; c</title>"
          "<style>#svgm-stage .a{fill:url(#g);stroke:#000}#svgm-stage #arm &gt; path,#svgm-stage rect{opacity:0.5}</style>"
          "<defs><linearGradient id=\"g\" gradientUnits=\"userSpaceOnUse\" x1=\"0\" x2=\"1\">"
          "<stop offset=\"0\" stop-color=\"#f00\"></stop><stop offset=\"1\" style=\"stop-color:blue\"></stop></linearGradient>"
          "<linearGradient id=\"h\" href=\"#g\"></linearGradient>"
          "<clipPath id=\"c\" clipPathUnits=\"userSpaceOnUse\"><rect width=\"50\" height=\"50\"></rect></clipPath>"
          "<mask id=\"m\"><circle cx=\"5\" cy=\"5\" r=\"5\" fill=\"#fff\"></circle></mask></defs>"
          "<g id=\"arm\" data-group=\"arm\" clip-path=\"url(#c)\" mask=\"url('#m')\" transform=\"translate(1 2)\">"
          "<path id=\"p\" class=\"a\" d=\"M0 0H10V10Z\"><animate attributeName=\"d\" dur=\"2s\" repeatCount=\"indefinite\" "
          "keyTimes=\"0;1\" values=\"M0 0H10V10Z;M0 0H20V20Z\"></animate></path>"
          "<animateTransform attributeName=\"transform\" type=\"rotate\" additive=\"sum\" values=\"0;10\" dur=\"2s\">"
          "</animateTransform><set attributeName=\"fill\" to=\"url(#h)\" begin=\"1s\"></set></g>"
          "<use href=\"#p\" x=\"5\"></use><text x=\"1\" y=\"2\">hi &amp; <tspan>there</tspan></text></svg>");
  }

  TEST_CASE("prefixed documents, other namespaces, the page's ids and deep nesting") {
    // svgmotion's writer keeps the user's prefix (svg:path); other namespaces are not SVG.
    const InlinedSvg p = inline_text(
        "<svg:svg xmlns:svg=\"http://www.w3.org/2000/svg\" xmlns:x=\"http://www.w3.org/1999/xhtml\" "
        "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"10\" height=\"10\">"
        "<svg:path d=\"M0 0H1V1Z\" inkscape:label=\"a\"/><x:script>alert(1)</x:script>"
        "<svg:g><path xmlns=\"http://www.w3.org/1999/xhtml\" d=\"M0 0H1V1Z\"/></svg:g>"
        "<svg:rect id=\"svgm-play\" width=\"1\" height=\"1\"/></svg:svg>");
    CHECK(p.markup == "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\" width=\"100%\" height=\"100%\">"
                      "<path d=\"M0 0H1V1Z\"></path><g></g><rect width=\"1\" height=\"1\"></rect></svg>");
    CHECK(p.dropped == "1 inkscape:* attribute, 1 <x:script>, 1 <path>, 1 id taken from the page (svgm-...)");
    std::string deep = "<svg xmlns=\"http://www.w3.org/2000/svg\">";
    for (int i = 0; i < 300; ++i) deep += "<g>";
    for (int i = 0; i < 300; ++i) deep += "</g>";
    CHECK(inline_text(deep + "</svg>").dropped == "1 element nested deeper than 256");
  }
}
