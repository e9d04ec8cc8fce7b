// A reader for the WordNet 3.0 database as Debian's wordnet-base installs it
// (/usr/share/wordnet/{index,data}.{noun,verb,adj,adv} and the *.exc exception lists; the format
// is `man 5 wndb`). The motion lexicon (lexicon.h) uses it to read words the hand-written
// vocabulary does not list: a word's senses (most frequent first), the words of each sense, and
// its hypernyms ("shuffle" is a kind of "walk", "gazelle" a kind of ... "mammal").
//
// Lazy: the files are mapped into memory, not read; a lemma is found by binary search of its
// sorted index file and a synset by the byte offset the index gives, so a lookup touches a few
// pages and costs microseconds. Only the exception lists (about 100 KB) are read at open.
// Immutable once open, so one database may be shared by threads.
//
// Where: SVGM_WORDNET_DIR in the environment, else the directory CMake found at configure time
// (SVGM_WORDNET_DEFAULT_DIR). shared() returns null when neither holds the database, after one
// info line saying the vocabulary alone is used.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace svgm::wordnet {

enum class Pos { Noun, Verb, Adj, Adv };

struct Pointer {
  std::string symbol;  // "@" hypernym, "@i" instance hypernym, "$" verb group, "*" entailment,
                       // "+" derivationally related, "#p" part holonym ... (man 5 wndb)
  Pos pos;
  uint32_t offset;
};

struct Synset {
  uint32_t offset = 0;
  Pos pos = Pos::Noun;
  int lex_file = 0;                 // lexicographer file: 5 noun.animal, 38 verb.motion ... (man 5 lexnames)
  std::vector<std::string> words;   // lower case, '_' between the words of a collocation
  std::vector<Pointer> pointers;
  // A verb's sentence frames (man 5 wndb; 1 "Something ----s", 2 "Somebody ----s", 8
  // "Somebody ----s something" ...), each once; empty for other parts of speech.
  std::vector<int> frames;
  std::string gloss;
};

struct Ancestor {
  uint32_t offset;
  int depth;  // 1: a direct hypernym
};

class Database {
 public:
  // The database in `dir`, or null when its index and data files are not all there.
  static std::unique_ptr<Database> open(const std::string& dir);
  // The process's database (see the file comment); null when absent.
  static const Database* shared();

  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  // The lemmas `word` may be an inflection of, per `man 5 morphy`: the exception list's base
  // forms, the word itself, then the detachment rules ("flies" -> fly, "geese" -> goose,
  // "ran" -> run), only those in the index. A collocation ("takes_off") inflects its first word.
  std::vector<std::string> base_forms(std::string_view word, Pos pos) const;
  // The synsets of a lemma (exact, lower case), most frequent sense first; empty when unknown.
  std::vector<uint32_t> senses(std::string_view lemma, Pos pos) const;
  // How many of those senses are ranked by tagged frequency; the rest follow in no meaningful order.
  int tagged_senses(std::string_view lemma, Pos pos) const;
  std::optional<Synset> synset(Pos pos, uint32_t offset) const;
  // Hypernyms (and instance hypernyms) of a synset, breadth first up to `max_depth`, each once.
  std::vector<Ancestor> hypernyms(Pos pos, uint32_t offset, int max_depth) const;

  const std::string& dir() const { return dir_; }

  struct File;        // a read-only mapping of one file (wordnet.cpp)
  struct Exceptions;  // the *.exc lists

 private:
  Database() = default;
  std::string_view index_line(std::string_view lemma, Pos pos) const;
  std::string dir_;
  std::unique_ptr<File> index_[4], data_[4];
  std::unique_ptr<Exceptions> exc_;
};

Pos pos_of_char(char c);  // 'n' 'v' 'a' 's' 'r'

}  // namespace svgm::wordnet
