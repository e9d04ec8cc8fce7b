// Releasing WordNet's mapped pages (motion/wordnet.cpp maps its index and data files whole,
// read only): the lexicon's build and the prompt's lookups leave ~11 MB of them resident,
// which counts in the peak of a stage that reads no words (the fitter, issue 38).
#pragma once

namespace svgm::wordnet {

// Drops the shared database's file pages from the process's resident set: madvise
// MADV_DONTNEED on every mapping of its folder's files, whoever made it (each plugin links the
// engine statically, so the prompt's stage maps them through its own copy of
// Database::shared()). The mappings stay; a later lookup reads its pages again from the file.
void release_shared_pages();

}  // namespace svgm::wordnet
