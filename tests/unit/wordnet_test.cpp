// The WordNet reader: morphology (the exception lists and morphy's detachment rules), senses in
// frequency order, a synset's words and pointers, transitive hypernyms, and a clear absence when
// the directory holds no database. Needs wordnet-base (CI installs it); skipped without it.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "motion/wordnet.h"
#include "motion/wordnet_pages.h"
#include "temp_dir.h"

using namespace svgm::wordnet;

namespace {

const Database* db_or_skip() {
  const Database* db = Database::shared();
  if (!db) MESSAGE("WordNet is not installed (apt install wordnet-base): skipped");
  return db;
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

// The offset of the synset of `lemma` holding `word`, or 0.
uint32_t synset_with(const Database& db, const std::string& lemma, Pos pos, const std::string& word) {
  for (uint32_t o : db.senses(lemma, pos))
    if (const auto s = db.synset(pos, o); s && has(s->words, word)) return o;
  return 0;
}

// Resident kB of this process's mappings of files in `dir` (/proc/self/smaps).
long resident_kb_in(const std::string& dir) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool in = false;
  long kb = 0;
  while (std::getline(smaps, line)) {
    const size_t sp = line.find(' ');
    if (sp != std::string::npos && line.find('-') < sp) {  // a mapping's header line
      const size_t slash = line.find('/');
      in = slash != std::string::npos && line.compare(slash, dir.size() + 1, dir + "/") == 0;
    } else if (in && line.rfind("Rss:", 0) == 0) {
      kb += std::stol(line.substr(4));
    }
  }
  return kb;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("wordnet: release_shared_pages drops the files' resident pages, and lookups read them again alike") {
  const Database* db = db_or_skip();
  if (!db) return;
  const std::vector<uint32_t> before = db->senses("run", Pos::Verb);
  REQUIRE_FALSE(before.empty());
  CHECK(resident_kb_in(db->dir()) > 0);  // the lookup touched index.verb and the exceptions' reads
  release_shared_pages();
  CHECK(resident_kb_in(db->dir()) == 0);
  CHECK(db->senses("run", Pos::Verb) == before);
  CHECK(resident_kb_in(db->dir()) > 0);
}

TEST_CASE("wordnet: inflections find their lemmas (exception lists and detachment rules)") {
  const Database* db = db_or_skip();
  if (!db) return;
  CHECK(db->base_forms("flies", Pos::Verb).front() == "fly");  // ies -> y
  CHECK(has(db->base_forms("flies", Pos::Noun), "fly"));  // "flies" is a noun of its own too (a theatre's)
  CHECK(db->base_forms("ran", Pos::Verb).front() == "run");    // verb.exc
  CHECK(db->base_forms("geese", Pos::Noun).front() == "goose");  // noun.exc
  CHECK(has(db->base_forms("running", Pos::Verb), "run"));     // the doubled consonant
  CHECK(has(db->base_forms("boxes", Pos::Noun), "box"));       // xes -> x
  CHECK(db->base_forms("takes_off", Pos::Verb).front() == "take_off");  // a collocation's first word
  CHECK(db->base_forms("glass", Pos::Noun) == std::vector<std::string>{"glass"});  // not "glas"
  CHECK(db->base_forms("xyzzy", Pos::Verb).empty());
}

TEST_CASE("wordnet: senses, synsets and hypernyms (a hummingbird is a bird)") {
  const Database* db = db_or_skip();
  if (!db) return;
  const std::vector<uint32_t> senses = db->senses("hummingbird", Pos::Noun);
  REQUIRE(senses.size() == 1);
  const auto s = db->synset(Pos::Noun, senses[0]);
  REQUIRE(s);
  CHECK(s->words == std::vector<std::string>{"hummingbird"});
  CHECK(s->lex_file == 5);  // noun.animal
  CHECK(s->gloss.find("iridescent") != std::string::npos);
  const uint32_t bird = synset_with(*db, "bird", Pos::Noun, "bird");
  REQUIRE(bird != 0);
  const auto up = db->hypernyms(Pos::Noun, senses[0], 20);
  const auto it = std::find_if(up.begin(), up.end(), [&](const Ancestor& a) { return a.offset == bird; });
  REQUIRE(it != up.end());
  CHECK(it->depth == 2);  // hummingbird -> apodiform bird -> bird
  // The first verb sense of "shuffle" is a kind of walking.
  const uint32_t walk = synset_with(*db, "walk", Pos::Verb, "walk");
  const auto shuffle = db->hypernyms(Pos::Verb, db->senses("shuffle", Pos::Verb).at(0), 1);
  REQUIRE(shuffle.size() == 1);
  CHECK(shuffle[0].offset == walk);
  CHECK(db->senses("no_such_lemma_at_all", Pos::Noun).empty());
  CHECK_FALSE(db->synset(Pos::Noun, 3));  // not a synset's offset
}

TEST_CASE("wordnet: a directory without the database opens as absent") {
  svgm::test::TempDir dir;
  CHECK(Database::open(dir.path.string()) == nullptr);
  CHECK(Database::open("/nonexistent/wordnet") == nullptr);
}

}  // TEST_SUITE
