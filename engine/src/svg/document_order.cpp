// Matching the working copy to the user's document and moving its elements (see
// document_order.h).
#include "svg/document_order.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <map>
#include <sstream>

#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"

namespace svgm {

namespace {

std::string_view local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

// Positions (indices into seq) of one longest strictly increasing subsequence of seq
// (patience sorting, O(n log n)); ties broken towards the earliest elements.
std::vector<size_t> longest_increasing(const std::vector<int>& seq) {
  std::vector<size_t> tails;                 // tails[l]: position ending the best run of length l+1
  std::vector<ptrdiff_t> prev(seq.size(), -1);
  for (size_t i = 0; i < seq.size(); ++i) {
    const auto it = std::lower_bound(tails.begin(), tails.end(), seq[i],
                                     [&](size_t pos, int v) { return seq[pos] < v; });
    const size_t l = static_cast<size_t>(it - tails.begin());
    if (l > 0) prev[i] = static_cast<ptrdiff_t>(tails[l - 1]);
    if (it == tails.end()) tails.push_back(i);
    else *it = i;
  }
  std::vector<size_t> run;
  for (ptrdiff_t i = tails.empty() ? -1 : static_cast<ptrdiff_t>(tails.back()); i >= 0; i = prev[static_cast<size_t>(i)])
    run.push_back(static_cast<size_t>(i));
  std::reverse(run.begin(), run.end());
  return run;
}

bool is_blank_text(pugi::xml_node n) {
  if (n.type() != pugi::node_pcdata) return false;
  for (const char* c = n.value(); *c; ++c)
    if (!std::strchr(" \t\r\n", *c)) return false;
  return true;
}

// Moves `e` (with the blank text before it, so indentation travels along) next to `anchor`,
// a sibling: after it when `after`, else before it.
void move_next_to(pugi::xml_node e, pugi::xml_node anchor, bool after) {
  pugi::xml_node parent = e.parent();
  pugi::xml_node blank = e.previous_sibling();
  if (!is_blank_text(blank)) blank = {};
  if (after) {
    pugi::xml_node at = anchor;
    if (blank) at = parent.insert_move_after(blank, at);
    parent.insert_move_after(e, at);
  } else {
    parent.insert_move_before(e, anchor);
    if (blank) parent.insert_move_before(blank, e);
  }
}

}  // namespace

pugi::xml_node find_locator(pugi::xml_document& doc, const std::string& locator) {
  pugi::xml_node node = doc;
  std::string_view rest = locator;
  while (!rest.empty()) {
    if (rest.front() == '/') rest.remove_prefix(1);
    const size_t slash = rest.find('/');
    std::string_view part = rest.substr(0, slash);
    rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash);
    int index = 1;
    std::string_view name = part;
    if (const size_t br = part.find('['); br != std::string_view::npos) {
      name = part.substr(0, br);
      std::from_chars(part.data() + br + 1, part.data() + part.size() - 1, index);
    }
    pugi::xml_node found;
    int seen = 0;
    for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling()) {
      if (c.type() == pugi::node_element && local_name(c.name()) == name && ++seen == index) {
        found = c;
        break;
      }
    }
    if (!found) return {};
    node = found;
  }
  return node;
}

std::vector<int> match_paths(const Scene& copy, const Scene& original, const std::string& copy_name) {
  std::map<std::string, std::vector<int>> by_id;  // original indices per id, in paint order
  for (size_t i = original.paths.size(); i-- > 0;) by_id[original.paths[i].id].push_back(static_cast<int>(i));
  std::vector<int> match(copy.paths.size(), -1);
  for (size_t j = 0; j < copy.paths.size(); ++j) {
    const Path& c = copy.paths[j];
    auto it = by_id.find(c.id);
    if (it == by_id.end() || it->second.empty())
      throw Error(copy_name + ": path '" + c.id + "' is not in the original document");
    const int i = it->second.back();  // the earliest unused one with this id
    it->second.pop_back();
    const Path& o = original.paths[static_cast<size_t>(i)];
    bool same = o.subpaths.size() == c.subpaths.size();
    for (size_t s = 0; same && s < o.subpaths.size(); ++s)
      same = o.subpaths[s].points.size() == c.subpaths[s].points.size() &&
             o.subpaths[s].closed == c.subpaths[s].closed;
    if (!same)
      throw Error(copy_name + ": path '" + c.id + "' has a different structure than in the original document");
    match[j] = i;
  }
  for (const auto& [id, left] : by_id)
    if (!left.empty()) throw Error(copy_name + ": lacks the original document's path '" + id + "'");
  return match;
}

