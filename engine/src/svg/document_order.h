// The user's own document as the fit's output: finding a scene's elements in it, matching the
// pipeline's working copy (grouped/layered.svg) to it, and applying a changed paint order by
// moving as few elements as possible.
//
// The pipeline fits a working copy: grouped.svg flattens the user's document into <g> runs
// with every transform baked in, and the layers stage may reorder those runs. None of that may
// reach the user: animation.svg is the user's input.svg with <animate> children added and, if
// the layers stage changed the paint order, the few elements that must move moved. Paths of
// the working copy are matched to the original's by id (grouped.svg keeps every id; a path
// without one has the reader's stable generated "path-N" in both), duplicates by rank.
//
// Moving: the new order is a permutation of the original's paths. The paths on a longest
// increasing subsequence of it keep their place; every other one is moved next to its new
// neighbour (after its predecessor, else before its successor), but only within its own parent
// element: a move into another parent would change the transform, style and clip it inherits,
// so it is refused and the caller keeps the original order. Shapes drawn through one <use>, or
// elements holding several paths, cannot move apart and are refused the same way.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm {

// pugixml parse flags that keep a document as the user wrote it (whitespace, comments,
// doctype, declaration, processing instructions).
constexpr unsigned kKeepDocumentParse = pugi::parse_default | pugi::parse_ws_pcdata |
                                        pugi::parse_declaration | pugi::parse_comments |
                                        pugi::parse_doctype | pugi::parse_pi;

// The element at a locator like "/svg/g[2]/rect[1]" (1-based among same-named siblings, names
// without namespace prefixes); an empty node when there is none.
pugi::xml_node find_locator(pugi::xml_document& doc, const std::string& locator);

// For each path of `copy` (the working copy), the index of the same path in `original`.
// Throws svgm::Error naming `copy_name` when a path has no counterpart or the two differ in
// subpath structure (they must hold the same control points in the same layout).
std::vector<int> match_paths(const Scene& copy, const Scene& original, const std::string& copy_name);

// Moves elements of `doc` (holding `original`, elements found by locator) so its paths are
// painted in `order` (back to front, indices into original.paths; a permutation). Returns the
// number of elements moved, or the reason the order cannot be applied without changing what an
// element inherits (then `doc` is unchanged).
struct ReorderResult {
  int moved = 0;
  std::optional<std::string> refused;  // why not, when the order could not be applied
};
ReorderResult reorder_document(pugi::xml_document& doc, const Scene& original,
                               const std::vector<int>& order);
// The same with the elements already found (el[i] draws original.paths[i]); for callers that
// change the document (and so its locators) before reordering.
ReorderResult reorder_elements(const std::vector<pugi::xml_node>& el, const Scene& original,
                               const std::vector<int>& order);

// The same on a file's text: checks that the reordered document reads back with its paths in
// `order` (a second, independent check of the move). Returns the result; `out_text` receives
// the reordered document when it was applied.
ReorderResult reorder_document_text(const std::string& text, const std::string& name,
                                    const Scene& original, const std::vector<int>& order,
                                    std::string* out_text);

}  // namespace svgm
