// Tests that need WordNet (Debian's wordnet-base) skip themselves, with a message, where it is not
// installed: the lexicon falls back to its own tables there and these tests' facts do not hold.
#pragma once

#include <doctest/doctest.h>

#include "motion/lexicon.h"

namespace svgm {

inline bool wordnet_or_skip() {
  if (Lexicon::shared().has_wordnet()) return true;
  MESSAGE("WordNet is not installed (apt install wordnet-base): skipped");
  return false;
}

}  // namespace svgm
