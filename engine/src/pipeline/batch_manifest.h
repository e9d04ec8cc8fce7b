// The list of drawings `svgmotion batch` animates: a CSV or YAML manifest, one item per
// drawing, each becoming one run directory named after its id.
//
// CSV: a header row naming the columns, then one row per item; `input` is required, `id`,
// `prompt`, `target` (a video or folder of frames: the item is fitted to it through the `file`
// video provider) and `overrides` (space-separated key.path=value settings) are optional.
// Fields may be double-quoted ("" is a quote); blank lines and lines starting with # are skipped.
// YAML: a list of items, or a map whose `items` is that list; each item a map with the same
// keys, `overrides` either a map (nested maps become dotted keys) or a list of "key=value".
// Relative paths are relative to the manifest's folder. An item's id defaults to its input's
// file name without extension and leading dots; ids are letters, digits, '.', '_' and '-', must
// be unique, and may not start with '.', contain "..", or be the batch's own summary.csv or
// summary.json. Overrides are config settings only (check_batch_override), never options.
// Whether an input exists is not checked here: a missing file fails that item only.
//
// Limits: a NUL byte is refused (text only); a leading UTF-8 byte order mark is skipped; the
// extension's case does not matter; a manifest is at most 64 MB, and a YAML one may expand
// (aliases) to at most 64 MB of text and 10^7 values, each item's overrides to the config
// loader's own cap (kMaxConfigValues, config.h) and nesting (kMaxYamlDepth).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace svgm {

struct BatchItem {
  std::string id;                      // the run directory's name
  std::filesystem::path input;         // the SVG (absolute)
  std::string prompt;
  std::filesystem::path target;        // empty: the config's video provider makes one
  std::vector<std::string> overrides;  // "key.path=value", after the batch's own
  int line = 0;                        // where the item starts in the manifest (1-based)
};

// Reads a manifest (.csv, or .yaml/.yml). Throws svgm::Error "FILE:LINE: problem" for a
// malformed manifest, an unknown column or key, a missing input field, a bad or repeated id, a
// bad override; "FILE: is a directory, not a manifest" and the like for what is not one.
std::vector<BatchItem> read_batch_manifest(const std::filesystem::path& file);

// Throws svgm::Error "override 'TEXT': problem" unless TEXT is a setting an item's run may be
// given: key.path=value, not an option ("-o=DIR" was read by `svgmotion run` as one), a key
// of the config schema with a value of its type (the config reader's own check, config.h), and
// not input, prompt or output (the batch sets those per item; the run would ignore them).
void check_batch_override(const std::string& text);

}  // namespace svgm