ReorderResult reorder_document(pugi::xml_document& doc, const Scene& original,
                               const std::vector<int>& order) {
  std::vector<pugi::xml_node> el(original.paths.size());
  for (size_t i = 0; i < el.size(); ++i) {
    el[i] = find_locator(doc, original.paths[i].locator);
    if (!el[i]) throw Error("internal: " + original.paths[i].locator + " not found in the document");
  }
  return reorder_elements(el, original, order);
}

ReorderResult reorder_elements(const std::vector<pugi::xml_node>& el, const Scene& original,
                               const std::vector<int>& order) {
  ReorderResult r;
  const size_t n = original.paths.size();
  if (order.size() != n || el.size() != n)
    throw Error("internal: paint order does not cover the document's paths");
  std::map<const void*, int> paths_of;  // element -> how many paths it draws
  for (size_t i = 0; i < n; ++i) ++paths_of[el[i].internal_object()];
  std::vector<char> keep(n, 0);
  for (size_t pos : longest_increasing(order)) keep[static_cast<size_t>(order[pos])] = 1;
  // Check every move before making any, so a refusal leaves the document untouched.
  struct Move {
    size_t path;
    pugi::xml_node anchor;
    bool after;
  };
  std::vector<Move> moves;
  for (size_t t = 0; t < n; ++t) {
    const size_t p = static_cast<size_t>(order[t]);
    if (keep[p]) continue;
    const pugi::xml_node e = el[p];
    if (paths_of[e.internal_object()] > 1)
      return {0, "'" + original.paths[p].id + "' is drawn by an element (" + std::string(e.name()) +
                     ") that holds other shapes too, so it cannot move alone"};
    if (t > 0 && el[static_cast<size_t>(order[t - 1])].parent() == e.parent()) {
      moves.push_back({p, el[static_cast<size_t>(order[t - 1])], true});
      continue;
    }
    // Before the next path in the new order that stays where it is.
    size_t u = t + 1;
    while (u < n && !keep[static_cast<size_t>(order[u])]) ++u;
    if (u < n && el[static_cast<size_t>(order[u])].parent() == e.parent()) {
      moves.push_back({p, el[static_cast<size_t>(order[u])], false});
      continue;
    }
    return {0, "moving '" + original.paths[p].id +
                   "' would take it out of its parent element (changing the transform and style it inherits)"};
  }
  for (const Move& m : moves) move_next_to(el[m.path], m.anchor, m.after);
  r.moved = static_cast<int>(moves.size());
  return r;
}

ReorderResult reorder_document_text(const std::string& text, const std::string& name,
                                    const Scene& original, const std::vector<int>& order,
                                    std::string* out_text) {
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), kKeepDocumentParse);
  if (!parsed) throw Error(name + ": cannot parse: " + parsed.description());
  ReorderResult r = reorder_document(doc, original, order);
  if (r.refused) return r;
  std::ostringstream s;
  doc.save(s, "", pugi::format_raw | pugi::format_no_declaration, pugi::encoding_utf8);
  // Read it back: the paths must now come in `order`. Compared by geometry, not by id: a path
  // without an id gets a generated one from its position, which the move changes.
  const Scene back = read_svg_string(s.str(), name);
  bool same = back.paths.size() == order.size();
  for (size_t t = 0; same && t < order.size(); ++t) {
    const Path& a = back.paths[t];
    const Path& b = original.paths[static_cast<size_t>(order[t])];
    same = a.subpaths.size() == b.subpaths.size();
    for (size_t k = 0; same && k < a.subpaths.size(); ++k)
      same = a.subpaths[k].points == b.subpaths[k].points;
  }
  if (!same) return {0, "the reordered document does not read back in the new order"};
  if (out_text) *out_text = s.str();
  return r;
}

}  // namespace svgm
