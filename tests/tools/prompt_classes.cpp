// Bench tool: the figure class the prompt parser reads for each prompt (issue 35: a noun's sense
// by its context, motion/sense_context.h). Reads tab-separated rows "name <tab> ... prompt" (the
// prompt in column PROMPT_COLUMN, 1-based; default 4, motion_emoji.tsv's) from stdin, skipping '#'
// lines, and prints "name <tab> class of each clause <tab> the lexicon's readings" per row, so
// two builds' outputs diff to the prompts whose class changed.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "procedural/prompt_parse.h"

int main(int argc, char** argv) {
  const int column = argc > 1 ? std::atoi(argv[1]) : 4;
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cols;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, '\t');) cols.push_back(c);
    if (static_cast<int>(cols.size()) < column) continue;
    const svgm::ParsedPrompt p = svgm::parse_prompt(cols[column - 1]);
    std::string classes, readings;
    for (const auto& c : p.clauses) classes += std::string(classes.empty() ? "" : ",") + svgm::figure_class_name(c.figure);
    for (const auto& r : p.readings) readings += (readings.empty() ? "" : "; ") + r;
    std::printf("%s\t%s\t%s\n", cols[0].c_str(), classes.c_str(), readings.c_str());
  }
  return 0;
}
