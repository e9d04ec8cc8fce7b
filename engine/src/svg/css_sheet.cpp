// CSS style sheets of <style> elements (see css_sheet.h).
#include "svg/css_sheet.h"

#include <algorithm>
#include <cctype>

namespace svgm::svg {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string strip_comments(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '/' && i + 1 < s.size() && s[i + 1] == '*') {
      const size_t end = s.find("*/", i + 2);
      if (end == std::string_view::npos) break;
      i = end + 1;
      out += ' ';
    } else {
      out += s[i];
    }
  }
  return out;
}

bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ||
         static_cast<unsigned char>(c) >= 0x80;
}

}  // namespace

std::vector<CssDeclaration> parse_declarations(std::string_view block) {
  std::vector<CssDeclaration> out;
  const std::string text = block.find("/*") == std::string_view::npos ? std::string(block) : strip_comments(block);
  std::string_view rest = text;
  while (!rest.empty()) {
    const size_t semi = rest.find(';');
    const std::string_view decl = rest.substr(0, semi);
    if (const size_t colon = decl.find(':'); colon != std::string_view::npos) {
      const std::string_view name = trim(decl.substr(0, colon));
      std::string_view value = trim(decl.substr(colon + 1));
      if (const size_t bang = value.rfind('!'); bang != std::string_view::npos) {
        std::string word(trim(value.substr(bang + 1)));
        for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (word == "important") value = trim(value.substr(0, bang));
      }
      if (!name.empty()) out.push_back({std::string(name), std::string(value)});
    }
    if (semi == std::string_view::npos) break;
    rest.remove_prefix(semi + 1);
  }
  return out;
}

int StyleSheet::add(std::string_view css_in) {
  const std::string css = strip_comments(css_in);
  std::string_view s = css;
  int skipped = 0;
  size_t i = 0;
  // Skips a {...} block starting at s[i] == '{', nested braces included.
  auto skip_block = [&]() {
    int level = 0;
    for (; i < s.size(); ++i) {
      if (s[i] == '{') ++level;
      else if (s[i] == '}' && --level == 0) { ++i; return; }
    }
  };
  while (i < s.size()) {
    while (i < s.size() && is_space(s[i])) ++i;
    if (i >= s.size()) break;
    if (s.compare(i, 4, "<!--") == 0) { i += 4; continue; }  // legacy HTML comment markers
    if (s.compare(i, 3, "-->") == 0) { i += 3; continue; }
    if (s[i] == '@') {  // at-rule: up to ';' or through its block
      const size_t semi = s.find(';', i), brace = s.find('{', i);
      if (brace != std::string_view::npos && (semi == std::string_view::npos || brace < semi)) {
        i = brace;
        skip_block();
      } else {
        i = semi == std::string_view::npos ? s.size() : semi + 1;
      }
      ++skipped;
      continue;
    }
    const size_t brace = s.find('{', i);
    if (brace == std::string_view::npos) break;
    const std::string_view selectors = s.substr(i, brace - i);
    const size_t close = s.find('}', brace);
    const std::string_view body = s.substr(brace + 1, (close == std::string_view::npos ? s.size() : close) - brace - 1);
    i = close == std::string_view::npos ? s.size() : close + 1;
    const size_t block = blocks_.size();
    blocks_.push_back(parse_declarations(body));
    std::string_view sel_list = selectors;
    while (true) {
      const size_t comma = sel_list.find(',');
      const std::string_view sel = trim(sel_list.substr(0, comma));
      Rule r;
      bool ok = !sel.empty();
      size_t p = 0;
      if (ok && sel[0] == '*') {
        ++p;
      } else {
        while (p < sel.size() && ident_char(sel[p])) ++p;
        r.tag = std::string(sel.substr(0, p));
        if (!r.tag.empty()) r.specificity += 1;
      }
      while (ok && p < sel.size()) {
        const char kind = sel[p++];
        const size_t start = p;
        while (p < sel.size() && ident_char(sel[p])) ++p;
        if ((kind != '.' && kind != '#') || p == start) {
          ok = false;
          break;
        }
        if (kind == '.') {
          r.classes.emplace_back(sel.substr(start, p - start));
          r.specificity += 10;
        } else {
          r.id = std::string(sel.substr(start, p - start));
          r.specificity += 100;
        }
      }
      if (ok) {
        r.order = static_cast<int>(rules_.size());
        r.block = block;
        rules_.push_back(std::move(r));
      } else {
        ++skipped;
      }
      if (comma == std::string_view::npos) break;
      sel_list.remove_prefix(comma + 1);
    }
  }
  return skipped;
}

void StyleSheet::match(std::string_view tag, std::string_view id, std::string_view class_attr,
                       std::vector<const CssDeclaration*>& out) const {
  out.clear();
  if (rules_.empty()) return;
  std::vector<const Rule*> hits;
  for (const Rule& r : rules_) {
    if (!r.tag.empty() && r.tag != tag) continue;
    if (!r.id.empty() && r.id != id) continue;
    bool all = true;
    for (const std::string& c : r.classes) {
      bool found = false;
      std::string_view rest = class_attr;
      while (!rest.empty() && !found) {
        while (!rest.empty() && is_space(rest.front())) rest.remove_prefix(1);
        size_t n = 0;
        while (n < rest.size() && !is_space(rest[n])) ++n;
        found = rest.substr(0, n) == c;
        rest.remove_prefix(n);
      }
      if (!found) {
        all = false;
        break;
      }
    }
    if (all) hits.push_back(&r);
  }
  std::stable_sort(hits.begin(), hits.end(), [](const Rule* a, const Rule* b) {
    return a->specificity != b->specificity ? a->specificity < b->specificity : a->order < b->order;
  });
  for (const Rule* r : hits)
    for (const CssDeclaration& d : blocks_[r->block]) out.push_back(&d);
}

}  // namespace svgm::svg
