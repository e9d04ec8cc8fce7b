// A noun's sense chosen by the prompt's other nouns. WordNet ranks a noun's senses by how often
// each is used, and the most frequent is not always the one a prompt means: "drone" is first a
// male bee, so "the drone hovers, its rotors whirring" beat arms like wings. The prompt's other
// nouns say which: a rotor is a part of a helicopter, a helicopter is a heavier-than-air craft,
// and so is drone's fourth sense (a pilotless aircraft), two steps apart; the bee is a dozen
// steps from any of them. So each sense is measured by the shortest path through a common
// hypernym (Rada et al. 1989's distance in the is-a graph) to the senses of the context nouns
// and to the wholes they are parts of (a part names its whole: Banerjee and Pedersen 2002 use
// the part-of links the same way), and a sense nearer than the frequent one comes first when it
// is near indeed (kMaxSensePath). Verbs are no evidence: a bee and a drone both hover.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "motion/wordnet.h"

namespace svgm {

// `senses` (noun synsets of one lemma, most frequent first) with the sense the `context` words
// (lower case, as written; the prompt's words, of which its nouns count) point at moved to the
// front; `senses` unchanged when none is nearer than the first, or the context is empty. `why`,
// when given, receives "drone: sense 4 (heavier-than-air_craft, 2 steps from 'rotors')" when
// the order changed.
std::vector<uint32_t> senses_by_context(const wordnet::Database& db, const std::string& lemma, const std::vector<uint32_t>& senses,
                                        const std::vector<std::string>& context, std::string* why = nullptr);

// A sense comes before the frequent one when a context noun's sense (or its whole) is at most
// this many is-a steps from it through a common hypernym, and the frequent sense is farther.
// Two steps are siblings (a drone and a helicopter); three an uncle; farther links meet only in
// categories such as "artifact" that say nothing of what a thing is.
inline constexpr int kMaxSensePath = 3;

}  // namespace svgm
